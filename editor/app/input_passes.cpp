#include "app/input_passes.h"

#include <algorithm>

namespace grass::editor {

namespace {

// The text and keys of `from` typed from `textFrom` to `textTo` and pressed from `keysFrom` to
// `keysTo` into `pass`, each key's place in the text counted from the piece's start; the
// clipboard's text with them when a paste is among the keys.
void takeKeys(const ui::Input& from, std::size_t textFrom, std::size_t textTo, std::size_t keysFrom,
              std::size_t keysTo, ui::Input& pass) {
    pass.text = from.text.substr(textFrom, textTo - textFrom);
    pass.keys.assign(from.keys.begin() + std::ptrdiff_t(keysFrom),
                     from.keys.begin() + std::ptrdiff_t(keysTo));
    pass.clipboardText.clear();
    for (ui::KeyEvent& key : pass.keys) {
        if (key.textBefore != std::string::npos)
            key.textBefore = std::clamp(key.textBefore, textFrom, textTo) - textFrom;
        if (key.key == ui::Key::V && key.modifiers.ctrl)
            pass.clipboardText = from.clipboardText;
    }
}

}  // namespace

std::vector<ui::Input> uiPasses(const ui::Input& last, const std::vector<ButtonEvent>& events,
                                std::vector<PassSource>* sources) {
    std::vector<ui::Input> passes;
    if (sources)
        sources->clear();
    // The buttons as they were before the first event: each event flips one.
    std::array<bool, ui::POINTER_BUTTON_COUNT> down = last.buttonDown;
    for (auto e = events.rbegin(); e != events.rend(); ++e)
        if (e->button >= 0 && e->button < ui::POINTER_BUTTON_COUNT)
            down[std::size_t(e->button)] = !e->down;
    std::size_t textTaken = 0, keysTaken = 0;  // given to the passes so far
    for (std::size_t index = 0; index < events.size(); ++index) {
        const ButtonEvent& e = events[index];
        if (e.button < 0 || e.button >= ui::POINTER_BUTTON_COUNT)
            continue;
        bool& now = down[std::size_t(e.button)];
        if (now == e.down)
            continue;  // a repeat: nothing changes
        const std::size_t textBefore = std::clamp(e.typedBefore, textTaken, last.text.size());
        const std::size_t keysBefore = std::clamp(e.keysBefore, keysTaken, last.keys.size());
        const bool typedFirst = textBefore > textTaken || keysBefore > keysTaken;
        if (passes.size() + (typedFirst ? 2 : 1) >= MAX_UI_PASSES)
            continue;  // a flood: the last pass settles the buttons, and has the keys
        // The pass sees the pointer where the event happened, at its time, with nothing else.
        ui::Input pass;
        pass.screenRect = last.screenRect;
        pass.pixelsPerPoint = last.pixelsPerPoint;
        pass.timeS = e.timeS;
        pass.hasPointer = last.hasPointer;
        pass.pointerPos = e.pos;
        pass.buttonDown = down;  // as before the event
        pass.modifiers = last.modifiers;
        if (typedFirst) {
            ui::Input typed = pass;
            takeKeys(last, textTaken, textBefore, keysTaken, keysBefore, typed);
            textTaken = textBefore;
            keysTaken = keysBefore;
            passes.push_back(std::move(typed));
            if (sources)
                sources->push_back({index, true});
        }
        now = e.down;
        pass.buttonDown = down;
        passes.push_back(std::move(pass));
        if (sources)
            sources->push_back({index, false});
    }
    // A flood beyond MAX_UI_PASSES leaves the last pass to settle the buttons as they are now.
    ui::Input rest = last;
    takeKeys(last, textTaken, last.text.size(), keysTaken, last.keys.size(), rest);
    rest.clipboardText = last.clipboardText;
    passes.push_back(std::move(rest));
    return passes;
}

}  // namespace grass::editor
