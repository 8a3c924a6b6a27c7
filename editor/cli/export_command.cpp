// grass export: writes a project's grown grass for other runtimes (issue 8): one glTF 2.0 file
// per layer with the blades as EXT_mesh_gpu_instancing instances, or the raw GPU blade buffers
// with a manifest. The work is core's exportProject (core/export/export.h), which the editor's
// File menu shares; this file is the command line around it. Formats: docs/export.md.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.h"
#include "export/export.h"
#include "cli/preset_option.h"
#include "project/project.h"
#include "scene/scene.h"
#include "util/arg_parser.h"

namespace grass::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct ExportArgs {
    std::string project, out, format = "gltf", preset = "project";
    int lod = 0;
};

// An error of core's exportProject names the option by its ExportOptions field; the user
// typed the command-line flag.
Error withFlagNames(Error error) {
    if (error.path == "lod")
        error.path = "--lod";
    else if (error.path == "outDir")
        error.path = "--out";
    return error;
}

}  // namespace

int runExport(const std::vector<std::string>& argv) {
    ExportArgs args;
    ArgParser parser(
        "grass export <project-dir|project.json> --out DIR [--format gltf|raw] [--lod N]",
        "Grows the project's grass and writes it for other runtimes into DIR (created if "
        "missing; files are written under temporary names and renamed into place only when "
        "all are done). gltf: per layer <layer>.gltf + .bin (+ map PNGs): the terrain and every "
        "blade as an EXT_mesh_gpu_instancing instance of a unit blade. raw: per layer the exact "
        "64-byte blade records the renderer uploads, the patch table, the maps as float32, and "
        "manifest.json. Progress goes to stderr. See docs/export.md.");
    parser.positional("project", "a project folder (with project.json) or a project .json file",
                      &args.project, true);
    parser.text("--out", "DIR", "the folder to write into (required)", &args.out);
    parser.text("--format", "gltf|raw", "what to write (default gltf)", &args.format);
    parser.integer("--lod", "gltf only: keep every 2^N-th blade, each 2^N times wider; 0 keeps all",
                   &args.lod, 0, core::MAX_EXPORT_LOD);
    addPresetOption(parser, &args.preset);
    if (auto parsed = parser.parse(argv); !parsed) {
        printError("export", parsed.error().str());
        return EXIT_USAGE;
    }
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    auto format = core::parseExportFormat(args.format);
    if (!format) {
        printError("export", "--format: " + format.error().message);
        return EXIT_USAGE;
    }
    if (args.out.empty()) {
        printError("export",
                   "--out: missing: give the folder to write into, e.g. --out "
                   "exported/" +
                       std::string(core::exportFormatName(*format)));
        return EXIT_USAGE;
    }
    if (*format == core::ExportFormat::Raw && args.lod != 0) {
        printError("export",
                   "--lod: applies to --format gltf only (raw holds every blade "
                   "exactly); leave --lod out");
        return EXIT_USAGE;
    }
    // A file where the folder should be fails now, not after the field is grown.
    std::error_code ec;
    if (std::filesystem::exists(args.out, ec) && !std::filesystem::is_directory(args.out, ec)) {
        printError("export", "--out: " + args.out +
                                 " exists and is not a folder (give a folder "
                                 "to export into)");
        return EXIT_FAILED;
    }

    const auto start = Clock::now();
    auto loaded = core::loadProject(args.project);
    if (!loaded) {
        printError("export", loaded.error().str());
        return EXIT_FAILED;
    }
    applyPresetOption(args.preset, loaded->project);
    core::ExportOptions options;
    options.format = *format;
    options.lod = args.lod;
    options.outDir = args.out;
    if (auto refused = core::refuseExportOverInputs(*loaded, options); !refused) {
        printError("export", withFlagNames(refused.error()).str());
        return EXIT_USAGE;
    }
    std::fprintf(stderr, "note: growing %s ...\n", loaded->file.c_str());
    auto scene = core::buildScene(*loaded);
    if (!scene) {
        printError("export", scene.error().str());
        return EXIT_FAILED;
    }
    for (const auto& note : scene->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    const double growMs = msSince(start);
    std::fprintf(stderr, "note: grown in %.0f ms: %zu blades in %zu layers\n", growMs,
                 scene->totalBlades(), scene->layers.size());

    const auto exportStart = Clock::now();
    auto report =
        core::exportProject(*loaded, *scene, options, [](float fraction, std::string_view stage) {
            std::fprintf(stderr, "note: export %3.0f%%: %.*s\n",
                         static_cast<double>(fraction) * 100.0, static_cast<int>(stage.size()),
                         stage.data());
        });
    if (!report) {
        printError("export", withFlagNames(report.error()).str());
        return EXIT_FAILED;
    }
    const double exportMs = msSince(exportStart);
    for (const auto& layer : report->layers)
        std::printf("layer \"%s\": %zu live blades, %zu %s\n", layer.name.c_str(), layer.liveBlades,
                    layer.instances,
                    *format == core::ExportFormat::Gltf ? "instances" : "blade slots");
    for (const auto& file : report->files)
        std::printf("wrote %s (%llu bytes)\n", file.path.c_str(),
                    static_cast<unsigned long long>(file.bytes));
    std::printf("exported %s (%s, lod %d): %zu files, %llu bytes in %.0f ms (grow %.0f ms)\n",
                loaded->project.name.c_str(), std::string(core::exportFormatName(*format)).c_str(),
                args.lod, report->files.size(),
                static_cast<unsigned long long>(report->totalBytes()), exportMs, growMs);
    return 0;
}

}  // namespace grass::cli
