// Curve editors for unitless response curves on x ∈ [0, 1] with values in [0, 1]: one quadratic
// Bézier (3 control values at x = 0, 0.5, 1) and the two-piece curve of SPEC §9 (5 control values:
// piece 1 on [0, 0.3] with controls at x = 0, 0.15, 0.3; piece 2 on [0.3, 1] at 0.3, 0.65, 1;
// the pieces share the value at 0.3). Each piece is evaluated in its own parameter
// (t = x/0.3, t = (x − 0.3)/0.7), as core/growth/growth_curves.h does; the few lines are
// re-implemented here because grass_ui must not depend on core.
//
// The control values are drawn as handles at their x positions and dragged vertically; a value
// moves by the pointer's movement divided by the plot's inner height (plot height minus
// 2 · CURVE_HANDLE_RADIUS, so handles at 0 and 1 stay inside the widget), clamped to [0, 1].
#pragma once

#include <array>
#include <string_view>

#include "ui/ui.h"

namespace grass::ui {

inline constexpr float CURVE_HANDLE_RADIUS = 5.0f;
inline constexpr float CURVE_JOINT_X = 0.3f;
inline constexpr Vec2 CURVE_DEFAULT_SIZE{200.0f, 100.0f};

// Where the handles sit along x.
inline constexpr std::array<float, 3> BEZIER_CONTROL_X{0.0f, 0.5f, 1.0f};
inline constexpr std::array<float, 5> TWO_PIECE_CONTROL_X{0.0f, 0.15f, 0.3f, 0.65f, 1.0f};

float quadraticBezier(float y0, float y1, float y2, float t);
// x clamped to [0, 1].
float evalBezierCurve(const std::array<float, 3>& values, float x);
float evalTwoPieceCurve(const std::array<float, 5>& values, float x);

// `label` above the plot; the Response's rect is the plot (`size` points). Changed when a value
// moved; hovered when the pointer is over the plot or a handle.
Response bezierCurveEdit(Ui& ui, std::string_view label, std::array<float, 3>& values,
                         Vec2 size = CURVE_DEFAULT_SIZE);
Response twoPieceCurveEdit(Ui& ui, std::string_view label, std::array<float, 5>& values,
                           Vec2 size = CURVE_DEFAULT_SIZE);

// The plot area handles move in: the plot inset by CURVE_HANDLE_RADIUS (for tests and callers
// that overlay marks, e.g. the current light level).
Rect curvePlotInner(Rect plot);

}  // namespace grass::ui
