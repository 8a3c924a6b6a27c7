// The side panel's Snow section driven as a user drives it, with simulated input and no window:
// the checkbox turns snow on, a drag changes the amount, the viewport's render options follow
// the project, each edit is one undo step, and whatever the widgets reach still loads. (In
// grass_gl_tests because the panels link the renderer's options; no GL context is used.)
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "app/edit_actions.h"
#include "app/panels.h"
#include "snow/snow_drift.h"
#include "support/scratch_folder.h"
#include "support/test_fonts.h"
#include "support/test_paths.h"
#include "ui/font.h"

namespace grass::test {
namespace {

// The editor on the tiny growth project, as main.cpp runs it: panels, then a history step once
// no widget is active. A tall screen keeps the Snow section, last in the panel, unscrolled.
struct SnowPanelDriver {
    SnowPanelDriver() : ctx(testFonts()) {
        auto loaded = core::loadProject(sourceDir() / "tests/data/projects/growth_tiny");
        EXPECT_TRUE(loaded.ok()) << loaded.error().str();
        state.doc.loaded = std::move(*loaded);
        state.view.options = editor::viewRenderOptions(state);
        editor::resetHistory(state);
        input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};
        input.hasPointer = true;
        input.pointerPos = {1000.0f, 700.0f};
    }

    const ui::Output& frame() {
        ctx.beginFrame(input);
        editor::buildPanels(ctx, state);
        const ui::Output& out = ctx.endFrame();
        editor::recordProjectEdit(state, ctx.activeId().value != 0);
        // What the viewport draws next, derived from the project as main.cpp does each frame.
        state.view.options = editor::viewRenderOptions(state);
        input.keys.clear();
        input.text.clear();
        input.timeS += 1.0 / 60.0;
        return out;
    }

    // Where the topmost text shape reading exactly `text` starts, plus a few points inside.
    ui::Vec2 find(std::string_view text) {
        std::optional<ui::Vec2> at;
        const ui::Output& out = frame();
        for (const ui::ClippedShape& shape : out.shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text == text)
                at = t->pos + ui::Vec2(3.0f, 6.0f);
        EXPECT_TRUE(at.has_value()) << "nothing reads \"" << text << "\"";
        return at.value_or(ui::Vec2(-100.0f, -100.0f));
    }

    // Hover, press, release on the text.
    void click(std::string_view text) {
        input.pointerPos = find(text);
        frame();
        input.buttonDown[0] = true;
        frame();
        input.buttonDown[0] = false;
        frame();
    }

    // Presses on the text (a drag value's box) and drags `dx` points right over four frames.
    void drag(std::string_view text, float dx) {
        input.pointerPos = find(text);
        frame();
        input.buttonDown[0] = true;
        frame();
        for (int i = 0; i < 4; ++i) {
            input.pointerPos.x += 0.25f * dx;
            frame();
        }
        input.buttonDown[0] = false;
        frame();
    }

    ui::Context ctx;
    ui::Input input;
    editor::EditorState state;

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
