// `--preset draft|balanced|high|reference` (issue 10): the quality presets chosen from the
// measured fronts (core/quality/quality_presets.h), shared by render, sim and export. The preset
// is applied to the loaded project before anything is built; options given explicitly on the
// same command line (--dt, --lod-distance, --geometry, ...) still win.
#pragma once

#include <string>

#include "project/project.h"
#include "util/arg_parser.h"

namespace grass::cli {

// Registers --preset; `preset` stays "project" when it is not given.
void addPresetOption(ArgParser& parser, std::string* preset);
// Applies the chosen preset to the project ("project": nothing).
void applyPresetOption(const std::string& preset, core::Project& project);

}  // namespace grass::cli
