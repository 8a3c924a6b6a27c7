#include "app/input_passes.h"

namespace grass::editor {

std::vector<ui::Input> uiPasses(const ui::Input& last, const std::vector<ButtonEvent>& events,
                                std::vector<std::size_t>* sources) {
    std::vector<ui::Input> passes;
    if (sources)
        sources->clear();
    // The buttons as they were before the first event: each event flips one.
    std::array<bool, ui::POINTER_BUTTON_COUNT> down = last.buttonDown;
    for (auto e = events.rbegin(); e != events.rend(); ++e)
        if (e->button >= 0 && e->button < ui::POINTER_BUTTON_COUNT)
            down[std::size_t(e->button)] = !e->down;
    for (std::size_t index = 0; index < events.size(); ++index) {
        const ButtonEvent& e = events[index];
        if (e.button < 0 || e.button >= ui::POINTER_BUTTON_COUNT ||
            passes.size() + 1 >= MAX_UI_PASSES)
            continue;
        bool& now = down[std::size_t(e.button)];
        if (now == e.down)
            continue;  // a repeat: nothing changes
        now = e.down;
        // The pass sees the pointer where the event happened, at its time, with nothing else.
        ui::Input pass;
        pass.screenRect = last.screenRect;
        pass.pixelsPerPoint = last.pixelsPerPoint;
        pass.timeS = e.timeS;
        pass.hasPointer = last.hasPointer;
        pass.pointerPos = e.pos;
        pass.buttonDown = down;
        pass.modifiers = last.modifiers;
        passes.push_back(std::move(pass));
        if (sources)
            sources->push_back(index);
    }
    passes.push_back(last);
    // A flood beyond MAX_UI_PASSES leaves the last pass to settle the buttons as they are now.
    return passes;
}

}  // namespace grass::editor
