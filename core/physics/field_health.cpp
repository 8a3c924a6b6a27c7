#include "physics/field_health.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/assert.h"

namespace grass::core {

namespace {

bool isFinite(glm::vec4 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

double FieldHealth::meanTipDisplacementM() const {
    return blades > 0 ? sumTipDisplacementM / static_cast<double>(blades) : 0.0;
}

double FieldHealth::meanRelLengthError() const {
    return blades > 0 ? sumRelLengthError / static_cast<double>(blades) : 0.0;
}

double FieldHealth::crushedShare() const {
    return blades > 0 ? static_cast<double>(crushed) / static_cast<double>(blades) : 0.0;
}

void FieldHealth::add(const FieldHealth& other) {
    blades += other.blades;
    nonfinite += other.nonfinite;
    belowGround += other.belowGround;
    crushed += other.crushed;
    maxRelLengthError = std::max(maxRelLengthError, other.maxRelLengthError);
    sumRelLengthError += other.sumRelLengthError;
    maxLengthErrorPerTolerance =
        std::max(maxLengthErrorPerTolerance, other.maxLengthErrorPerTolerance);
    sumTipDisplacementM += other.sumTipDisplacementM;
    maxTipDisplacementM = std::max(maxTipDisplacementM, other.maxTipDisplacementM);
}

float bladeLengthEstimate(const Blade& blade) {
    const float l0 = glm::length(blade.v2() - blade.v0());
    const float l1 = glm::length(blade.v1() - blade.v0()) + glm::length(blade.v2() - blade.v1());
    return (2.0f * l0 + l1) / 3.0f;
}

float lengthTolerance(const Blade& blade) {
    const glm::vec3 a = glm::abs(blade.v0());
    const float h = blade.h();
    return 1e-4f * h +
           4.0f * std::numeric_limits<float>::epsilon() * (std::max({a.x, a.y, a.z}) + h);
}

FieldHealth measureHealth(std::span<const Blade> blades, std::span<const float> eta,
                          std::span<const glm::vec3> restTips) {
    GRASS_ASSERT(eta.size() == blades.size() && restTips.size() == blades.size());
    FieldHealth health;
    for (std::size_t i = 0; i < blades.size(); ++i) {
        const Blade& b = blades[i];
        if (!isFinite(b.v0Theta) || !isFinite(b.v1H) || !isFinite(b.v2W) || !isFinite(b.upS) ||
            !std::isfinite(eta[i])) {
            ++health.nonfinite;
            continue;
        }
        const float h = b.h();
        if (!(h > 0.0f))
            continue;
        ++health.blades;
        const double absError = std::abs(static_cast<double>(bladeLengthEstimate(b)) - h);
        const double lengthError = absError / static_cast<double>(h);
        health.maxRelLengthError = std::max(health.maxRelLengthError, lengthError);
        health.sumRelLengthError += lengthError;
        health.maxLengthErrorPerTolerance = std::max(
            health.maxLengthErrorPerTolerance, absError / static_cast<double>(lengthTolerance(b)));
        if (glm::dot(b.v2() - b.v0(), b.up()) < -1e-5f * h)
            ++health.belowGround;
        if (eta[i] > 0.0f)
            ++health.crushed;
        const double displacement = glm::length(b.v2() - restTips[i]);
        health.sumTipDisplacementM += displacement;
        health.maxTipDisplacementM = std::max(health.maxTipDisplacementM, displacement);
    }
    return health;
}

}  // namespace grass::core
