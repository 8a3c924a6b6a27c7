// The viewport's picture while the user interacts (issue 24): viewRenderOptions applies the
// adaptive quality's rung, and at rung 0 — whenever input has stopped — the options are exactly
// the project's with the view's overrides, so the refined picture is the full-quality one.
#include <gtest/gtest.h>

#include "app/panels.h"
#include "support/plane_project.h"

namespace grass::test {
namespace {

struct Driver {
    Driver() {
        PlaneField field;
        state.doc.loaded = planeFieldProject(field);
    }
    editor::EditorState state;
};

void expectSameOptions(const render::RenderOptions& a, const render::RenderOptions& b) {
    EXPECT_EQ(a.cull.keepEvery, b.cull.keepEvery);
    EXPECT_EQ(a.cull.lodDistanceM, b.cull.lodDistanceM);
    EXPECT_EQ(a.widthScale, b.widthScale);
    EXPECT_EQ(a.stripSegments, b.stripSegments);
    EXPECT_EQ(a.technique, b.technique);
}

TEST(AdaptiveQuality, AtRestTheViewDrawsTheProjectsOwnSettings) {
    Driver d;
    const render::RenderOptions full =
        render::renderOptionsFor(d.state.doc.project(), d.state.view.softwareRenderer);
    render::RenderOptions drawn = editor::viewRenderOptions(d.state);
    expectSameOptions(drawn, full);
    EXPECT_EQ(drawn.cull.keepEvery, 1);
    EXPECT_EQ(drawn.widthScale, 1.0f);

    // A slow frame while orbiting reduces; input stopping brings back exactly the full options.
    d.state.view.quality.update(900.0, true, 1.0);
    ASSERT_GT(d.state.view.quality.level(), 0);
    const core::Reduction& r = d.state.view.quality.reduction();
    drawn = editor::viewRenderOptions(d.state);
    EXPECT_EQ(drawn.cull.keepEvery, r.keepEvery);
    EXPECT_GT(drawn.widthScale, 1.0f) << "fewer blades are drawn wider";
    EXPECT_LT(drawn.cull.lodDistanceM, full.cull.lodDistanceM);
    EXPECT_GT(drawn.cull.lodDistanceM, 0.0f) << "0 would mean full detail everywhere";

    d.state.view.quality.update(60.0, false, 1.5);
    ASSERT_EQ(d.state.view.quality.level(), 0);
    expectSameOptions(editor::viewRenderOptions(d.state), full);
}

TEST(AdaptiveQuality, TheDocumentIsNeverTouched) {
    Driver d;
    const core::Project before = d.state.doc.project();
    d.state.view.quality.update(900.0, true, 1.0);
    editor::viewRenderOptions(d.state);
    EXPECT_EQ(d.state.doc.project(), before);
    EXPECT_FALSE(d.state.doc.dirty);
}

}  // namespace
}  // namespace grass::test
