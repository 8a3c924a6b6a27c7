// Kim & Cho growth model, control curves and growth parameters (SPEC §9). Everything is unitless:
// the environment inputs soil quality g and light amount l, the control values and the curve
// values all live in [0, 1]; only the bend θ (restLeanRad) is an angle, in radians.
//
// f1(g): soil curve, one quadratic Bézier in g over [0, 1] (control values gy0, gy1, gy2).
// f2(l): width-vs-light, f3(l): height-vs-light: two quadratic Bézier pieces joined at l = 0.3,
// piece 1 over [0, 0.3] with control values y0, y1, y2 and piece 2 over [0.3, 1] with y2, y3,
// y4. Unlike the paper, each piece is evaluated in its own parameter (t = l/0.3 on the first,
// t = (l − 0.3)/0.7 on the second): the paper feeds the raw l into both pieces, which makes the
// curve jump at 0.3. Here both pieces meet at y2 (C0 always; C1 when
// (y2 − y1)/0.3 = (y3 − y2)/0.7, as the defaults are).
#pragma once

#include <numbers>

#include "util/result.h"

namespace grass::core {

// Where f2 and f3 switch from their first to their second Bézier piece (Kim & Cho).
inline constexpr float GROWTH_LIGHT_JOINT = 0.3f;

// The user-editable control values (the editor's curve widgets). Meant to lie in [0, 1]; see
// validate(). Defaults: poor soil grows little (gy0 = 0.1), good soil fully (gy2 = 1.0), with a
// concave middle (gy1 = 0.6: moderate soil is already fairly good). Light as Kim & Cho describe
// it (§3.2): grass short of light grows narrow and relatively tall, grass in strong light wide
// and short, so width rises with light and height falls, both steeper in the dim range. wy and
// hy are C1 at the joint (slope ±0.5 on both sides: (0.5 − 0.35)/0.3 = (0.85 − 0.5)/0.7) so the
// default curves have no visible kink at l = 0.3; hy is wy's mirror, 1 − (0.1, 0.25, 0.4, 0.75,
// 0.8), the rising curve the defaults had before (issue 30 item 5).
struct GrowthCurves {
    float gy0 = 0.1f, gy1 = 0.6f, gy2 = 1.0f;
    float wy0 = 0.2f, wy1 = 0.35f, wy2 = 0.5f, wy3 = 0.85f, wy4 = 0.9f;
    float hy0 = 0.9f, hy1 = 0.75f, hy2 = 0.6f, hy3 = 0.25f, hy4 = 0.2f;

    bool operator==(const GrowthCurves&) const = default;
};

// Rejects a non-finite control value or one outside [0, 1]; the error's path names the field
// ("gy1", "wy3", ...; callers prefix their own location, e.g. a project file's JSON path).
// Within [0, 1] every curve stays within [0, 1] (a Bézier lies in the hull of its control values),
// so α, β, b and the curves need no clamping for validated curves.
Result<void> validate(const GrowthCurves& curves);

// f1(g), f2(l), f3(l). Inputs are clamped to [0, 1] and NaN reads as 0 (painted maps may be
// filtered slightly out of range). The outputs are not clamped: they are what the curves say.
float soilCurve(const GrowthCurves& curves, float g);
float widthLightCurve(const GrowthCurves& curves, float l);
float heightLightCurve(const GrowthCurves& curves, float l);

// Kim & Cho's per-point growth parameters (SPEC §9):
//   alpha = (f1 + f2)/8 in [0, 0.25] (width), beta = (f1 + f3)/2 in [0, 1] (height),
//   gamma = beta − alpha + f3 (unclamped: kept so callers can see how far the paper's θ strays),
//   theta = (π·gamma/1.75)/3 clamped to [0, π/3] (bend, radians),
//   b = (f1 + (f2 + f3)/2)/2 in [0, 1] (colour blend; high b = good conditions, healthy colour).
// The paper claims θ ∈ [0, π/3], but with f in [0, 1] gamma spans [−1/8, 15/8], so the raw θ
// spans [−0.024π, 0.357π]; we clamp it. alpha, beta and b are clamped too (NaN → the lower
// bound) so the function is total for unvalidated control values a user may have typed: the
// renderer must never get a negative width or a NaN from a bad curve widget value.
struct GrowthParams {
    float alpha = 0.0f;
    float beta = 0.0f;
    float gamma = 0.0f;
    float theta = 0.0f;
    float b = 0.0f;

    bool operator==(const GrowthParams&) const = default;
};

inline constexpr float GROWTH_ALPHA_MAX = 0.25f;
inline constexpr float GROWTH_THETA_MAX_RAD = std::numbers::pi_v<float> / 3.0f;

GrowthParams growthParams(const GrowthCurves& curves, float g, float l);

// The growth model mapped onto a Jahrmann blade (SPEC §9, last item): painting soil and light
// changes the live field. Scales are relative to the layer's blade settings:
//   heightScale = beta (beta = 1 gives the layer's maximum height h; beta is already in [0, 1]),
//   widthScale = alpha/0.25 (alpha's maximum gives the layer's maximum width w),
//   restLeanRad = theta (lean of the rest pose away from up, radians, in [0, π/3]),
//   colourBlend = b (0: poor grass colour, 1: healthy grass colour).
// Inputs are re-clamped so a hand-filled GrowthParams cannot produce out-of-range blades.
struct BladeGrowth {
    float heightScale = 1.0f;
    float widthScale = 1.0f;
    float restLeanRad = 0.0f;
    float colourBlend = 1.0f;

    bool operator==(const BladeGrowth&) const = default;
};

BladeGrowth bladeGrowth(const GrowthParams& params);

}  // namespace grass::core
