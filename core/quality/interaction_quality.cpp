#include "quality/interaction_quality.h"

#include <algorithm>
#include <cmath>

namespace grass::core {

namespace {

constexpr int TOP_LEVEL = int(REDUCTION_LADDER.size()) - 1;
// A measured frame time is trusted this long; the view (and so the cost) changes as the user
// moves.
constexpr double MEASURED_FOR_S = 3.0;
constexpr double SMOOTHING = 0.5;  // weight of the newest frame

}  // namespace

double InteractionQuality::estimateMs(int level, double nowS) const {
    const auto known = [&](int l) { return nowS - mMeasured[std::size_t(l)].atS <= MEASURED_FOR_S; };
    if (known(level))
        return mMeasured[std::size_t(level)].ms;
    // The nearest measured rung, the more expensive reading when two are as near.
    for (int d = 1; d <= TOP_LEVEL; ++d) {
        double estimate = 0.0;
        if (level - d >= 0 && known(level - d))
            estimate = mMeasured[std::size_t(level - d)].ms / std::exp2(d);
        if (level + d <= TOP_LEVEL && known(level + d))
            estimate = std::max(estimate, mMeasured[std::size_t(level + d)].ms * std::exp2(d));
        if (estimate > 0.0)
            return estimate;
    }
    return 0.0;  // nothing measured yet: assume it fits
}

std::optional<double> InteractionQuality::fullPictureAtS() const {
    if (mLevel == 0)
        return std::nullopt;
    return mLastInteractionS + mSettings.settleS;
}

int InteractionQuality::update(double lastFrameMs, bool interacting, double nowS,
                               bool lastFrameDrawn) {
    Measured& last = mMeasured[std::size_t(mLevel)];
    const bool known = nowS - last.atS <= MEASURED_FOR_S;
    if (lastFrameDrawn) {
        last.ms = known ? (1.0 - SMOOTHING) * last.ms + SMOOTHING * lastFrameMs : lastFrameMs;
        last.atS = nowS;
    } else if (known) {
        last.atS = nowS;
    }
    if (!mSettings.enabled) {
        mLevel = 0;
        return mLevel;
    }
    if (interacting)
        mLastInteractionS = nowS;
    if (nowS - mLastInteractionS >= mSettings.settleS) {
        mLevel = 0;  // input has stopped: the full picture
        return mLevel;
    }
    mLevel = TOP_LEVEL;
    for (int level = 0; level < TOP_LEVEL; ++level)
        if (estimateMs(level, nowS) <= mSettings.budgetMs) {
            mLevel = level;
            break;
        }
    return mLevel;
}

}  // namespace grass::core
