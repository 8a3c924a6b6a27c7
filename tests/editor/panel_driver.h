// The editor's side panel driven as a user drives it, with simulated input and no window: the
// panels of a project, then a history step once no widget is active, as main.cpp runs them.
// (The panels link the renderer's options; no GL context is used.)
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string_view>
#include <variant>

#include "app/edit_actions.h"
#include "app/panels.h"
#include "support/test_fonts.h"
#include "ui/font.h"

namespace grass::test {

// One frame of the panels with `input`, whose per-frame events are then cleared; with
// `recordHistory`, a history step once no widget is active and the viewport's options derived
// from the project again, as main.cpp does each frame.
inline const ui::Output& panelFrame(ui::Context& ctx, ui::Input& input, editor::EditorState& state,
                                    bool recordHistory) {
    ctx.beginFrame(input);
    editor::buildPanels(ctx, state);
    const ui::Output& out = ctx.endFrame();
    if (recordHistory) {
        editor::recordProjectEdit(state, ctx.activeId().value != 0);
        state.view.options = editor::viewRenderOptions(state);
    }
    input.keys.clear();
    input.text.clear();
    input.timeS += 1.0 / 60.0;
    return out;
}

// A tall screen keeps the last sections of the panel unscrolled.
struct PanelDriver {
    explicit PanelDriver(const std::filesystem::path& project) : ctx(testFonts()) {
        auto loaded = core::loadProject(project);
        EXPECT_TRUE(loaded.ok()) << loaded.error().str();
        if (loaded.ok())
            state.doc.loaded = std::move(*loaded);
        state.view.options = editor::viewRenderOptions(state);
        editor::resetHistory(state);
        input.screenRect = {{0.0f, 0.0f}, {1280.0f, 3000.0f}};
        input.hasPointer = true;
        input.pointerPos = {1000.0f, 700.0f};
    }

    const ui::Output& frame() { return panelFrame(ctx, input, state, true); }

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

    // Whether the panel shows a text reading exactly `text`.
    bool shows(std::string_view text) {
        const ui::Output& out = frame();
        for (const ui::ClippedShape& shape : out.shapes)
            if (const auto* t = std::get_if<ui::TextShape>(&shape.shape); t && t->text == text)
                return true;
        return false;
    }

    ui::Context ctx;
    ui::Input input;
    editor::EditorState state;
};

}  // namespace grass::test
