// Curve editor widgets (curve_edit.h).
#include "ui/curve_edit.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <span>
#include <vector>

namespace grass::ui {

namespace {

// Enough segments that the polyline of a quadratic looks smooth at a few hundred points wide.
constexpr int CURVE_SAMPLES = 64;

// Grab offset of the handle being dragged (value − value under the pointer at the press), so a
// handle grabbed off-centre does not jump to the pointer.
struct CurveDragState {
    float grabOffset = 0.0f;
};

Response curveEditImpl(Ui& ui, std::string_view label, std::span<float> values,
                       std::span<const float> xs, const std::function<float(float)>& eval,
                       Vec2 size, bool showJoint) {
    Context& ctx = ui.context();
    const Style& s = ui.style();
    const Id id = ui.makeId(label);
    const float labelHeight = label.empty() ? 0.0f : ctx.fonts().lineHeight(s.textSizePt);
    const float gap = label.empty() ? 0.0f : s.itemSpacing.y;
    const Rect total = ui.allocate({size.x, labelHeight + gap + size.y});
    const Rect plot{{total.min.x, total.min.y + labelHeight + gap}, total.max};
    const Rect inner = curvePlotInner(plot);
    const auto toScreen = [&](float x, float v) {
        return Vec2{inner.min.x + x * inner.width(), inner.max.y - v * inner.height()};
    };
    const auto valueAt = [&](float y) {
        return inner.height() > 0.0f ? (inner.max.y - y) / inner.height() : 0.0f;
    };

    // The plot first, then the handles: later interactions are on top for hit testing.
    Response result = ui.interact(plot, id, Sense::hover());
    CurveDragState& drag = ctx.state<CurveDragState>(id.with("drag"));
    std::vector<Response> handles;
    handles.reserve(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const Vec2 c = toScreen(xs[i], std::clamp(values[i], 0.0f, 1.0f));
        // A hit box larger than the drawn handle (small targets are hard to grab), kept within
        // the plot so the Response's rect stays the plot's.
        const Rect hit =
            Rect{c - Vec2(CURVE_HANDLE_RADIUS + 2.0f), c + Vec2(CURVE_HANDLE_RADIUS + 2.0f)}
                .intersect(plot);
        Response h = ui.interact(hit, id.with(std::uint64_t(i)), Sense::dragOnly());
        if (h.dragStarted()) {
            drag.grabOffset = values[i] - valueAt(h.pointerPos().y);
        }
        if (h.dragged()) {
            const float v = std::clamp(valueAt(h.pointerPos().y) + drag.grabOffset, 0.0f, 1.0f);
            if (v != values[i]) {
                values[i] = v;
                h.markChanged();
            }
        }
        if (h.hovered() || h.dragged()) {
            ctx.output().cursor = CursorIcon::ResizeVertical;
        }
        result.unite(h);
        handles.push_back(h);
    }

    Painter& p = ui.painter();
    if (const std::string_view shown = shownLabel(label); !shown.empty()) {
        p.text(total.min, shown, s.textSizePt, s.text);
    }
    p.rect(plot, s.rounding, s.extremeBg, {1.0f, s.separator});
    // Quarter grid lines, and the joint of the two pieces.
    for (int i = 1; i < 4; ++i) {
        const float t = 0.25f * float(i);
        p.line(toScreen(0.0f, t), toScreen(1.0f, t), {1.0f, s.scrollBarTrack});
        p.line(toScreen(t, 0.0f), toScreen(t, 1.0f), {1.0f, s.scrollBarTrack});
    }
    if (showJoint) {
        p.line(toScreen(CURVE_JOINT_X, 0.0f), toScreen(CURVE_JOINT_X, 1.0f), {1.0f, s.separator});
    }
    // The control polygon: the curve lies inside its hull.
    std::vector<Vec2> polygon;
    for (std::size_t i = 0; i < values.size(); ++i) {
        polygon.push_back(toScreen(xs[i], values[i]));
    }
    p.path(std::move(polygon), false, Color32::transparent(), {1.0f, s.textWeak});
    std::vector<Vec2> curve;
    curve.reserve(CURVE_SAMPLES + 1);
    for (int i = 0; i <= CURVE_SAMPLES; ++i) {
        const float x = float(i) / CURVE_SAMPLES;
        curve.push_back(toScreen(x, std::clamp(eval(x), 0.0f, 1.0f)));
    }
    p.path(std::move(curve), false, Color32::transparent(), {2.0f, s.accent});
    for (std::size_t i = 0; i < values.size(); ++i) {
        const Response& h = handles[i];
        const bool hot = h.hovered() || h.dragged();
        const Vec2 c = toScreen(xs[i], values[i]);
        p.circle(c, hot ? CURVE_HANDLE_RADIUS + 1.0f : CURVE_HANDLE_RADIUS,
                 hot ? s.textStrong : s.inactive.text, {1.0f, s.extremeBg});
        if (hot) {
            // The exact value next to the handle being edited.
            char text[16];
            std::snprintf(text, sizeof text, "%.3f", double(values[i]));
            const bool right = xs[i] < 0.5f;
            p.text(c + Vec2(right ? 8.0f : -8.0f, 0.0f), text, s.textSizePt, s.textStrong,
                   {right ? 0.0f : 1.0f, values[i] > 0.5f ? 0.0f : 1.0f});
        }
    }
    return result;
}

}  // namespace

float quadraticBezier(float y0, float y1, float y2, float t) {
    const float u = 1.0f - t;
    return u * u * y0 + 2.0f * u * t * y1 + t * t * y2;
}

float evalBezierCurve(const std::array<float, 3>& v, float x) {
    return quadraticBezier(v[0], v[1], v[2], std::clamp(x, 0.0f, 1.0f));
}

float evalTwoPieceCurve(const std::array<float, 5>& v, float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    if (x <= CURVE_JOINT_X) {
        return quadraticBezier(v[0], v[1], v[2], x / CURVE_JOINT_X);
    }
    return quadraticBezier(v[2], v[3], v[4], (x - CURVE_JOINT_X) / (1.0f - CURVE_JOINT_X));
}

Rect curvePlotInner(Rect plot) {
    return plot.expand(-CURVE_HANDLE_RADIUS);
}

Response bezierCurveEdit(Ui& ui, std::string_view label, std::array<float, 3>& values, Vec2 size) {
    return curveEditImpl(
        ui, label, values, BEZIER_CONTROL_X,
        [&values](float x) { return evalBezierCurve(values, x); }, size, false);
}

Response twoPieceCurveEdit(Ui& ui, std::string_view label, std::array<float, 5>& values,
                           Vec2 size) {
    return curveEditImpl(
        ui, label, values, TWO_PIECE_CONTROL_X,
        [&values](float x) { return evalTwoPieceCurve(values, x); }, size, true);
}

}  // namespace grass::ui
