// How long a frame at rest may wait for input. A window at rest (its picture as it was, no input
// since the last frame) sleeps until an event comes; it used to wake every 0.1 s whatever was on
// screen, building and drawing the panels ten times a second for nothing (0.66 s of CPU in 5 s
// of the meadow at rest). What changes on screen without input says when: the panels (a text
// box's caret blinks), the adaptive quality (the full picture after its settle time), the
// autosave, the status bar (its "at rest" after the last moving frames), a running job's
// progress. A job's end wakes the window at once (Window::wake), so a frame at rest otherwise
// waits up to LONGEST_IDLE_WAIT_S: the bound on anything that changes on its own and says
// nothing.
#pragma once

#include <optional>

namespace grass::editor {

inline constexpr double LONGEST_IDLE_WAIT_S = 1.0;
// While a job's progress or running time is on screen (an export's bar, a re-grow's badge).
inline constexpr double PROGRESS_IDLE_WAIT_S = 0.1;
// While the timeline plays a field whose picture stands still: the physics keeps up (two 60 Hz
// steps a frame) and the timeline's clock moves.
inline constexpr double PLAYING_IDLE_WAIT_S = 1.0 / 30.0;

// What will change on screen without input, each in seconds from now (unset: nothing will).
struct RestingFrame {
    std::optional<double> panelsChangeInS;  // ui::Output::repaintAfterS
    std::optional<double> fullPictureInS;   // a reduced picture's settle time ends
    std::optional<double> autosaveInS;      // unsaved changes: the next autosave
    std::optional<double> statusUpdateInS;  // the status bar still shows moving frames' rate
    bool progressShown = false;
    bool playing = false;
};

// Seconds the frame may wait for an event: the soonest of the changes, at most
// LONGEST_IDLE_WAIT_S (PROGRESS_IDLE_WAIT_S with progress shown, PLAYING_IDLE_WAIT_S while
// playing), at least 0.
double idleWaitS(const RestingFrame& frame);

}  // namespace grass::editor
