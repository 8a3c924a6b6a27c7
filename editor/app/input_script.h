// Recorded input for the editor (issue 8: `grass-editor --script FILE`): a text file of pointer,
// key and wait commands turned into one InputState per frame, which the Editor uses instead of
// GLFW's, so tests and bug reports replay a session exactly. One command per line, '#' starts a
// comment; coordinates are window coordinates (GLFW's screen coordinates, y down):
//
//   wait N                   N frames with no new input (buttons stay as they are)
//   wait-s S                 no new input for S seconds of wall time (with --wall-clock)
//   phase NAME               frame times from here on are summed up under NAME (--wall-clock)
//   move X Y                 the pointer moves to (X, Y): one frame
//   press [left|right|middle]   / release [...]   one frame each (default left)
//   drag X0 Y0 X1 Y1 N       press at (X0, Y0), move to (X1, Y1) over N frames, release
//   stroke X0 Y0 X1 Y1 N     the same drag as a slow window delivers it: the press comes with
//                            the first frame's motion, the release with the last's (N = 1: a
//                            whole flick inside one frame)
//   strokepath N X0 Y0 X1 Y1 ...   the same through every point, the moves spread over N frames
//                            (N = 1: a curved flick inside one frame)
//   click X Y / doubleclick X Y   one or two left clicks inside one frame (as at a low frame rate)
//   batch N                  the input of the next N frames arrives in one frame (a key and a
//                            click quicker than a slow frame: batch 2, key g, click X Y)
//   hold ctrl|shift|none     modifiers held from now on (hold ctrl+shift for both)
//   key [ctrl+][shift+]NAME  one key press: a letter, digit, [ ], enter, escape, tab, f
//   type TEXT                typed text (the rest of the line)
//   drop PATH                a file dropped on the window (relative to the script's folder)
//   pressure P               pen pressure for what follows, 0…1
//   minimise / restore       the window is minimised from the next frame on / shown again
//   screenshot FILE          save the window after this frame (relative to the script's folder)
//   quit                     stop (also at the end of the script)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "util/result.h"
#include "app/window.h"

namespace grass::editor {

struct ScriptFrame {
    InputState input;
    std::string screenshot;  // empty: none after this frame
    double holdS = 0.0;  // > 0: the frame repeats until this much wall time has passed
    std::string phase;   // the frame times from this frame on are reported under this name
};

// Errors name the file and line: "script.txt:4: drag: expected X0 Y0 X1 Y1 N".
Result<std::vector<ScriptFrame>> parseInputScript(const std::string& text,
                                                  const std::filesystem::path& file);
Result<std::vector<ScriptFrame>> loadInputScript(const std::filesystem::path& file);

}  // namespace grass::editor
