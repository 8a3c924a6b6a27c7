// grass: the command-line face of the editor. Sub-commands share the editor's code paths
// (ARCHITECTURE.md): what `grass render` draws is what the viewport draws.
#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/commands.h"
#include "util/nearest_name.h"
#include "util/version.h"

namespace {

constexpr const char* HELP = R"(usage: grass <command> [options]

grass grows, simulates and renders grass fields on any mesh.

commands:
  render      render a project (or any glTF mesh) headless to an image
  sim         run a project's physics headless and report its cost and health
  mesh-info   print vertex/triangle counts, area, bounds of a glTF file
  paint       paint a layer's density, soil, light or cut map with brush strokes
  export      write a project's grass as glTF (instanced blades) or raw GPU buffers
  bench       run the standard benchmark set and print per-stage costs (--compare old runs)
  tradeoff    sweep quality knobs against a reference: cost/error table, tradeoff.json, plots
  presets     print the quality presets (--preset of render, sim, export) and their measurements
  soak        run a project's physics for an hour of game time: length drift, NaN, memory, GL leaks

Run 'grass <command> --help' for the options of a command.
The editor window is 'grass-editor'.
)";

// The commands, in the order the help lists them: what runs them, and the names the "missing"
// and "unknown command" messages list.
struct Command {
    std::string_view name;
    int (*run)(const std::vector<std::string>&);
};
constexpr std::array<Command, 9> COMMANDS{{{"render", grass::cli::runRender},
                                           {"sim", grass::cli::runSim},
                                           {"mesh-info", grass::cli::runMeshInfo},
                                           {"paint", grass::cli::runPaint},
                                           {"export", grass::cli::runExport},
                                           {"bench", grass::cli::runBench},
                                           {"tradeoff", grass::cli::runTradeoff},
                                           {"presets", grass::cli::runPresets},
                                           {"soak", grass::cli::runSoak}}};

std::string commandNames(std::string_view separator) {
    std::string names;
    for (const Command& command : COMMANDS)
        names += (names.empty() ? "" : std::string(separator)) + std::string(command.name);
    return names;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        grass::cli::printError(
            "", "missing command: grass " + commandNames("|") + " ... (see grass --help)");
        return grass::cli::EXIT_USAGE;
    }
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(HELP, stdout);
        return 0;
    }
    if (args[0] == "--version") {
        std::printf("grass %s\n", std::string(grass::core::versionText()).c_str());
        return 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    std::vector<std::string_view> names;
    for (const Command& known : COMMANDS) {
        if (known.name == command)
            return known.run(args);
        names.push_back(known.name);
    }
    if (command.rfind("-", 0) == 0) {
        grass::cli::printError("", command + ": unknown option (see grass --help)");
    } else {
        const std::optional<std::string_view> meant = grass::core::closestMatch(command, names);
        grass::cli::printError(command,
                               "unknown command" +
                                   (meant ? "; did you mean " + std::string(*meant) + "?" : "") +
                                   " (commands: " + commandNames(", ") + "; see grass --help)");
    }
    return grass::cli::EXIT_USAGE;
}
