// The side panel's Snow section driven as a user drives it, with simulated input and no window:
// the checkbox turns snow on, a drag changes the amount, the viewport's render options follow
// the project, each edit is one undo step, and whatever the widgets reach still loads. (In
// grass_gl_tests because the panels link the renderer's options; no GL context is used.)
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "panel_driver.h"
#include "snow/snow_drift.h"
#include "support/scratch_folder.h"
#include "support/test_fonts.h"
#include "support/test_paths.h"
#include "ui/font.h"

namespace grass::test {
namespace {

// The editor on the tiny growth project (panel_driver.h).
struct SnowPanelDriver : PanelDriver {
    SnowPanelDriver() : PanelDriver(sourceDir() / "tests/data/projects/growth_tiny") {}

    // The project's snow as the viewport draws it: the drift's direction resolved from the
    // project's winds (core::snowWithWindDrift), everything else as the project says.
    core::SnowParams drawnSnow() const {
        std::vector<core::WindSource> wind;
        for (const core::WindDesc& source : state.doc.loaded.project.wind)
            wind.push_back(source.source);
        return core::snowWithWindDrift(state.doc.loaded.project.snow, wind);
    }
};

TEST(EditorSnowPanel, CheckboxAndAmountEditProjectAndViewportAndUndo) {
    SnowPanelDriver editor;
    const core::SnowParams before = editor.state.doc.loaded.project.snow;
    ASSERT_EQ(before.enabled, 0u) << "the test project must start without snow";
    editor.click("Snow");
    editor.click("snow");
    EXPECT_EQ(editor.state.doc.loaded.project.snow.enabled, 1u);
    EXPECT_EQ(editor.state.view.options.snow.enabled, 1u) << "the viewport must draw the snow";
    EXPECT_TRUE(editor.state.doc.dirty);
    EXPECT_EQ(editor.state.doc.history.undoSteps(), 1u);

    // The amount's value box ("0.150"): dragged right, the snow deepens; one step for the drag.
    editor.drag("0.150", 40.0f);
    const float amount = editor.state.doc.loaded.project.snow.amountM;
    EXPECT_GT(amount, before.amountM + 0.05f);
    EXPECT_LE(amount, before.maxAmountM);
    EXPECT_EQ(editor.state.view.options.snow, editor.drawnSnow());
    EXPECT_EQ(editor.state.doc.history.undoSteps(), 2u) << "a drag is one undo step";

    ASSERT_TRUE(editor::undo(editor.state));
    editor.frame();
    EXPECT_EQ(editor.state.doc.loaded.project.snow.amountM, before.amountM);
    EXPECT_EQ(editor.state.doc.loaded.project.snow.enabled, 1u);
    EXPECT_EQ(editor.state.view.options.snow.amountM, before.amountM)
        << "after an undo the viewport must draw the project's snow";
    ASSERT_TRUE(editor::undo(editor.state));
    editor.frame();
    EXPECT_EQ(editor.state.doc.loaded.project.snow, before);
    EXPECT_EQ(editor.state.view.options.snow, editor.drawnSnow());
    ASSERT_TRUE(editor::redo(editor.state));
    editor.frame();
    EXPECT_EQ(editor.state.view.options.snow.enabled, 1u);
}

TEST(EditorSnowPanel, DraggedPastTheEndsTheProjectStillLoads) {
    const ScratchFolder folder("editor-snow-panel");
    SnowPanelDriver editor;
    editor.click("Snow");
    editor.click("snow");
    // Far past the track's end: the amount stops at max amount, which stops at the amount.
    editor.drag("0.150", 2000.0f);
    EXPECT_EQ(editor.state.doc.loaded.project.snow.amountM,
              editor.state.doc.loaded.project.snow.maxAmountM);
    editor.drag("1.00", -2000.0f);
    EXPECT_EQ(editor.state.doc.loaded.project.snow.maxAmountM,
              editor.state.doc.loaded.project.snow.amountM);
    // The fall direction's y (-1.00, x and z 0) dragged by +1 would reach zero: it stops short.
    editor.drag("-1.00", 100.0f);
    EXPECT_GT(glm::length(editor.state.doc.loaded.project.snow.fallDirection), 1e-3f);
    EXPECT_LT(editor.state.doc.loaded.project.snow.fallDirection.y, 0.0f);

    ASSERT_TRUE(core::saveProject(editor.state.doc.loaded.project, folder / "project.json").ok());
    auto reloaded = core::loadProject(folder / "project.json");
    ASSERT_TRUE(reloaded.ok()) << reloaded.error().str();
    EXPECT_EQ(reloaded->project.snow, editor.state.doc.loaded.project.snow);
}

}  // namespace
}  // namespace grass::test
