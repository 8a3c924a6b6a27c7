// The figures of the editor's status line (blades, physics, pass times, UI time, frame rate) in
// the room the window leaves them: whole figures are left out, least wanted first, instead of the
// line running past the window's edge mid-word (a reduced picture's "moving: …" note and "physics
// behind" cut the UI time and the frame rate off a 1280-point window, or the pass times in half).
// GL-free.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace grass::editor {

struct StatusFigure {
    std::string text;
    int keep = 0;  // a figure with a lower keep is left out first (the later one on a tie)
};

// Between two figures.
inline constexpr std::string_view STATUS_FIGURE_GAP = "   ";

// The figures in their order, joined by STATUS_FIGURE_GAP, with figures left out until the line
// is at most `room` wide as `width` measures it; the figure with the highest keep stays whatever
// the room.
std::string fitStatusFigures(std::vector<StatusFigure> figures, float room,
                             const std::function<float(std::string_view)>& width);

}  // namespace grass::editor
