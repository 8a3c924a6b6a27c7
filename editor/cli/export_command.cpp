// grass export: writes a project's grown grass for other runtimes (issue 8): one glTF 2.0 file
// per layer with the blades as EXT_mesh_gpu_instancing instances, or the raw GPU blade buffers
// with a manifest. The work is core's exportProject (core/export/export.h), which the editor's
// File menu shares; this file is the command line around it. Formats: docs/export.md.
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "cli/parse_arguments.h"
#include "cli/preset_option.h"
#include "export/export.h"
#include "project/project.h"
#include "scene/scene.h"
#include "tools/ms_since.h"
#include "util/arg_parser.h"
#include "util/interrupt_stop.h"

namespace grass::cli {

namespace {

using tools::Clock;
using tools::msSince;

struct ExportArgs {
    std::string project, out, format = "gltf", preset = "project";
    int lod = 0;
};

// The grown field and how long growing it took.
struct GrownScene {
    core::Scene scene;
    double growMs = 0.0;
};

std::optional<int> parseExportArgs(const std::vector<std::string>& argv, ExportArgs& args) {
    ArgParser parser(
        "grass export <project-dir|project.json> --out DIR [--format gltf|raw|glb|mesh] [--lod N]",
        "Grows the project's grass and writes it for other runtimes into DIR (created if "
        "missing; files are written under temporary names and renamed into place only when "
        "all are done). gltf: per layer <layer>.gltf + .bin (+ map PNGs): the terrain and every "
        "blade as an EXT_mesh_gpu_instancing instance of a pre-bent unit blade, split into cells. "
        "glb: every layer in one <project>.glb with one shared terrain and the maps embedded. "
        "mesh: like glb, the blades baked into plain meshes (<project>-merged.glb) for viewers "
        "without EXT_mesh_gpu_instancing. "
        "raw: per layer the exact "
        "64-byte blade records the renderer uploads, the patch table, the maps as float32, and "
        "manifest.json. Progress goes to stderr. Ctrl+C stops it at its next stage with the "
        "folder as it was (exit 130); a second Ctrl+C ends it at once. See docs/export.md.");
    addProjectArgument(parser, &args.project, true);
    parser.text("--out", "DIR", "the folder to write into (required)", &args.out);
    parser.text("--format", "gltf|raw|glb|mesh", "what to write (default gltf)", &args.format);
    parser.integer("--lod", "not raw: keep every 2^N-th blade, each 2^N times wider; 0 keeps all",
                   &args.lod, 0, core::MAX_EXPORT_LOD);
    addPresetOption(parser, &args.preset);
    return parseArguments(parser, argv, "export");
}

// Everything the command line alone can refute; returns the format it names.
Result<core::ExportFormat> checkArgs(const ExportArgs& args) {
    auto format = core::parseExportFormat(args.format);
    if (!format)
        return makeError("--format", format.error().message);
    if (args.out.empty())
        return makeError("--out",
                         "missing: give the folder to write into, e.g. --out "
                         "exported/" +
                             std::string(core::exportFormatName(*format)));
    if (*format == core::ExportFormat::Raw && args.lod != 0)
        return makeError("--lod",
                         "applies to --format gltf, glb and mesh only (raw holds every blade "
                         "exactly); leave --lod out");
    return *format;
}

// A file where the folder should be fails now, not after the field is grown.
Result<void> checkOutFolder(const ExportArgs& args) {
    std::error_code ec;
    if (std::filesystem::exists(args.out, ec) && !std::filesystem::is_directory(args.out, ec))
        return makeError("--out", args.out +
                                      " exists and is not a folder (give a folder "
                                      "to export into)");
    return {};
}

// An error of core's exportProject names the option by its ExportOptions field; the user
// typed the command-line flag.
Error withFlagNames(Error error) {
    if (error.path == "lod")
        error.path = "--lod";
    else if (error.path == "outDir")
        error.path = "--out";
    return error;
}

core::ExportOptions exportOptions(const ExportArgs& args, core::ExportFormat format,
                                  std::stop_token stop) {
    core::ExportOptions options;
    options.format = format;
    options.lod = args.lod;
    options.outDir = args.out;
    options.stop = std::move(stop);
    return options;
}

// Grows the field, with its notes and the time it took on stderr; `start` is when the project
// began to load.
Result<GrownScene> growScene(const core::LoadedProject& loaded, Clock::time_point start,
                             std::stop_token stop) {
    std::fprintf(stderr, "note: growing %s ...\n", loaded.file.c_str());
    auto scene = core::buildScene(loaded, nullptr, std::move(stop), buildProgressNotes());
    if (!scene)
        return scene.error();
    printNotes(scene->notes);
    const double growMs = msSince(start);
    std::fprintf(stderr, "note: grown in %.0f ms: %zu blades in %zu layers\n", growMs,
                 scene->totalBlades(), scene->layers.size());
    return GrownScene{std::move(*scene), growMs};
}

Result<core::ExportReport> exportWithProgress(const core::LoadedProject& loaded,
                                              const core::Scene& scene,
                                              const core::ExportOptions& options) {
    return core::exportProject(loaded, scene, options, [](float fraction, std::string_view stage) {
        std::fprintf(stderr, "note: export %3.0f%%: %.*s\n", static_cast<double>(fraction) * 100.0,
                     static_cast<int>(stage.size()), stage.data());
    });
}

void printExportReport(const core::LoadedProject& loaded, const core::ExportOptions& options,
                       const core::ExportReport& report, double exportMs, double growMs) {
    printNotes(report.notes);
    for (const auto& layer : report.layers)
        std::printf("layer \"%s\": %zu live blades, %zu %s\n", layer.name.c_str(), layer.liveBlades,
                    layer.instances,
                    options.format != core::ExportFormat::Raw ? "instances" : "blade slots");
    for (const auto& file : report.files)
        std::printf("wrote %s (%llu bytes)\n", file.path.c_str(),
                    static_cast<unsigned long long>(file.bytes));
    std::printf("exported %s (%s, lod %d): %zu files, %llu bytes in %.0f ms (grow %.0f ms)\n",
                loaded.project.name.c_str(),
                std::string(core::exportFormatName(options.format)).c_str(), options.lod,
                report.files.size(), static_cast<unsigned long long>(report.totalBytes()), exportMs,
                growMs);
}

}  // namespace

int runExport(const std::vector<std::string>& argv) {
    ExportArgs args;
    if (const auto exitCode = parseExportArgs(argv, args))
        return *exitCode;
    const auto format = checkArgs(args);
    if (!format)
        return reportFailure("export", format.error(), EXIT_USAGE);
    if (auto folder = checkOutFolder(args); !folder)
        return reportFailure("export", folder.error(), EXIT_FAILED);

    const auto start = Clock::now();
    // From here Ctrl+C stops the growing or the export at its next stage (interrupt_stop.h).
    const core::InterruptStop interrupt;
    const auto failed = [&](const Error& error) {
        return reportFailure("export", withFlagNames(error), interrupt.exitCodeOr(EXIT_FAILED));
    };
    auto loaded = core::loadProject(args.project);
    if (!loaded)
        return reportFailure("export", loaded.error(), EXIT_FAILED);
    applyPresetOption(args.preset, loaded->project);
    const core::ExportOptions options = exportOptions(args, *format, interrupt.token());
    if (auto refused = core::refuseExportOverInputs(*loaded, options); !refused)
        return reportFailure("export", withFlagNames(refused.error()), EXIT_USAGE);
    auto grown = growScene(*loaded, start, interrupt.token());
    if (!grown)
        return failed(grown.error());

    const auto exportStart = Clock::now();
    auto report = exportWithProgress(*loaded, grown->scene, options);
    if (!report)
        return failed(report.error());
    printExportReport(*loaded, options, *report, msSince(exportStart), grown->growMs);
    return 0;
}

}  // namespace grass::cli
