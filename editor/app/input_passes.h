// One frame's input as the UI sees it (issue 24): the window queues every button event with where
// and when it happened, and the UI runs one pass per event, so a press and its release inside one
// frame are a click and two quick clicks a double-click, judged by the events' times and places,
// however long the frame took (1 fps on a software renderer, a touchpad tap at any rate). The
// last pass also carries the keys, the typed text and the wheel, and is the one drawn.
#pragma once

#include <array>
#include <vector>

#include "ui/context.h"

namespace grass::editor {

// A mouse button going down or up: which (ui::PointerButton's order), where (points) and when
// (seconds on the clock of the frame's timeS; negative: at the frame's time, as scripts say).
struct ButtonEvent {
    int button = 0;
    bool down = false;
    ui::Vec2 pos{0.0f};
    double timeS = 0.0;
    // How much of the frame's typed text came before it (InputState::typed): a key and a click
    // inside one slow frame keep their order.
    std::size_t typedBefore = 0;
    // How many of the frame's InputState::leftPath points came before it.
    std::size_t pathBefore = 0;
    // How many of the frame's key presses (InputState::keys) came before it: a Delete and a
    // click inside one slow frame keep their order too.
    std::size_t keysBefore = 0;
};

// A frame's left-button path keeps at most this many points (GLFW reports a motion event per
// pointer move, ~100–1000 a second): a frame stalled for seconds keeps the start of the path.
inline constexpr std::size_t MAX_LEFT_PATH_POINTS = 4096;

// More events than this in one frame (a stuck button, a flood) are folded into the last pass.
inline constexpr std::size_t MAX_UI_PASSES = 16;

// Where a pass but the last comes from: the event (its index in `events`) and whether the pass
// is that event's or carries the keys and text typed before it (since the event before).
struct PassSource {
    std::size_t event = 0;
    bool keysBefore = false;
    bool operator==(const PassSource&) const = default;
};

// The UI passes for a frame whose final input is `last` (buttons as they are now, the pointer
// where it is now, keys, text, wheel) and whose button events are `events`, in order. With no
// events (or only events that change nothing), one pass: `last`. The keys and text typed before
// an event (ButtonEvent::keysBefore, typedBefore) come in a pass of their own just before the
// event's, with the buttons as they were, so that they reach the field that had the keyboard
// then, not one the event's click gives it to (at a frame a second, "35" typed into a number box
// and a click elsewhere arrive in one frame: the click ended the entry, and the 35 was lost);
// the last pass has the rest. `sources`, when given, receives where each pass but the last
// comes from.
std::vector<ui::Input> uiPasses(const ui::Input& last, const std::vector<ButtonEvent>& events,
                                std::vector<PassSource>* sources = nullptr);

}  // namespace grass::editor
