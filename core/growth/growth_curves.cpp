#include "growth/growth_curves.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace grass::core {
namespace {

// Clamp that maps NaN to lo: std::clamp passes NaN through, and a NaN map texel or control value
// must not reach the renderer.
float clampOrLow(float x, float lo, float hi) {
    if (!(x >= lo)) {
        return lo;
    }
    return std::min(x, hi);
}

// Quadratic Bézier in one dimension: (1−t)²·y0 + 2(1−t)t·y1 + t²·y2.
float quadratic(float y0, float y1, float y2, float t) {
    const float s = 1.0f - t;
    return s * s * y0 + 2.0f * s * t * y1 + t * t * y2;
}

// Two quadratic pieces joined at GROWTH_LIGHT_JOINT, each over its own parameter so both give
// y2 at the joint (the paper uses the raw l in both and jumps there).
float twoPiece(float y0, float y1, float y2, float y3, float y4, float l) {
    l = clampOrLow(l, 0.0f, 1.0f);
    if (l <= GROWTH_LIGHT_JOINT) {
        return quadratic(y0, y1, y2, l / GROWTH_LIGHT_JOINT);
    }
    const float t = (l - GROWTH_LIGHT_JOINT) / (1.0f - GROWTH_LIGHT_JOINT);
    return quadratic(y2, y3, y4, std::min(t, 1.0f));
}

}  // namespace

Result<void> validate(const GrowthCurves& curves) {
    struct Field {
        const char* name;
        float value;
    };
    const Field fields[] = {
        {"gy0", curves.gy0}, {"gy1", curves.gy1}, {"gy2", curves.gy2}, {"wy0", curves.wy0},
        {"wy1", curves.wy1}, {"wy2", curves.wy2}, {"wy3", curves.wy3}, {"wy4", curves.wy4},
        {"hy0", curves.hy0}, {"hy1", curves.hy1}, {"hy2", curves.hy2}, {"hy3", curves.hy3},
        {"hy4", curves.hy4},
    };
    for (const Field& field : fields) {
        if (!std::isfinite(field.value)) {
            return makeError(field.name, "growth control value must be a finite number in [0, 1]");
        }
        if (field.value < 0.0f || field.value > 1.0f) {
            return makeError(field.name, "growth control value must be in [0, 1], got " +
                                             std::to_string(field.value));
        }
    }
    return {};
}

float soilCurve(const GrowthCurves& curves, float g) {
    return quadratic(curves.gy0, curves.gy1, curves.gy2, clampOrLow(g, 0.0f, 1.0f));
}

float widthLightCurve(const GrowthCurves& curves, float l) {
    return twoPiece(curves.wy0, curves.wy1, curves.wy2, curves.wy3, curves.wy4, l);
}

float heightLightCurve(const GrowthCurves& curves, float l) {
    return twoPiece(curves.hy0, curves.hy1, curves.hy2, curves.hy3, curves.hy4, l);
}

GrowthParams growthParams(const GrowthCurves& curves, float g, float l) {
    const float f1 = soilCurve(curves, g);
    const float f2 = widthLightCurve(curves, l);
    const float f3 = heightLightCurve(curves, l);
    // Raw values first: gamma is defined on the paper's unclamped alpha and beta.
    const float alpha = (f1 + f2) / 8.0f;
    const float beta = (f1 + f3) / 2.0f;
    GrowthParams p;
    p.gamma = beta - alpha + f3;
    p.alpha = clampOrLow(alpha, 0.0f, GROWTH_ALPHA_MAX);
    p.beta = clampOrLow(beta, 0.0f, 1.0f);
    p.theta =
        clampOrLow(std::numbers::pi_v<float> * p.gamma / 1.75f / 3.0f, 0.0f, GROWTH_THETA_MAX_RAD);
    p.b = clampOrLow((f1 + (f2 + f3) / 2.0f) / 2.0f, 0.0f, 1.0f);
    return p;
}

BladeGrowth bladeGrowth(const GrowthParams& params) {
    BladeGrowth blade;
    blade.heightScale = clampOrLow(params.beta, 0.0f, 1.0f);
    blade.widthScale = clampOrLow(params.alpha, 0.0f, GROWTH_ALPHA_MAX) / GROWTH_ALPHA_MAX;
    blade.restLeanRad = clampOrLow(params.theta, 0.0f, GROWTH_THETA_MAX_RAD);
    blade.colourBlend = clampOrLow(params.b, 0.0f, 1.0f);
    return blade;
}

}  // namespace grass::core
