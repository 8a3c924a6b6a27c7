// Drives a ui::Context frame by frame with simulated input for the UI tests (no window, no GL).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "ui/context.h"
#include "ui/font.h"
#include "support/test_fonts.h"
#include "ui/ui.h"

namespace grass::ui::test {

using grass::test::testFonts;

class UiHarness {
public:
    explicit UiHarness(Rect panelRect = {{10.0f, 20.0f}, {310.0f, 580.0f}})
        : ctx(testFonts()), panel(panelRect) {
        input.screenRect = {{0.0f, 0.0f}, {800.0f, 600.0f}};
        input.pointerPos = {790.0f, 590.0f};
    }

    // One frame: `build` fills a root Ui covering the panel.
    template <class F>
    const Output& frame(F&& build) {
        ctx.beginFrame(input);
        Ui ui(ctx, panel);
        build(ui);
        const Output& out = ctx.endFrame();
        // Events last one frame; held state (pointer, buttons) stays.
        input.keys.clear();
        input.text.clear();
        input.scrollDelta = Vec2(0.0f);
        input.timeS += 1.0 / 60.0;
        return out;
    }

    void moveTo(Vec2 p) { input.pointerPos = p; }
    void press() { input.buttonDown[0] = true; }
    void release() { input.buttonDown[0] = false; }

    // Hover, press and release at `p`: three frames.
    template <class F>
    void clickAt(Vec2 p, F&& build) {
        moveTo(p);
        frame(build);
        press();
        frame(build);
        release();
        frame(build);
    }

    Context ctx;
    Input input;
    Rect panel;
};

// The box of the topmost (last painted) text shape showing exactly `text`, if any: a combo
// box's selected text appears both in the box and, above it, in the open list.
inline std::optional<Rect> findText(const Output& out, std::string_view text) {
    for (auto it = out.shapes.rbegin(); it != out.shapes.rend(); ++it) {
        if (const auto* t = std::get_if<TextShape>(&it->shape); t && t->text == text) {
            return Rect::fromMinSize(t->pos, testFonts().textSize(t->text, t->sizePt));
        }
    }
    return std::nullopt;
}

}  // namespace grass::ui::test
