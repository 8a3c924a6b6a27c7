// Colour editing: RGB <-> HSV conversion and a colour edit widget (a swatch that opens a picker
// popup with a saturation/value square, a hue bar and R G B / H S V drag values).
//
// All channels are in 0..1; hue is in turns (0..1, 0 = red, 1/3 = green, 2/3 = blue), not
// degrees. The widget edits whatever 0..1 triple it is given; with `linear` set, the triple is
// taken as linear-light and the swatch and picker show it sRGB-encoded, as a display would.
#pragma once

#include <string_view>

#include <glm/glm.hpp>

#include "ui/ui.h"

namespace grass::ui {

// Hue in [0, 1), saturation and value in [0, 1]. Greys (max == min) get hue 0 and black gets
// saturation 0: those components are undefined there.
glm::vec3 rgbToHsv(glm::vec3 rgb);
// Any hue (wrapped into [0, 1)), saturation and value clamped to [0, 1].
glm::vec3 hsvToRgb(glm::vec3 hsv);

// Side of the saturation/value square; the hue bar is as tall, COLOR_HUE_BAR_WIDTH wide.
inline constexpr float COLOR_PICKER_SIZE = 160.0f;
inline constexpr float COLOR_HUE_BAR_WIDTH = 20.0f;

// The picker on its own (what the popup shows), laid out from ui's cursor: the SV square at
// nextItemPos(), the hue bar right of it (item spacing apart), then the drag values below.
// Hue and saturation are remembered under `idSalt` so they survive passing through greys and
// black. Changed when the colour moved.
Response colorPicker(Ui& ui, std::string_view idSalt, glm::vec3& rgb, bool linear = false);

// [swatch] label; a click on the swatch toggles the picker popup below it (closed by Escape or a
// press outside). Changed when the colour moved.
Response colorEdit(Ui& ui, std::string_view label, glm::vec3& rgb, bool linear = false);

}  // namespace grass::ui
