#include "cli/preset_option.h"

#include "quality/quality_presets.h"

namespace grass::cli {

void addPresetOption(ArgParser& parser, std::string* preset) {
    *preset = "project";
    parser.choice("--preset", {"project", "draft", "balanced", "high", "reference"},
                  "quality preset chosen from the measured speed/accuracy fronts "
                  "(docs/presets.md): sets the physics substep, blade segments, LOD and thinning "
                  "distances, snow map, billboard cross-fade and AO bake cells; project: the "
                  "project's own",
                  preset);
}

void applyPresetOption(const std::string& preset, core::Project& project) {
    if (preset == "project")
        return;
    // ArgParser::choice has already refused any other name.
    if (const auto parsed = core::parseQualityPreset(preset))
        core::applyQuality(core::qualitySettings(*parsed), project);
}

}  // namespace grass::cli
