// grass paint: paints a layer's density, soil or light map with brush strokes from the command
// line (issue 6), as the editor's brush does, and re-grows only the grass each stroke can reach,
// so scripts can author maps and the incremental re-growth can be watched and timed.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "cli/paint_options.h"
#include "cli/paint_regrow.h"
#include "edit/scene_paint.h"
#include "maps/brush.h"
#include "maps/map_image.h"
#include "maps/texel_surface.h"
#include "project/project.h"
#include "scene/scene.h"
#include "tools/ms_since.h"
#include "util/file_extension.h"

namespace grass::cli {

namespace {

using tools::Clock;
using tools::msSince;
namespace fs = std::filesystem;

// The default radius as a share of the mesh bounds diagonal: a brush that reads on any mesh
// whatever its units, like the editor's first brush.
constexpr float DEFAULT_RADIUS_SHARE = 0.05f;

// The map the command paints and where it is saved.
struct PaintTarget {
    std::size_t layerIndex = 0;
    core::LayerMap which = core::LayerMap::Density;
    fs::path file;         // resolved: where the painted map is saved
    std::string relative;  // how project.json names it
};

// The mesh with the texel positions of the map on it, built before the field: --uv points and
// the default radius need them.
struct PaintSurface {
    core::MovableSurfaceMesh mesh;
    core::PaintUvs uvs;  // a generated atlas is kept with the map painted in it
    std::vector<std::string> notes;
    glm::dvec3 groundOrigin{0.0};  // Scene::groundOrigin
    std::unique_ptr<core::TexelSurface> texels;
};

// The formats saveMapImage writes at full precision. Checked before any work, so a typo in
// --file fails at once instead of after the scene is grown.
bool isMapFormat(const fs::path& file) {
    const std::string extension = lowerExtension(file);
    return extension == ".png" || extension == ".tif" || extension == ".tiff" ||
           extension == ".exr";
}

// The layer's field that names the map's file (empty: the layer has no such map); const or not
// as the layer is.
template <class Layer>
auto& mapFileOf(Layer& layer, core::LayerMap which) {
    return which == core::LayerMap::Density ? layer.densityMap
           : which == core::LayerMap::Soil  ? layer.soilMap
           : which == core::LayerMap::Light ? layer.lightMap
                                            : layer.cutMap;
}

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

// Every --uv point placed on the surface, in place.
Result<void> placeUvPoints(const core::TexelSurface& surface,
                           std::vector<std::vector<glm::vec3>>& points) {
    for (std::size_t s = 0; s < points.size(); ++s)
        for (std::size_t p = 0; p < points[s].size(); ++p) {
            const std::string where =
                "stroke " + std::to_string(s + 1) + ", point " + std::to_string(p + 1);
            auto onSurface = surfaceAtUv(surface, glm::vec2(points[s][p]), where);
            if (!onSurface)
                return onSurface.error();
            points[s][p] = *onSurface;
        }
    return {};
}

Result<core::LoadedProject> loadPaintableProject(const std::string& path) {
    auto loaded = core::loadProject(path);
    if (!loaded)
        return loaded.error();
    if (loaded->project.layers.empty())
        return makeError(loaded->file.string(), "the project has no layers to paint");
    return loaded;
}

// --layer by name; none given: the first.
Result<std::size_t> findLayer(const core::Project& project, const std::string& name) {
    if (name.empty())
        return std::size_t{0};
    const auto found =
        std::find_if(project.layers.begin(), project.layers.end(),
                     [&](const core::GrassLayer& layer) { return layer.name == name; });
    if (found != project.layers.end())
        return static_cast<std::size_t>(found - project.layers.begin());
    std::string names;
    for (const auto& layer : project.layers)
        names += (names.empty() ? "" : ", ") + layer.name;
    return makeError("--layer", "no layer named \"" + name + "\" (layers: " + names + ")");
}

// Where the painted map goes: --file, else the layer's own file, else a new default one.
Result<PaintTarget> chooseTarget(const PaintArgs& args, const core::LoadedProject& loaded,
                                 std::size_t layerIndex, core::LayerMap which) {
    const core::GrassLayer& layer = loaded.project.layers[layerIndex];
    const std::string& mapFile = mapFileOf(layer, which);
    const std::string targetText = !args.file.empty() ? args.file
                                   : !mapFile.empty() ? mapFile
                                                      : core::defaultMapFile(layer.name, args.map);
    auto file = core::resolveAssetPath(loaded.folder, targetText, "--file");
    if (!file)
        return file.error();
    if (!isMapFormat(*file))
        return makeError("--file",
                         "cannot save a map as " + targetText + " (use .png, .tif or .exr)");
    return PaintTarget{layerIndex, which, *file,
                       fs::path(targetText).lexically_normal().generic_string()};
}

// The map as the layer has it, or a new one of 1 everywhere: what the grass already saw. Notes
// of the map's file go to stderr and into `printedNotes`.
Result<core::MapImage> loadStartingMap(const PaintArgs& args, const core::LoadedProject& loaded,
                                       const PaintTarget& target,
                                       std::vector<std::string>& printedNotes) {
    const core::GrassLayer& layer = loaded.project.layers[target.layerIndex];
    const std::string& mapFile = mapFileOf(layer, target.which);
    const glm::ivec2 size = layer.mapResolution;
    if (mapFile.empty()) {
        std::printf("%s map of layer \"%s\": new, %dx%d, 1 everywhere\n", args.map.c_str(),
                    layer.name.c_str(), size.x, size.y);
        return core::makeConstantMap(size.x, size.y, 1.0f);
    }
    const std::string fieldPointer =
        "/layers/" + std::to_string(target.layerIndex) + "/" + args.map + "_map";
    auto source = core::resolveAssetPath(loaded.folder, mapFile, fieldPointer);
    if (!source)
        return makeError(loaded.file.string(), source.error().str());
    auto map = core::loadMapImageAt(*source, size.x, size.y);
    if (!map)
        return map.error();
    for (const auto& warning : map->warnings) {
        printedNotes.push_back(source->string() + ": " + warning);
        std::fprintf(stderr, "note: %s\n", printedNotes.back().c_str());
    }
    std::printf("%s map of layer \"%s\": loaded %s at %dx%d\n", args.map.c_str(),
                layer.name.c_str(), mapFile.c_str(), size.x, size.y);
    return map;
}

Result<PaintSurface> loadSurface(const core::LoadedProject& loaded, glm::ivec2 size) {
    PaintSurface surface;
    auto mesh = core::loadProjectMesh(loaded, &surface.notes, nullptr, &surface.uvs,
                                      &surface.groundOrigin);
    if (!mesh)
        return mesh.error();
    surface.mesh = std::move(*mesh);
    surface.texels = std::make_unique<core::TexelSurface>(surface.mesh, size.x, size.y);
    return surface;
}

// Grows the field on the surface's mesh and says what it grew; notes already printed with the
// map are not printed again.
Result<core::Scene> growScene(const PaintArgs& args, const core::LoadedProject& loaded,
                              const PaintTarget& target, PaintSurface& surface,
                              const std::vector<std::string>& printedNotes,
                              Clock::time_point buildStart) {
    const core::GrassLayer& layer = loaded.project.layers[target.layerIndex];
    std::printf("growing layer \"%s\" of %s ...\n", layer.name.c_str(), loaded.file.c_str());
    std::fflush(stdout);
    auto scene =
        core::buildSceneFromMesh(loaded, std::move(surface.mesh), std::move(surface.notes),
                                 surface.groundOrigin);
    if (!scene)
        return scene.error();
    for (const auto& note : scene->notes)
        if (std::find(printedNotes.begin(), printedNotes.end(), note) == printedNotes.end())
            std::fprintf(stderr, "note: %s\n", note.c_str());
    // buildScene says this only for maps the layer already names; a new one deserves it too.
    if (target.which != core::LayerMap::Density && !layer.growth.enabled)
        std::fprintf(stderr,
                     "note: layer \"%s\": the %s map takes effect only with "
                     "growth.enabled = true\n",
                     layer.name.c_str(), args.map.c_str());
    const core::LayerField& field = scene->layers[target.layerIndex];
    std::printf(
        "  built in %.1f ms: %zu live blades in %zu patches; map %dx%d, %zu texels on the "
        "mesh\n",
        msSince(buildStart), field.liveBlades, field.patched.patches.size(), layer.mapResolution.x,
        layer.mapResolution.y, surface.texels->coveredCount());
    return scene;
}

void printBrush(const PaintArgs& args, const core::BrushSettings& brush) {
    char setValue[48] = "";
    if (brush.mode == core::BrushMode::Set)
        std::snprintf(setValue, sizeof setValue, ", value %.3g", args.value);
    std::printf("  brush %s, radius %.4g, strength %.3g, falloff %s, spacing %.3g%s\n",
                args.mode.c_str(), static_cast<double>(brush.radiusM), args.strength,
                args.falloff.c_str(), args.spacing, setValue);
}

// Saves the painted map and, when it is a new file for the layer or was painted in a generated
// atlas (kept next to the mesh), project.json naming them. Nothing changed, or --dry-run:
// writes nothing.
int saveOutputs(const PaintArgs& args, core::LoadedProject& loaded, const PaintTarget& target,
                const core::MapImage& painted, std::size_t totalChanged, core::PaintUvs& uvs) {
    // Nothing to keep: leave the project as it was rather than save a map equal to what the
    // grass already read (and name a new constant map in project.json).
    if (totalChanged == 0) {
        std::printf("no texel changed: nothing written\n");
        return 0;
    }
    if (args.dryRun) {
        std::printf("dry run: nothing written (would save %s)\n", target.file.c_str());
        return 0;
    }
    // saveMapImage wants the folder to exist; a new default map brings its maps/ folder.
    std::error_code ec;
    const fs::path folder = target.file.parent_path();
    const bool madeFolder =
        !folder.empty() && !fs::exists(folder, ec) && fs::create_directories(folder, ec);
    if (auto saved = core::saveMapImage(painted, target.file); !saved) {
        if (madeFolder)
            fs::remove(folder, ec);
        return reportFailure("paint", saved.error(), EXIT_FAILED);
    }
    std::printf("wrote %s (%dx%d)\n", target.file.c_str(), painted.width, painted.height);
    core::GrassLayer& layer = loaded.project.layers[target.layerIndex];
    std::string& mapFile = mapFileOf(layer, target.which);
    auto keptUvs = core::keepGeneratedUvs(loaded.project, loaded.folder, uvs);
    if (!keptUvs)
        return reportFailure("paint", keptUvs.error(), EXIT_FAILED);
    if (*keptUvs)
        std::printf("wrote %s: the UVs the map is painted in\n",
                    (loaded.folder / loaded.project.mesh.uvAtlas).c_str());
    if (mapFile == target.relative && !*keptUvs)
        return 0;
    mapFile = target.relative;
    if (auto saved = core::saveProject(loaded.project, loaded.file); !saved)
        return reportFailure("paint", saved.error(), EXIT_FAILED);
    std::printf("updated %s: layer \"%s\" %s_map = \"%s\"\n", loaded.file.c_str(),
                layer.name.c_str(), args.map.c_str(), target.relative.c_str());
    return 0;
}

}  // namespace

int runPaint(const std::vector<std::string>& argv) {
    PaintArgs args;
    if (const auto exitCode = parsePaintArgs(argv, args))
        return *exitCode;
    auto strokes = readPaintStrokes(args);
    if (!strokes)
        return reportFailure("paint", strokes.error(), EXIT_USAGE);

    auto loaded = loadPaintableProject(args.project);
    if (!loaded)
        return reportFailure("paint", loaded.error(), EXIT_FAILED);
    const auto layerIndex = findLayer(loaded->project, args.layer);
    if (!layerIndex)
        return reportFailure("paint", layerIndex.error(), EXIT_USAGE);
    const auto target = chooseTarget(args, *loaded, *layerIndex, strokes->which);
    if (!target)
        return reportFailure("paint", target.error(), EXIT_USAGE);
    std::vector<std::string> printedNotes;
    auto map = loadStartingMap(args, *loaded, *target, printedNotes);
    if (!map)
        return reportFailure("paint", map.error(), EXIT_FAILED);

    // The mesh first: --uv points and the default radius need the surface, and a bad UV should
    // fail before the (possibly long) growing of the field.
    const auto buildStart = Clock::now();
    auto surface = loadSurface(*loaded, loaded->project.layers[*layerIndex].mapResolution);
    if (!surface)
        return reportFailure("paint", surface.error(), EXIT_FAILED);
    if (args.uv)
        if (auto placed = placeUvPoints(*surface->texels, strokes->points); !placed)
            return reportFailure("paint", placed.error(), EXIT_USAGE);
    core::BrushSettings brush = brushSettings(args);
    if (!args.radiusGiven)
        brush.radiusM = DEFAULT_RADIUS_SHARE * glm::length(core::meshBounds(surface->mesh).size());
    auto scene = growScene(args, *loaded, *target, *surface, printedNotes, buildStart);
    if (!scene)
        return reportFailure("paint", scene.error(), EXIT_FAILED);

    // Paint straight into the map the field grows from, so each re-growth sees every stroke so
    // far without copying the map.
    core::LayerField& field = scene->layers[*layerIndex];
    core::MapImage& painted = core::layerMap(field.source.maps, strokes->which);
    painted = std::move(*map);
    printBrush(args, brush);
    const std::size_t liveBefore = field.liveBlades;
    // The editor's brush on the grown scene, with the texel surface already built above.
    core::ScenePainter painter(*scene, loaded->project.lighting);
    const core::TexelSurface& texels = *surface->texels;
    painter.adoptSurface(std::move(surface->texels));
    auto changed = paintAndRegrow({painter, *layerIndex, strokes->which, field, painted, texels},
                                  brush, strokes->points);
    if (!changed)
        return reportFailure("paint", changed.error(), EXIT_FAILED);
    if (strokes->which == core::LayerMap::Density)
        std::printf("live blades %zu -> %zu\n", liveBefore, field.liveBlades);
    return saveOutputs(args, *loaded, *target, painted, *changed, surface->uvs);
}

}  // namespace grass::cli
