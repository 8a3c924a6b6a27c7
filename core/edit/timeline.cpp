#include "edit/timeline.h"

#include <algorithm>
#include <cmath>

#include "util/assert.h"

namespace grass::core {

Timeline::Timeline(double startS, double endS, double stepS) {
    GRASS_ASSERT(std::isfinite(startS) && std::isfinite(endS));
    GRASS_ASSERT(std::isfinite(stepS) && stepS > 0.0);
    mStartS = startS;
    mEndS = std::max(startS, endS);
    mTimeS = startS;
    mStepS = stepS;
}

bool Timeline::setRange(double startS, double endS, TimeUpdate* update) {
    if (!std::isfinite(startS) || !std::isfinite(endS))
        return false;
    mStartS = startS;
    mEndS = std::max(startS, endS);
    // A range that now starts after the current time is a jump forwards; one that ends before it
    // is a jump back, like any other.
    const TimeUpdate moved = moveTo(std::clamp(mTimeS, mStartS, mEndS), TimeChange::JumpForward);
    if (update)
        *update = moved;
    return true;
}

bool Timeline::setStep(double stepS) {
    if (!std::isfinite(stepS) || stepS <= 0.0)
        return false;
    mStepS = stepS;
    return true;
}

bool Timeline::setSpeed(double speed) {
    if (!std::isfinite(speed) || speed <= 0.0)
        return false;
    mSpeed = std::clamp(speed, TIMELINE_MIN_SPEED, TIMELINE_MAX_SPEED);
    return true;
}

TimeUpdate Timeline::play() {
    TimeUpdate update{TimeChange::None, mTimeS, mTimeS};
    // Otherwise play would stop again at once, and the button would seem dead.
    if (!mLoop && mTimeS >= mEndS && mEndS > mStartS)
        update = moveTo(mStartS, TimeChange::JumpBack);
    mPlaying = true;
    return update;
}

TimeUpdate Timeline::toggle() {
    if (!mPlaying)
        return play();
    pause();
    return TimeUpdate{TimeChange::None, mTimeS, mTimeS};
}

TimeUpdate Timeline::advance(double wallElapsedS) {
    if (!mPlaying || !std::isfinite(wallElapsedS) || wallElapsedS <= 0.0)
        return TimeUpdate{TimeChange::None, mTimeS, mTimeS};
    const double deltaS = wallElapsedS * mSpeed;
    const double lengthS = mEndS - mStartS;
    if (mTimeS + deltaS <= mEndS)
        return moveTo(mTimeS + deltaS, TimeChange::Continuous);
    if (!mLoop || lengthS <= 0.0) {
        mPlaying = false;
        return moveTo(mEndS, TimeChange::Continuous);
    }
    // fmod of the step first: a huge elapsed time (a laptop woken from sleep) then wraps without
    // losing the phase to rounding, and without looping once per lap.
    const double phaseS = std::fmod(mTimeS - mStartS + std::fmod(deltaS, lengthS), lengthS);
    return moveTo(mStartS + phaseS, TimeChange::JumpBack);
}

TimeUpdate Timeline::stepForward() {
    mPlaying = false;
    return moveTo(std::min(mTimeS + mStepS, mEndS), TimeChange::Continuous);
}

TimeUpdate Timeline::stepBack() {
    mPlaying = false;
    return moveTo(std::max(mTimeS - mStepS, mStartS), TimeChange::JumpBack);
}

TimeUpdate Timeline::scrub(double timeS) {
    if (std::isnan(timeS))
        return TimeUpdate{TimeChange::None, mTimeS, mTimeS};
    return moveTo(std::clamp(timeS, mStartS, mEndS), TimeChange::JumpForward);
}

// `forwards` is how a move ahead is reported; every move back is a JumpBack.
TimeUpdate Timeline::moveTo(double timeS, TimeChange forwards) {
    TimeUpdate update{TimeChange::None, mTimeS, timeS};
    if (timeS > mTimeS)
        update.change = forwards;
    else if (timeS < mTimeS)
        update.change = TimeChange::JumpBack;
    mTimeS = timeS;
    return update;
}

Timeline timelineFor(const Project& project) {
    double lastKeyS = 0.0;
    for (const float timeS : keyTimes(project))
        lastKeyS = std::max(lastKeyS, static_cast<double>(timeS));
    const double stepS = project.physics.dtS > 0.0f ? project.physics.dtS : 1.0 / 60.0;
    return Timeline(0.0, std::max(lastKeyS, TIMELINE_MIN_DEFAULT_END_S), stepS);
}

std::vector<float> keyTimes(const Project& project) {
    std::vector<float> times;
    for (const OwnedKey& key : ownedKeys(project))
        times.push_back(key.timeS);
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

std::vector<OwnedKey> ownedKeys(const Project& project) {
    std::vector<OwnedKey> keys;
    for (std::size_t i = 0; i < project.wind.size(); ++i)
        for (const PathKey& key : project.wind[i].source.path)
            keys.push_back({key.timeS, true, i});
    for (std::size_t i = 0; i < project.colliders.size(); ++i)
        for (const PathKey& key : project.colliders[i].path)
            keys.push_back({key.timeS, false, i});
    std::stable_sort(keys.begin(), keys.end(),
                     [](const OwnedKey& a, const OwnedKey& b) { return a.timeS < b.timeS; });
    return keys;
}

std::optional<OwnedKey> nearestOwnedKey(const std::vector<OwnedKey>& keys, float timeS,
                                        float toleranceS) {
    std::optional<OwnedKey> best;
    for (const OwnedKey& key : keys)
        if (const float d = std::abs(key.timeS - timeS);
            d <= toleranceS && (!best || d < std::abs(best->timeS - timeS)))
            best = key;
    return best;
}

std::size_t setKey(std::vector<PathKey>& path, float timeS, glm::vec3 posWorld, float toleranceS) {
    GRASS_ASSERT(std::isfinite(timeS) && toleranceS >= 0.0f);
    GRASS_ASSERT(std::isfinite(posWorld.x) && std::isfinite(posWorld.y) &&
                 std::isfinite(posWorld.z));
    if (const auto near = nearestKey(path, timeS, toleranceS)) {
        path[*near].posWorld = posWorld;
        return *near;
    }
    // After any keys at the same time, so keys keyed in order stay in that order.
    const auto at = std::upper_bound(path.begin(), path.end(), timeS,
                                     [](float t, const PathKey& key) { return t < key.timeS; });
    // The iterator insert returns, not one from before: inserting may reallocate.
    const auto inserted = path.insert(at, PathKey{timeS, posWorld});
    return static_cast<std::size_t>(inserted - path.begin());
}

bool removeKey(std::vector<PathKey>& path, float timeS, float toleranceS) {
    const auto near = nearestKey(path, timeS, toleranceS);
    if (!near)
        return false;
    path.erase(path.begin() + static_cast<std::ptrdiff_t>(*near));
    return true;
}

std::optional<std::size_t> nearestKey(const std::vector<PathKey>& path, float timeS,
                                      float maxDistanceS) {
    std::optional<std::size_t> best;
    float bestDistanceS = maxDistanceS;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const float distanceS = std::abs(path[i].timeS - timeS);
        // Strictly nearer only, so a tie keeps the earlier key; `<=` on the first lets a key
        // exactly at the tolerance count.
        if (best ? distanceS < bestDistanceS : distanceS <= bestDistanceS) {
            best = i;
            bestDistanceS = distanceS;
        }
    }
    return best;
}

}  // namespace grass::core
