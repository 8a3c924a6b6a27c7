// The editor window's first size: the project's render size, made smaller (same shape) when the
// screen's work area cannot hold it. A window larger than the screen hides the status bar and
// the timeline where no window manager constrains it (seen at 800×600 under Xvfb); screenshots
// and scripted sessions keep the exact size, which tests compare against `grass render`.
#pragma once

#include <algorithm>
#include <cmath>

namespace grass::editor {

struct WindowSize {
    int width = 0;
    int height = 0;
    bool operator==(const WindowSize&) const = default;
};

// Room a window's frame takes around its content (title bar, borders), in screen units.
inline constexpr int WINDOW_FRAME_ALLOWANCE = 48;

// `requested` when it fits the work area (areaWidth × areaHeight screen units, less the frame's
// allowance, at `contentScale` pixels per unit: GLFW scales the window to the monitor); else
// scaled down to fit, keeping its shape. An unknown area (≤ 0) changes nothing.
inline WindowSize fitWindowSize(WindowSize requested, int areaWidth, int areaHeight,
                                float contentScale = 1.0f) {
    if (areaWidth <= 0 || areaHeight <= 0 || requested.width <= 0 || requested.height <= 0)
        return requested;
    const float scale = contentScale > 0.0f ? contentScale : 1.0f;
    const float roomWidth = float(areaWidth - WINDOW_FRAME_ALLOWANCE / 4) / scale;
    const float roomHeight = float(areaHeight - WINDOW_FRAME_ALLOWANCE) / scale;
    const float shrink =
        std::min({1.0f, roomWidth / float(requested.width), roomHeight / float(requested.height)});
    if (shrink >= 1.0f)
        return requested;
    return {std::max(1, int(std::floor(float(requested.width) * shrink))),
            std::max(1, int(std::floor(float(requested.height) * shrink)))};
}

// The least size the editor is laid out for, in points: narrower, the side panel took half the
// window and the timeline's speed field ran off its edge (at 700 points); lower, the side
// panel showed a handful of rows.
inline constexpr WindowSize LEAST_WINDOW_POINTS{800, 480};

// The window's size limit for the window system, in screen units: LEAST_WINDOW_POINTS at
// `screenUnitsPerPoint` (the content scale, and on systems whose screen units are points, one),
// but never more than the window as created, so that a window asked smaller (a test's or a
// script's size, a small screen's fitted one) can keep the size it was given.
inline WindowSize leastWindowSize(WindowSize created, float screenUnitsPerPoint) {
    const float scale = screenUnitsPerPoint > 0.0f ? screenUnitsPerPoint : 1.0f;
    return {std::min(created.width, int(std::lround(float(LEAST_WINDOW_POINTS.width) * scale))),
            std::min(created.height, int(std::lround(float(LEAST_WINDOW_POINTS.height) * scale)))};
}

}  // namespace grass::editor
