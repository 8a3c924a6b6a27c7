// Blade shapes of SPEC §7: how the unit quad (u, v) of a blade is narrowed between its two edges.
// A project picks one per grass layer; the enumerator values are the shape ids of
// shaders/include/shapes.glsl (SHAPE_QUAD ... SHAPE_DANDELION), so keep the two in step.
#pragma once

#include <array>
#include <string_view>

#include "util/result.h"

namespace grass::core {

enum class BladeShape { Quad = 0, Triangle = 1, Quadratic = 2, TriangleTip = 3, Dandelion = 4 };

inline constexpr std::size_t BLADE_SHAPE_COUNT = 5;

// The width correction of SPEC §7 (shaders/include/shapes.glsl's W_MIN_PX, WIDTH_SPAN_PX and
// widthCorrectedT, which these mirror): a blade narrower on screen than MIN_PX blends its shape
// towards the quad over SPAN_PX more pixels, so far blades keep covering pixels instead of
// aliasing away. Φ = 1 − clamp((wpx − MIN_PX)/SPAN_PX, 0, 1) and t' = t + Φ·(u − t), so at
// Φ = 1 both edges are the quad's. SPEC writes t' = max(t, Φ·u), which moves the u = 1 edge
// alone: a triangle became a trapezoid of ¾ the quad's area, not the quad. widthPx < 0: unknown,
// the shape is left alone.
inline constexpr float WIDTH_CORRECTION_MIN_PX = 1.0f;
inline constexpr float WIDTH_CORRECTION_SPAN_PX = 2.0f;
float widthCorrectionPhi(float widthPx);
float widthCorrectedT(float t, float u, float widthPx);

// The names projects and the CLI use, in enumerator order.
inline constexpr std::array<std::string_view, BLADE_SHAPE_COUNT> BLADE_SHAPE_NAMES{
    "quad", "triangle", "quadratic", "triangle-tip", "dandelion"};
const std::array<std::string_view, BLADE_SHAPE_COUNT>& bladeShapeNames();
std::string_view bladeShapeName(BladeShape shape);
// Error message: `unknown blade shape "x" (valid: "quad", ...)`, no path (the caller adds it).
Result<BladeShape> parseBladeShape(std::string_view name);

}  // namespace grass::core
