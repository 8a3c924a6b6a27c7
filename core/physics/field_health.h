// Health figures of a simulated field (issue 4, `grass sim --report`): what a user checks to trust
// a simulation at a given step and substep policy. Computed from blades, η and rest tips alone,
// so the CPU reference and a GPU read-back are measured by the same code.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <span>

#include "blade/blade.h"

namespace grass::core {

struct FieldHealth {
    std::size_t blades = 0;       // live blades (h > 0); padding and collapsed blades excluded
    std::size_t nonfinite = 0;    // blades with NaN/Inf anywhere, padding included
    std::size_t belowGround = 0;  // tip under the blade's ground plane by more than 1e-5·h
    std::size_t crushed = 0;      // blades still carrying collision strength (η > 0)
    // max |L − h| / h, L the degree-2 length estimate of SPEC §3 (what validation holds).
    double maxRelLengthError = 0.0;
    double sumRelLengthError = 0.0;  // Σ |L − h| / h over live blades
    // max |L − h| / lengthTolerance(blade): at most 1 while validation holds its stated tolerance.
    double maxLengthErrorPerTolerance = 0.0;
    double sumTipDisplacementM = 0.0;  // Σ |v2 − Iv2|
    double maxTipDisplacementM = 0.0;

    double meanTipDisplacementM() const;
    double meanRelLengthError() const;
    double crushedShare() const;
    // Folds another part of the field (another layer) into this one.
    void add(const FieldHealth& other);
};

// The length estimate (2·|v2 − v0| + |v1 − v0| + |v2 − v1|) / 3 (SPEC §3, degree 2).
float bladeLengthEstimate(const Blade& blade);

// The stated tolerance of |L − h| (docs/physics.md): 1e-4·h, plus the float rounding of absolute
// world positions, 4·ε·(max|v0| + h) (a blade far from the origin loses ulp(|v0|)).
float lengthTolerance(const Blade& blade);

FieldHealth measureHealth(std::span<const Blade> blades, std::span<const float> eta,
                          std::span<const glm::vec3> restTips);

}  // namespace grass::core
