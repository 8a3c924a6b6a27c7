// Screen areas: a top bar and side panels that carve the screen into the UI's areas and a
// central rect left for the app (the 3D viewport), plus movable, resizable windows.
//
// Panels take space in call order within a frame: call topBar first (it spans the full width),
// then sidePanel()s, then centralRect() for what is left. Each is registered as a UI area
// (Output::wantsPointer). Points, y down.
//
// Windows float above the panels. The front window (the one last pressed on) is drawn and hit
// tested in the foreground layer, the others in the panel layer in call order, so the window
// brought to front by a click is on top whatever order the app calls them in. Call windows after
// the panels so that they are drawn over them.
#pragma once

#include <string_view>

#include "ui/ui.h"

namespace grass::ui {

enum class Side { Left, Right };

// Full width across the top of the remaining area, as tall as its content was last frame.
Rect topBar(Context& ctx, std::string_view id, const UiFn& fn);

// A panel along the left or right edge of the remaining area (below the top bar), defaultWidth
// wide until the user drags its inner edge; the width is remembered under `id`. Returns its rect.
Rect sidePanel(Context& ctx, std::string_view id, Side side, float defaultWidth, const UiFn& fn);

// What the top bar and side panels left of the screen this frame.
Rect centralRect(Context& ctx);

// Minimum size a window can be resized to.
inline constexpr Vec2 WINDOW_MIN_SIZE{120.0f, 60.0f};

// A window titled `title` (also its id) at its remembered rect (first shown at `defaultRect`):
// drag the title bar to move it, the bottom-right grip to resize it, the × to close it (sets
// *open = false; a null `open` has no close button). It is kept within the screen. Returns whether
// it is shown (fn ran).
bool window(Context& ctx, std::string_view title, bool* open, const UiFn& fn,
            Rect defaultRect = {{60.0f, 60.0f}, {380.0f, 300.0f}});

// The window's rect as remembered (empty before it was first shown).
Rect windowRect(Context& ctx, std::string_view title);

}  // namespace grass::ui
