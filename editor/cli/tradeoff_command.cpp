// grass tradeoff: sweep a project's quality knobs against a high-quality reference and write the
// cost/error table, tradeoff.json and one gnuplot plot per knob (issue 10, SPEC §13).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "cli/commands.h"
#include "cli/parse_arguments.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "tools/tradeoff_plot.h"
#include "tools/tradeoff_report.h"
#include "tools/tradeoff_sweep.h"
#include "util/arg_parser.h"
#include "util/atomic_file.h"
#include "util/interrupt_stop.h"

namespace grass::cli {

namespace {

std::vector<std::string> splitKnobs(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ','))
        if (!item.empty())
            out.push_back(item);
    return out;
}

struct TradeoffArgs {
    std::string project, knobs, out = "tradeoff", camera, technique = "project", replotDir;
    int width = 1280, height = 720, frames = 5;
    std::string msaa = "4";
    double sceneTimeS = 1.0, physicsSeconds = 2.0;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
    bool knobsGiven = false;
};

std::optional<int> parseTradeoffArgs(const std::vector<std::string>& argv, TradeoffArgs& args) {
    const std::string allKnobs = render::tradeoffKnobList();
    ArgParser parser(
        "grass tradeoff <project-dir|project.json> [--knobs K1,K2,...] [--out DIR]",
        "Sweeps the project's quality knobs (" + allKnobs +
            ") from cheap to expensive and measures, per setting, the frame cost (wall clock to "
            "glFinish, median and min–max of the timed frames, and the GL timer of each stage) "
            "and the error against a high-quality reference of the same scene at the same time: "
            "mean CIELAB ΔE76 over the pixels the feature touches (images) or the tips' "
            "trajectory error in blade heights (physics step). Knobs the project does not use "
            "(snow off, no billboards) are skipped with a note. Writes DIR/tradeoff.json, "
            "DIR/tradeoff.md and per knob DIR/<knob>.png (gnuplot; .gp and .dat next to it), "
            "each marking the settings the quality presets' rule would choose from this run. "
            "Ctrl+C ends the sweep after the knob under way and writes the knobs measured (exit "
            "130).");
    addProjectArgument(parser, &args.project, false);
    parser.text("--replot", "DIR",
                "no measuring: write DIR/tradeoff.md and the plots again from DIR/tradeoff.json",
                &args.replotDir);
    parser.text("--knobs", "K1,K2", "the knobs to sweep (default: all of " + allKnobs + ")",
                &args.knobs);
    parser.text("--out", "DIR", "output folder (default: tradeoff)", &args.out);
    parser.integer("--width", "frame width in pixels (default 1280)", &args.width, 16, 8192);
    parser.integer("--height", "frame height in pixels (default 720)", &args.height, 16, 8192);
    parser.integer("--frames", "timed frames per setting, after one warm-up", &args.frames, 1, 100);
    // The sample counts render and bench take (GL rounds others up to what the driver has).
    parser.choice("--msaa", {"1", "2", "4", "8"}, "samples per pixel", &args.msaa);
    parser.text("--camera", "NAME", "which of the project's cameras (default: the first)",
                &args.camera);
    parser.choice("--technique", {"project", "blades", "billboards", "hybrid", "growth"},
                  "draw the grass this way instead of the project's technique (hybrid measures "
                  "billboard_fade on a project that has no billboards)",
                  &args.technique);
    parser.number("--time", "S", "scene time of the images (the project's physics runs to it)",
                  &args.sceneTimeS, 0.0, 3600.0, "1");
    parser.number("--physics-seconds", "S", "simulated span of the physics-step sweep",
                  &args.physicsSeconds, 0.1, 600.0, "2");
    parser.flag("--gl-debug", "print GL debug output", &args.glDebug);
    if (const auto exitCode = parseArguments(parser, argv, "tradeoff"))
        return exitCode;
    args.knobsGiven = parser.given("--knobs");
    return std::nullopt;
}

// --knobs: the knobs it names, each one we know; none given: every knob.
Result<std::vector<std::string>> chosenKnobs(const TradeoffArgs& args) {
    const std::vector<std::string> knobs = splitKnobs(args.knobs);
    const std::vector<std::string> known = render::tradeoffKnobNames();
    for (const std::string& knob : knobs)
        if (std::find(known.begin(), known.end(), knob) == known.end())
            return makeError("--knobs", "unknown knob \"" + knob +
                                            "\" (knobs: " + render::tradeoffKnobList() + ")");
    if (args.knobsGiven && knobs.empty())
        return makeError("--knobs", "no knob named (knobs: " + render::tradeoffKnobList() + ")");
    return knobs;
}

// The output folder is made now (when tradeoff.json cannot be written there yet), so a bad
// --out fails before the sweep.
Result<void> prepareOutFolder(const std::string& out) {
    if (auto writable = checkFileWritable(std::filesystem::path(out) / "tradeoff.json",
                                          "tradeoff/tradeoff.json");
        !writable) {
        std::error_code error;
        std::filesystem::create_directories(out, error);
        if (error)
            return makeError("--out", out + ": " + error.message());
    }
    return {};
}

render::TradeoffOptions sweepOptions(const TradeoffArgs& args, std::vector<std::string> knobs) {
    render::TradeoffOptions options;
    options.knobs = std::move(knobs);
    options.width = args.width;
    options.height = args.height;
    options.frames = args.frames;
    options.msaaSamples = std::stoi(args.msaa);
    options.camera = args.camera;
    options.sceneTimeS = static_cast<float>(args.sceneTimeS);
    options.physicsSeconds = args.physicsSeconds;
    options.progress = [](const std::string& line) {
        std::fprintf(stderr, "%s\n", line.c_str());
        std::fflush(stderr);
    };
    return options;
}

// tradeoff.json, tradeoff.md and the plots into `folder`; prints the table and what it wrote.
int writeOutputs(const render::TradeoffReport& report, const std::filesystem::path& folder,
                 bool writeJson) {
    const std::string table = render::tradeoffTable(report);
    std::fputs(table.c_str(), stdout);
    if (writeJson)
        if (auto written = writeFileAtomic(folder / "tradeoff.json",
                                           render::tradeoffJson(report).dump(2) + "\n");
            !written)
            return reportFailure("tradeoff", written.error(), EXIT_FAILED);
    if (auto written = writeFileAtomic(folder / "tradeoff.md", table); !written)
        return reportFailure("tradeoff", written.error(), EXIT_FAILED);
    auto plots = render::writeTradeoffPlots(report, folder);
    if (!plots)
        return reportFailure("tradeoff", plots.error(), EXIT_FAILED);
    if (!plots->warning.empty())
        std::fprintf(stderr, "grass tradeoff: warning: %s\n", plots->warning.c_str());
    std::printf("wrote %s/%stradeoff.md and %zu plot files\n", folder.string().c_str(),
                writeJson ? "tradeoff.json, " : "", plots->written.size());
    return 0;
}

// --replot DIR: tables and plots again from DIR/tradeoff.json, nothing measured.
int replot(const std::string& folder) {
    const std::filesystem::path file = std::filesystem::path(folder) / "tradeoff.json";
    auto text = readFile(file, MAX_JSON_FILE_BYTES);
    if (!text)
        return reportFailure("tradeoff", makeError("--replot", text.error().str()), EXIT_FAILED);
    auto report = render::tradeoffFromJson(*text, file.string());
    if (!report)
        return reportFailure("tradeoff", report.error(), EXIT_FAILED);
    return writeOutputs(*report, folder, false);
}

// Loads the project and sweeps it on a headless context.
Result<render::TradeoffReport> measureTradeoff(const TradeoffArgs& args,
                                               const render::TradeoffOptions& options) {
    auto loaded = core::loadProject(args.project);
    if (!loaded)
        return loaded.error();
    if (args.technique != "project")
        if (auto chosen = core::parseGrassTechnique(args.technique))
            loaded->project.render.technique = *chosen;
    auto context = gl::HeadlessContext::create(args.glDebug);
    if (!context)
        return context.error();
    return render::runTradeoffSweep(*loaded, options);
}

}  // namespace

int runTradeoff(const std::vector<std::string>& argv) {
    TradeoffArgs args;
    if (const auto exitCode = parseTradeoffArgs(argv, args))
        return *exitCode;
    if (!args.replotDir.empty())
        return replot(args.replotDir);
    if (args.project.empty()) {
        printError("tradeoff", "missing the project to measure (or --replot DIR)");
        return EXIT_USAGE;
    }
    auto knobs = chosenKnobs(args);
    if (!knobs)
        return reportFailure("tradeoff", knobs.error(), EXIT_USAGE);
    if (auto folder = prepareOutFolder(args.out); !folder)
        return reportFailure("tradeoff", folder.error(), EXIT_USAGE);

    // Ctrl+C ends the sweep after the knob under way; the knobs measured are written.
    const core::InterruptStop interrupt;
    render::TradeoffOptions options = sweepOptions(args, std::move(*knobs));
    options.stop = interrupt.token();
    auto report = measureTradeoff(args, options);
    if (!report)
        return reportFailure("tradeoff", report.error(), EXIT_FAILED);
    const int written = writeOutputs(*report, args.out, true);
    return written == 0 ? interrupt.exitCodeOr(0) : written;
}

}  // namespace grass::cli
