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

// The names projects and the CLI use, in enumerator order.
inline constexpr std::array<std::string_view, BLADE_SHAPE_COUNT> BLADE_SHAPE_NAMES{
    "quad", "triangle", "quadratic", "triangle-tip", "dandelion"};
const std::array<std::string_view, BLADE_SHAPE_COUNT>& bladeShapeNames();
std::string_view bladeShapeName(BladeShape shape);
// Error message: `unknown blade shape "x" (valid: "quad", ...)`, no path (the caller adds it).
Result<BladeShape> parseBladeShape(std::string_view name);

}  // namespace grass::core
