// grass: the command-line face of the editor. Sub-commands share the editor's code paths
// (ARCHITECTURE.md): what `grass render` draws is what the viewport draws.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "util/nearest_name.h"

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

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        grass::cli::printError("",
                               "missing command: grass render|sim|mesh-info|paint|export|bench|"
                               "tradeoff|presets|soak ... "
                               "(see grass --help)");
        return grass::cli::EXIT_USAGE;
    }
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(HELP, stdout);
        return 0;
    }
    if (args[0] == "--version") {
        std::puts("grass 0.1.0");
        return 0;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    if (command == "render")
        return grass::cli::runRender(args);
    if (command == "sim")
        return grass::cli::runSim(args);
    if (command == "mesh-info")
        return grass::cli::runMeshInfo(args);
    if (command == "paint")
        return grass::cli::runPaint(args);
    if (command == "export")
        return grass::cli::runExport(args);
    if (command == "bench")
        return grass::cli::runBench(args);
    if (command == "tradeoff")
        return grass::cli::runTradeoff(args);
    if (command == "presets")
        return grass::cli::runPresets(args);
    if (command == "soak")
        return grass::cli::runSoak(args);
    if (command.rfind("-", 0) == 0)
        grass::cli::printError("", command + ": unknown option (see grass --help)");
    else {
        const std::vector<std::string> commands = {"render",   "sim",     "mesh-info",
                                                   "paint",    "export",  "bench",
                                                   "tradeoff", "presets", "soak"};
        const std::optional<std::string> meant = grass::core::nearestName(command, commands);
        grass::cli::printError(
            command, "unknown command" + (meant ? "; did you mean " + *meant + "?" : "") +
                         " (commands: render, sim, mesh-info, paint, export, bench, tradeoff, "
                         "presets, soak; see grass --help)");
    }
    return grass::cli::EXIT_USAGE;
}
