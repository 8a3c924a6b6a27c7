// grass presets: the quality presets and the measurements they were chosen from (issue 10).
#include <cstdio>

#include "cli/commands.h"
#include "cli/parse_arguments.h"
#include "quality/preset_table.h"
#include "quality/quality_presets.h"
#include "util/arg_parser.h"

namespace grass::cli {

int runPresets(const std::vector<std::string>& argv) {
    ArgParser parser(
        "grass presets",
        "Prints the quality presets draft, balanced, high and reference as a Markdown table: "
        "for every knob the setting each preset takes, with the frame (or physics) cost and the "
        "error `grass tradeoff` measured for it, the error bounds the presets were chosen by, "
        "and the device. The measurements are built in (core/quality/measured/*.json); "
        "render, sim and export take --preset NAME, the editor's Render section a preset menu.");
    if (const auto exitCode = parseArguments(parser, argv, "presets"))
        return *exitCode;
    std::fputs(core::presetTableMarkdown(core::builtInMeasurements()).c_str(), stdout);
    return 0;
}

}  // namespace grass::cli
