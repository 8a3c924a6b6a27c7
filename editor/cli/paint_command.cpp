// grass paint: paints a layer's density, soil or light map with brush strokes from the command
// line (issue 6), as the editor's brush does, and re-grows only the grass each stroke can reach,
// so scripts can author maps and the incremental re-growth can be watched and timed.
#include <algorithm>
#include <cctype>
#include <cfloat>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string_view>

#include "cli/commands.h"
#include "edit/scene_paint.h"
#include "maps/brush.h"
#include "maps/map_image.h"
#include "maps/texel_surface.h"
#include "project/project.h"
#include "scene/scene.h"
#include "cli/stroke_text.h"
#include "util/arg_parser.h"

namespace grass::cli {

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

// A stroke of many points reports how far it got at most this often, so a long scripted stroke
// shows it is alive without flooding the output.
constexpr double PROGRESS_INTERVAL_MS = 1000.0;
// Points fed to the brush between progress checks.
constexpr std::size_t PROGRESS_CHUNK_POINTS = 256;
// The default radius as a share of the mesh bounds diagonal: a brush that reads on any mesh
// whatever its units, like the editor's first brush.
constexpr float DEFAULT_RADIUS_SHARE = 0.05f;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct PaintArgs {
    std::string project, map, layer, mode = "add", falloff = "smooth", file;
    std::vector<std::string> strokes;
    double radiusM = 0.0, strength = 0.5, value = 1.0, spacing = 0.25;
    bool uv = false, dryRun = false;
};

// --uv: a point in the map's UV space becomes the surface position of the texel it falls in.
// That texel's centre is the nearest of all texel centres, and a UV on any triangle always
// lands in a covered texel (coverage reaches one texel past each triangle), so an uncovered
// one means the UV is off the mesh.
Result<glm::vec3> surfaceAtUv(const core::TexelSurface& surface, glm::vec2 uv,
                              const std::string& where) {
    char text[96];
    std::snprintf(text, sizeof text, "uv (%g, %g)", static_cast<double>(uv.x),
                  static_cast<double>(uv.y));
    if (uv.x < 0.0f || uv.x > 1.0f || uv.y < 0.0f || uv.y > 1.0f)
        return makeError(
            "--stroke", where + ": " + text + " is not on the mesh (outside [0, 1]², off the map)");
    const int i =
        std::min(static_cast<int>(uv.x * static_cast<float>(surface.width())), surface.width() - 1);
    const int j = std::min(static_cast<int>(uv.y * static_cast<float>(surface.height())),
                           surface.height() - 1);
    const auto texel = static_cast<std::uint32_t>(j * surface.width() + i);
    if (!surface.isCovered(texel))
        return makeError("--stroke", where + ": " + text +
                                         " is not on the mesh (no triangle's UVs "
                                         "reach texel " +
                                         std::to_string(i) + ", " + std::to_string(j) + ")");
    return surface.position(texel);
}

// Distance from a point to a box, 0 inside: how far off the mesh a stroke that touched nothing
// was.
float distanceToBounds(glm::vec3 point, const core::Bounds& bounds) {
    return glm::length(point - glm::clamp(point, bounds.min, bounds.max));
}

std::string boundsText(const core::Bounds& bounds) {
    char text[160];
    std::snprintf(text, sizeof text, "[%.3g %.3g %.3g] .. [%.3g %.3g %.3g]",
                  static_cast<double>(bounds.min.x), static_cast<double>(bounds.min.y),
                  static_cast<double>(bounds.min.z), static_cast<double>(bounds.max.x),
                  static_cast<double>(bounds.max.y), static_cast<double>(bounds.max.z));
    return text;
}

// The formats saveMapImage writes at full precision. Checked before any work, so a typo in
// --file fails at once instead of after the scene is grown.
bool isMapFormat(const fs::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".png" || extension == ".tif" || extension == ".tiff" ||
           extension == ".exr";
}

core::BrushSettings brushSettings(const PaintArgs& args) {
    core::BrushSettings brush;
    brush.mode = args.mode == "add"        ? core::BrushMode::Add
                 : args.mode == "subtract" ? core::BrushMode::Subtract
                 : args.mode == "smooth"   ? core::BrushMode::Smooth
                                           : core::BrushMode::Set;
    brush.falloff = args.falloff == "smooth"   ? core::BrushFalloff::Smooth
                    : args.falloff == "linear" ? core::BrushFalloff::Linear
                                               : core::BrushFalloff::Constant;
    brush.strength = static_cast<float>(args.strength);
    brush.setValue = static_cast<float>(args.value);
    brush.dabSpacing = static_cast<float>(args.spacing);
    brush.radiusM = static_cast<float>(args.radiusM);
    return brush;
}

// Feeds one stroke's points to the painter in chunks, so a stroke of many points can report its
// progress. Returns the dabs it took.
std::size_t feedStroke(core::ScenePainter& painter, const std::vector<glm::vec3>& hits,
                       std::size_t strokeNumber) {
    auto lastReport = Clock::now();
    for (std::size_t start = 0; start < hits.size(); start += PROGRESS_CHUNK_POINTS) {
        const std::size_t count = std::min(PROGRESS_CHUNK_POINTS, hits.size() - start);
        painter.addHits(std::span<const glm::vec3>(hits).subspan(start, count));
        if (msSince(lastReport) > PROGRESS_INTERVAL_MS && start + count < hits.size()) {
            std::printf("  stroke %zu: %zu of %zu points, %zu dabs so far\n", strokeNumber,
                        start + count, hits.size(), painter.dabCount());
            std::fflush(stdout);
            lastReport = Clock::now();
        }
    }
    return painter.dabCount();
}

// Paints the strokes one by one with the editor's brush (core::ScenePainter) into the map the
// layer grows from, and re-grows the patches each stroke can reach right after it, as the
// editor does at the end of a stroke; prints a line per stroke and the total. Returns how many
// texels the whole run changed.
Result<std::size_t> paintAndRegrow(core::ScenePainter& painter, std::size_t layerIndex,
                                   core::LayerMap which, const core::LayerField& field,
                                   const core::MapImage& painted, const core::TexelSurface& surface,
                                   const core::BrushSettings& brush,
                                   const std::vector<std::vector<glm::vec3>>& points) {
    // The value of every texel before its first change, to count the texels the whole run
    // changed (a texel painted by two strokes counts once, one painted back not at all).
    std::vector<std::uint8_t> touched(painted.texels.size(), 0);
    std::vector<std::pair<std::uint32_t, float>> original;
    std::vector<std::uint8_t> regrown(field.patched.patches.size(), 0);
    std::size_t totalDabs = 0;
    double regrowMs = 0.0;
    bool anyTouched = false;
    core::Bounds totalBounds;
    for (std::size_t s = 0; s < points.size(); ++s) {
        painter.begin(layerIndex, which, {painted.width, painted.height}, brush);
        const std::size_t dabs = feedStroke(painter, points[s], s + 1);
        totalDabs += dabs;
        const auto regrowStart = Clock::now();
        auto report = painter.regrowChanged();
        const double strokeMs = msSince(regrowStart);
        const std::optional<core::PaintEdit> edit = painter.end();
        if (!report)
            return report.error();
        if (!edit) {
            float nearestM = std::numeric_limits<float>::infinity();
            for (const glm::vec3 point : points[s])
                nearestM = std::min(nearestM, distanceToBounds(point, surface.bounds()));
            if (nearestM > brush.radiusM)
                std::fprintf(stderr,
                             "warning: stroke %zu touched no texel: its nearest point is %.4g "
                             "from the mesh bounds %s, beyond the radius %.4g (off the mesh?)\n",
                             s + 1, static_cast<double>(nearestM),
                             boundsText(surface.bounds()).c_str(),
                             static_cast<double>(brush.radiusM));
            std::printf("stroke %zu: %zu points, %zu dabs, 0 texels changed%s\n", s + 1,
                        points[s].size(), dabs,
                        nearestM > brush.radiusM ? " (off the mesh)"
                                                 : " (the map already holds what it paints)");
            continue;
        }
        const core::PaintRecord& record = edit->record;
        std::size_t changed = 0;
        for (std::size_t k = 0; k < record.texelIndex.size(); ++k) {
            changed += record.before[k] != record.after[k] ? 1 : 0;
            if (!touched[record.texelIndex[k]]) {
                touched[record.texelIndex[k]] = 1;
                original.emplace_back(record.texelIndex[k], record.before[k]);
            }
        }
        totalBounds = anyTouched ? core::Bounds{glm::min(totalBounds.min, record.touchedBounds.min),
                                                glm::max(totalBounds.max, record.touchedBounds.max)}
                                 : record.touchedBounds;
        anyTouched = true;
        regrowMs += strokeMs;
        for (const std::uint32_t patch : report->patches)
            regrown[patch] = 1;
        std::printf(
            "stroke %zu: %zu points, %zu dabs, %zu texels changed, bounds %s; re-grew %zu "
            "of %zu patches in %.2f ms\n",
            s + 1, points[s].size(), dabs, changed, boundsText(record.touchedBounds).c_str(),
            report->patches.size(), field.patched.patches.size(), strokeMs);
        std::fflush(stdout);
    }
    std::size_t totalChanged = 0;
    for (const auto& [texel, before] : original)
        totalChanged += painted.texels[texel] != before ? 1 : 0;
    const auto regrownCount =
        static_cast<std::size_t>(std::count(regrown.begin(), regrown.end(), std::uint8_t{1}));
    std::printf(
        "total: %zu strokes, %zu dabs, %zu texels changed, bounds %s; re-grew %zu of %zu "
        "patches in %.2f ms\n",
        points.size(), totalDabs, totalChanged,
        anyTouched ? boundsText(totalBounds).c_str() : "(none)", regrownCount,
        field.patched.patches.size(), regrowMs);
    return totalChanged;
}

}  // namespace

int runPaint(const std::vector<std::string>& argv) {
    PaintArgs args;
    // --stroke repeats, so takeStrokes reads it; the parser lists it for --help only.
    std::string strokeForHelp;
    ArgParser parser(
        "grass paint <project-dir|project.json> --map density|soil|light --stroke \"x,y,z; ...\" "
        "[--stroke ...] [options]",
        "Paints one map of a layer (density, or soil / light of the growth model, SPEC §9) with "
        "brush strokes across the mesh surface, as the editor's brush does, and saves it "
        "atomically. A layer without that map gets a new one (map_resolution, 1 everywhere, "
        "16-bit PNG) and project.json is updated to name it; nothing else in the project "
        "changes. Prints per stroke the dabs, the texels changed, the touched bounds and the "
        "grass patches re-grown (and how long that took); for density also the live blades.");
    parser.positional("project", "a project folder (with project.json) or a project .json file",
                      &args.project, true);
    parser.text("--map", "density|soil|light", "which of the layer's maps to paint (required)",
                &args.map);
    parser.text("--stroke", "\"x,y,z; x,y,z; ...\"",
                "one stroke: surface hits in world units, separated by ';'; repeat for more "
                "strokes (at least one)",
                &strokeForHelp);
    parser.text("--layer", "NAME", "which layer (default: the first)", &args.layer);
    parser.flag("--uv",
                "stroke points are \"u,v\" in the map's UV space, placed on the surface at the "
                "texel they fall in (error if that is off the mesh)",
                &args.uv);
    parser.choice("--mode", {"add", "subtract", "smooth", "set"},
                  "add or subtract the brush weight, smooth toward the neighbours, or set toward "
                  "--value",
                  &args.mode);
    // A micrometre at least: a brush of radius 0 paints nothing.
    parser.number("--radius", "M", "brush radius in world units", &args.radiusM, 1e-6, 1e9,
                  "5 % of the mesh bounds diagonal");
    parser.number("--strength", "S", "weight of one dab at its centre", &args.strength, 0.0, 1.0,
                  "0.5");
    parser.choice("--falloff", {"smooth", "linear", "constant"},
                  "weight across a dab: 1 − smoothstep, a cone, or a hard disc", &args.falloff);
    parser.number("--value", "V", "the value --mode set paints toward", &args.value, 0.0, 1.0, "1");
    parser.number("--spacing", "F", "distance between dabs as a fraction of the radius",
                  &args.spacing, 0.05, 2.0, "0.25");
    parser.text("--file", "RELPATH",
                "where to save the map, relative to the project folder, and name it in "
                "project.json (default: the layer's file, else maps/<layer>-<map>.png)",
                &args.file);
    parser.flag("--dry-run", "paint and report, but write nothing", &args.dryRun);

    std::vector<std::string> rest = argv;
    auto strokes = takeStrokes(rest);
    if (!strokes) {
        printError("paint", strokes.error().str());
        return EXIT_USAGE;
    }
    if (auto parsed = parser.parse(rest); !parsed) {
        printError("paint", parsed.error().str());
        return EXIT_USAGE;
    }
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    args.strokes = std::move(*strokes);

    // Everything the command line alone can refute is refuted before any file is read.
    core::LayerMap which = core::LayerMap::Density;
    if (args.map == "soil")
        which = core::LayerMap::Soil;
    else if (args.map == "light")
        which = core::LayerMap::Light;
    else if (args.map != "density") {
        printError("paint", args.map.empty()
                                ? "--map: missing: give --map density, soil or light"
                                : "--map: expected density, soil or light, got '" + args.map + "'");
        return EXIT_USAGE;
    }
    if (args.strokes.empty()) {
        printError("paint", "--stroke: missing: give at least one --stroke \"x,y,z; x,y,z\"");
        return EXIT_USAGE;
    }
    std::vector<std::vector<glm::vec3>> points;
    for (std::size_t s = 0; s < args.strokes.size(); ++s) {
        auto stroke = parseStroke(args.strokes[s], s + 1, args.uv ? 2 : 3);
        if (!stroke) {
            printError("paint", stroke.error().str());
            return EXIT_USAGE;
        }
        points.push_back(std::move(*stroke));
    }

    auto loaded = core::loadProject(args.project);
    if (!loaded) {
        printError("paint", loaded.error().str());
        return EXIT_FAILED;
    }
    core::Project& project = loaded->project;
    if (project.layers.empty()) {
        printError("paint", loaded->file.string() + ": the project has no layers to paint");
        return EXIT_FAILED;
    }
    std::size_t layerIndex = 0;
    if (!args.layer.empty()) {
        const auto found =
            std::find_if(project.layers.begin(), project.layers.end(),
                         [&](const core::GrassLayer& layer) { return layer.name == args.layer; });
        if (found == project.layers.end()) {
            std::string names;
            for (const auto& layer : project.layers)
                names += (names.empty() ? "" : ", ") + layer.name;
            printError("paint",
                       "--layer: no layer named \"" + args.layer + "\" (layers: " + names + ")");
            return EXIT_USAGE;
        }
        layerIndex = static_cast<std::size_t>(found - project.layers.begin());
    }
    core::GrassLayer& layer = project.layers[layerIndex];
    std::string& mapField = which == core::LayerMap::Density ? layer.densityMap
                            : which == core::LayerMap::Soil  ? layer.soilMap
                                                             : layer.lightMap;
    const std::string fieldPointer =
        "/layers/" + std::to_string(layerIndex) + "/" + args.map + "_map";

    // Where the painted map goes: --file, else the layer's own file, else a new default one.
    const std::string targetText = !args.file.empty()  ? args.file
                                   : !mapField.empty() ? mapField
                                                       : core::defaultMapFile(layer.name, args.map);
    auto target = core::resolveAssetPath(loaded->folder, targetText, "--file");
    if (!target) {
        printError("paint", target.error().str());
        return EXIT_USAGE;
    }
    if (!isMapFormat(*target)) {
        printError("paint",
                   "--file: cannot save a map as " + targetText + " (use .png, .tif or .exr)");
        return EXIT_USAGE;
    }
    const std::string targetRelative = fs::path(targetText).lexically_normal().generic_string();

    const glm::ivec2 size = layer.mapResolution;
    core::MapImage map;
    std::vector<std::string> printedNotes;
    if (!mapField.empty()) {
        auto source = core::resolveAssetPath(loaded->folder, mapField, fieldPointer);
        if (!source) {
            printError("paint", loaded->file.string() + ": " + source.error().str());
            return EXIT_FAILED;
        }
        auto read = core::loadMapImageAt(*source, size.x, size.y);
        if (!read) {
            printError("paint", read.error().str());
            return EXIT_FAILED;
        }
        map = std::move(*read);
        for (const auto& warning : map.warnings) {
            printedNotes.push_back(source->string() + ": " + warning);
            std::fprintf(stderr, "note: %s\n", printedNotes.back().c_str());
        }
        std::printf("%s map of layer \"%s\": loaded %s at %dx%d\n", args.map.c_str(),
                    layer.name.c_str(), mapField.c_str(), size.x, size.y);
    } else {
        // An absent map reads 1 everywhere: the new one starts as what the grass already saw.
        map = core::makeConstantMap(size.x, size.y, 1.0f);
        std::printf("%s map of layer \"%s\": new, %dx%d, 1 everywhere\n", args.map.c_str(),
                    layer.name.c_str(), size.x, size.y);
    }

    // The mesh first: --uv points and the default radius need the surface, and a bad UV should
    // fail before the (possibly long) growing of the field.
    const auto buildStart = Clock::now();
    std::vector<std::string> notes;
    auto mesh = core::loadProjectMesh(*loaded, &notes);
    if (!mesh) {
        printError("paint", mesh.error().str());
        return EXIT_FAILED;
    }
    auto ownSurface = std::make_unique<core::TexelSurface>(*mesh, size.x, size.y);
    const core::TexelSurface& surface = *ownSurface;
    if (args.uv)
        for (std::size_t s = 0; s < points.size(); ++s)
            for (std::size_t p = 0; p < points[s].size(); ++p) {
                const std::string where =
                    "stroke " + std::to_string(s + 1) + ", point " + std::to_string(p + 1);
                auto onSurface = surfaceAtUv(surface, glm::vec2(points[s][p]), where);
                if (!onSurface) {
                    printError("paint", onSurface.error().str());
                    return EXIT_USAGE;
                }
                points[s][p] = *onSurface;
            }
    core::BrushSettings brush = brushSettings(args);
    if (!parser.given("--radius"))
        brush.radiusM = DEFAULT_RADIUS_SHARE * glm::length(core::meshBounds(*mesh).size());

    std::printf("growing layer \"%s\" of %s ...\n", layer.name.c_str(), loaded->file.c_str());
    std::fflush(stdout);
    auto built = core::buildSceneFromMesh(*loaded, std::move(*mesh), std::move(notes));
    if (!built) {
        printError("paint", built.error().str());
        return EXIT_FAILED;
    }
    core::Scene& scene = *built;
    for (const auto& note : scene.notes)
        if (std::find(printedNotes.begin(), printedNotes.end(), note) == printedNotes.end())
            std::fprintf(stderr, "note: %s\n", note.c_str());
    core::LayerField& field = scene.layers[layerIndex];
    // buildScene says this only for maps the layer already names; a new one deserves it too.
    if (which != core::LayerMap::Density && !layer.growth.enabled)
        std::fprintf(stderr,
                     "note: layer \"%s\": the %s map takes effect only with "
                     "growth.enabled = true\n",
                     layer.name.c_str(), args.map.c_str());
    std::printf(
        "  built in %.1f ms: %zu live blades in %zu patches; map %dx%d, %zu texels on the "
        "mesh\n",
        msSince(buildStart), field.liveBlades, field.patched.patches.size(), size.x, size.y,
        surface.coveredCount());

    // Paint straight into the map the field grows from, so each re-growth sees every stroke so
    // far without copying the map.
    core::MapImage& painted = core::layerMap(field.source.maps, which);
    painted = std::move(map);

    char setValue[48] = "";
    if (brush.mode == core::BrushMode::Set)
        std::snprintf(setValue, sizeof setValue, ", value %.3g", args.value);
    std::printf("  brush %s, radius %.4g, strength %.3g, falloff %s, spacing %.3g%s\n",
                args.mode.c_str(), static_cast<double>(brush.radiusM), args.strength,
                args.falloff.c_str(), args.spacing, setValue);

    const std::size_t liveBefore = field.liveBlades;
    // The editor's brush on the grown scene, with the texel surface already built above.
    core::ScenePainter painter(scene, project.lighting);
    painter.adoptSurface(std::move(ownSurface));
    auto totals =
        paintAndRegrow(painter, layerIndex, which, field, painted, surface, brush, points);
    if (!totals) {
        printError("paint", totals.error().str());
        return EXIT_FAILED;
    }
    const std::size_t totalChanged = *totals;
    if (which == core::LayerMap::Density)
        std::printf("live blades %zu -> %zu\n", liveBefore, field.liveBlades);

    // Nothing to keep: leave the project as it was rather than save a map equal to what the
    // grass already read (and name a new constant map in project.json).
    if (totalChanged == 0) {
        std::printf("no texel changed: nothing written\n");
        return 0;
    }
    if (args.dryRun) {
        std::printf("dry run: nothing written (would save %s)\n", target->c_str());
        return 0;
    }
    // saveMapImage wants the folder to exist; a new default map brings its maps/ folder.
    std::error_code ec;
    const fs::path folder = target->parent_path();
    const bool madeFolder =
        !folder.empty() && !fs::exists(folder, ec) && fs::create_directories(folder, ec);
    if (auto saved = core::saveMapImage(painted, *target); !saved) {
        if (madeFolder)
            fs::remove(folder, ec);
        printError("paint", saved.error().str());
        return EXIT_FAILED;
    }
    std::printf("wrote %s (%dx%d)\n", target->c_str(), painted.width, painted.height);
    if (mapField != targetRelative) {
        mapField = targetRelative;
        if (auto saved = core::saveProject(project, loaded->file); !saved) {
            printError("paint", saved.error().str());
            return EXIT_FAILED;
        }
        std::printf("updated %s: layer \"%s\" %s_map = \"%s\"\n", loaded->file.c_str(),
                    layer.name.c_str(), args.map.c_str(), targetRelative.c_str());
    }
    return 0;
}

}  // namespace grass::cli
