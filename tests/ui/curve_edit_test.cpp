// Curve editors: evaluation matches SPEC §9's re-parameterised pieces, handles drag the right
// control value by the expected amount and clamp to [0, 1].
#include "ui/curve_edit.h"

#include <gtest/gtest.h>

#include <variant>

#include "tests/ui/ui_harness.h"

namespace grass::ui {
namespace {

using test::UiHarness;

TEST(UiCurve, TwoPieceCurveMeetsAtTheJointAndHitsItsEnds) {
    const std::array<float, 5> v{0.2f, 0.35f, 0.5f, 0.85f, 0.9f};
    EXPECT_FLOAT_EQ(evalTwoPieceCurve(v, 0.0f), 0.2f);
    EXPECT_FLOAT_EQ(evalTwoPieceCurve(v, 0.3f), 0.5f);
    EXPECT_NEAR(evalTwoPieceCurve(v, 0.3f + 1e-5f), 0.5f, 1e-4f);
    EXPECT_FLOAT_EQ(evalTwoPieceCurve(v, 1.0f), 0.9f);
    // Midpoints of each piece in its own parameter (t = 0.5).
    EXPECT_FLOAT_EQ(evalTwoPieceCurve(v, 0.15f), 0.25f * 0.2f + 0.5f * 0.35f + 0.25f * 0.5f);
    EXPECT_FLOAT_EQ(evalTwoPieceCurve(v, 0.65f), 0.25f * 0.5f + 0.5f * 0.85f + 0.25f * 0.9f);
    EXPECT_FLOAT_EQ(evalTwoPieceCurve(v, 2.0f), 0.9f) << "x clamped";
    const std::array<float, 3> b{0.1f, 0.6f, 1.0f};
    EXPECT_FLOAT_EQ(evalBezierCurve(b, 0.5f), 0.25f * 0.1f + 0.5f * 0.6f + 0.25f * 1.0f);
    EXPECT_FLOAT_EQ(evalBezierCurve(b, -1.0f), 0.1f);
}

// Presses on handle `index` of a curve editor and moves the pointer by `dy` points, returning the
// values after each step through `build`.
template <class F>
void dragHandle(UiHarness& h, Vec2 handle, float dy, F&& build) {
    h.moveTo(handle);
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(handle + Vec2(0.0f, dy));
    h.frame(build);
}

TEST(UiCurve, DraggingABezierHandleMovesThatValueAndClamps) {
    UiHarness h;
    std::array<float, 3> values{0.2f, 0.5f, 0.8f};
    Response r;
    const auto build = [&](Ui& ui) { r = bezierCurveEdit(ui, "Soil", values); };
    h.frame(build);
    const Rect inner = curvePlotInner(r.rect());
    EXPECT_FLOAT_EQ(r.rect().width(), CURVE_DEFAULT_SIZE.x);
    EXPECT_FLOAT_EQ(r.rect().height(), CURVE_DEFAULT_SIZE.y);
    // Grabbed 2 points off-centre: the handle must not jump to the pointer.
    const Vec2 middle{inner.min.x + 0.5f * inner.width(),
                      inner.max.y - 0.5f * inner.height() + 2.0f};
    dragHandle(h, middle, 0.2f * inner.height(), build);
    EXPECT_TRUE(r.changed());
    EXPECT_NEAR(values[1], 0.3f, 1e-5f);
    EXPECT_FLOAT_EQ(values[0], 0.2f);
    EXPECT_FLOAT_EQ(values[2], 0.8f);
    h.moveTo(middle + Vec2(0.0f, 500.0f));
    h.frame(build);
    EXPECT_FLOAT_EQ(values[1], 0.0f) << "clamped at the bottom";
    h.moveTo(middle + Vec2(30.0f, -500.0f));
    h.frame(build);
    EXPECT_FLOAT_EQ(values[1], 1.0f) << "clamped at the top";
    h.release();
    h.frame(build);
    EXPECT_FALSE(r.changed());
    EXPECT_FLOAT_EQ(values[0], 0.2f);
    EXPECT_FLOAT_EQ(values[2], 0.8f);
}

TEST(UiCurve, DraggingATwoPieceHandleMovesTheRightValue) {
    UiHarness h;
    std::array<float, 5> values{0.2f, 0.35f, 0.5f, 0.85f, 0.9f};
    const std::array<float, 5> before = values;
    Response r;
    const auto build = [&](Ui& ui) { r = twoPieceCurveEdit(ui, "Height vs light", values); };
    h.frame(build);
    const Rect inner = curvePlotInner(r.rect());
    for (std::size_t i = 0; i < values.size(); ++i) {
        SCOPED_TRACE(i);
        const Vec2 handle{inner.min.x + TWO_PIECE_CONTROL_X[i] * inner.width(),
                          inner.max.y - values[i] * inner.height()};
        // Up by a tenth of the range: values below 0.9 rise by 0.1, the last one clamps at 1.
        dragHandle(h, handle, -0.1f * inner.height(), build);
        h.release();
        h.frame(build);
        for (std::size_t j = 0; j < values.size(); ++j) {
            const float expected = j == i ? std::min(before[j] + 0.1f, 1.0f) : before[j];
            EXPECT_NEAR(values[j], expected, 1e-5f) << "value " << j;
        }
        values = before;
    }
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
}

TEST(UiCurve, HoveringAHandleHighlightsIt) {
    UiHarness h;
    std::array<float, 3> values{0.5f, 0.5f, 0.5f};
    Response r;
    const auto build = [&](Ui& ui) { r = bezierCurveEdit(ui, "", values); };
    h.frame(build);
    const auto bigCircles = [&] {
        int n = 0;
        for (const ClippedShape& c : h.ctx.output().shapes) {
            if (const auto* circle = std::get_if<CircleShape>(&c.shape)) {
                n += circle->radius > CURVE_HANDLE_RADIUS ? 1 : 0;
            }
        }
        return n;
    };
    EXPECT_EQ(bigCircles(), 0);
    const Rect inner = curvePlotInner(r.rect());
    h.moveTo({inner.max.x, inner.centre().y});
    h.frame(build);
    h.frame(build);
    EXPECT_TRUE(r.hovered());
    EXPECT_EQ(bigCircles(), 1);
    EXPECT_EQ(h.ctx.output().cursor, CursorIcon::ResizeVertical);
}

TEST(UiCurve, IdsStableAcrossFramesAndEditors) {
    UiHarness h;
    std::array<float, 3> a{};
    std::array<float, 5> b{};
    std::array<float, 5> c{};
    Id first;
    for (int i = 0; i < 3; ++i) {
        h.frame([&](Ui& ui) {
            const Response ra = bezierCurveEdit(ui, "Soil", a);
            twoPieceCurveEdit(ui, "Width", b);
            twoPieceCurveEdit(ui, "Height", c);
            if (i == 0) {
                first = ra.id();
            }
            EXPECT_EQ(ra.id(), first);
        });
        EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
    }
}

}  // namespace
}  // namespace grass::ui
