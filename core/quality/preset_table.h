// The presets as a Markdown table (`grass presets`, docs/presets.md): per knob, the setting each
// preset takes with its measured cost and error, where it was measured, and the bounds.
#pragma once

#include <string>
#include <vector>

#include "quality_presets.h"

namespace grass::core {

std::string presetTableMarkdown(const std::vector<MeasuredKnob>& knobs);

}  // namespace grass::core
