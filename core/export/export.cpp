#include "export/export.h"

#include <algorithm>
#include <set>
#include <system_error>

#include "export/content_names.h"
#include "export/gltf_export.h"
#include "export/merged_blades.h"
#include "export/raw_export.h"
#include "export/runtime_block.h"
#include "export/source_material.h"
#include "export/staged_files.h"
#include "project/project_inputs.h"
#include "util/atomic_file.h"
#include "util/folder_lock.h"

namespace grass::core {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct NamedMap {
    const char* name;
    const MapImage* map;
};

// The layer's painted maps, in a fixed order; maps without texels (absent: 1 everywhere) are
// left out.
std::vector<NamedMap> paintedMaps(const LayerField& layer) {
    std::vector<NamedMap> maps;
    for (const NamedMap map :
         {NamedMap{"density", &layer.source.maps.density},
          NamedMap{"soil", &layer.source.maps.soil}, NamedMap{"light", &layer.source.maps.light}})
        if (map.map->width > 0 && map.map->height > 0)
            maps.push_back(map);
    return maps;
}

// A map's texels and size as one content hash (content_names.h).
std::uint64_t mapHash(const MapImage& map) {
    const int size[2] = {map.width, map.height};
    const std::uint64_t seed = contentHash(std::as_bytes(std::span(size)));
    return contentHash(std::as_bytes(std::span(map.texels)), seed);
}

// A stem per layer, unique within the export even when two layers share a name.
std::vector<std::string> layerStems(const std::vector<std::string>& layerNames) {
    std::vector<std::string> stems;
    std::set<std::string> used{"manifest"};
    for (std::size_t i = 0; i < layerNames.size(); ++i) {
        std::string stem = exportFileStem(layerNames[i]);
        if (used.count(stem))
            stem += "-" + std::to_string(i);
        used.insert(stem);
        stems.push_back(stem);
    }
    return stems;
}

// The .glb's name: the project's, file-safe ("scene" for a project without one);
// "<name>-merged.glb" for --format mesh.
std::string glbFileName(const Project& project, ExportFormat format) {
    return (project.name.empty() ? std::string("scene") : fileSafeName(project.name)) +
           (format == ExportFormat::Mesh ? "-merged.glb" : ".glb");
}

// A glTF surface keeps its own material in the export (source_material.h).
SourceMaterial terrainMaterialOf(const LoadedProject& loaded) {
    const MeshSource& mesh = loaded.project.mesh;
    return mesh.isFile && mesh.fileMaterial ? sourceMeshMaterial(loaded.folder / mesh.file)
                                            : SourceMaterial{};
}

json colorJson(glm::vec3 color) {
    return json::array({color.r, color.g, color.b});
}

// `step` reports progress within the layer (0..1) with what is being done.
using LayerProgress = std::function<void(float within, const char* stage)>;

// An error once the export's stop is requested (ExportOptions::stop); checked between stages.
Result<void> unlessStopped(const ExportOptions& options) {
    if (options.stop.stop_requested())
        return makeError(options.outDir.string(), "the export was stopped: nothing was written");
    return {};
}

Result<void> stageGltfLayer(StagedFiles& staged, const LoadedProject& loaded, const Scene& scene,
                            const SourceMaterial& terrainMaterial, const json& runtime,
                            std::size_t index, const std::string& stem,
                            const ExportOptions& options, const LayerProgress& step,
                            ExportedLayer& report) {
    const LayerField& layer = scene.layers[index];
    GltfLayerInput input;
    input.scene = &scene;
    input.layer = index;
    input.lod = options.lod;
    input.segments = loaded.project.render.stripSegments;
    input.groundColor = loaded.project.render.groundColor;
    input.terrainMaterial = terrainMaterial;
    input.runtime = runtime;
    input.binStem = stem;
    step(0.0f, "maps");
    for (const NamedMap& map : paintedMaps(layer)) {
        const std::string uri =
            contentAddressedName(stem + "-" + map.name, mapHash(*map.map), ".png");
        if (auto written = staged.addPng(uri, *map.map); !written)
            return written.error();
        input.maps.push_back({map.name, uri, {}});
    }
    if (auto wanted = unlessStopped(options); !wanted)
        return wanted;
    step(0.3f, "terrain and blade instances");
    const GltfLayerDocument doc = buildLayerGltf(input);
    if (auto wanted = unlessStopped(options); !wanted)
        return wanted;
    step(0.7f, "writing");
    if (auto written = staged.add(doc.binUri, doc.binary); !written)
        return written.error();
    if (auto written = staged.add(stem + ".gltf", doc.json); !written)
        return written.error();
    report.instances = doc.instances;
    return {};
}

Result<json> stageRawLayer(StagedFiles& staged, const LayerField& layer, const std::string& stem,
                           ExportedLayer& report) {
    const PatchedBlades& patched = layer.patched;
    const auto file = [&](const std::string& name, std::size_t count, std::size_t bytes) {
        return json{{"file", name}, {"count", count}, {"bytes", bytes}};
    };
    json entry = {{"name", layer.name},
                  {"live_blades", layer.liveBlades},
                  {"patch_size", patched.patchSize},
                  {"shape", std::string(bladeShapeName(layer.shape))},
                  {"tip_start", layer.tipStart},
                  {"colors",
                   {{"root", colorJson(layer.rootColor)},
                    {"tip", colorJson(layer.tipColor)},
                    {"poor_root", colorJson(layer.poorRootColor)},
                    {"poor_tip", colorJson(layer.poorTipColor)},
                    {"rule", "colour = mix(healthy, poor, wilt), per slot, root and tip"}}}};
    const std::string blades = rawBladeBytes(patched.blades);
    const std::string patches = rawPatchBytes(patched.patches);
    const std::string wilt = rawFloatBytes(layer.wilt);
    // The lighting inputs the scene baked per slot (SSBO 9 of the blade shaders, 32 bytes:
    // blurred normal and AO, water, age, wilt), default (open ground) where none were baked.
    const std::vector<BladeShading> shadingSlots =
        layer.shading.size() == patched.blades.size()
            ? layer.shading
            : std::vector<BladeShading>(patched.blades.size());
    const std::string shading(reinterpret_cast<const char*>(shadingSlots.data()),
                              shadingSlots.size() * sizeof(BladeShading));
    const auto name = [&](const char* part, const std::string& bytes, const char* extension) {
        return contentAddressedName(stem + "." + part, contentHash(bytes), extension);
    };
    entry["blades"] = file(name("blades", blades, ".bin"), patched.blades.size(), blades.size());
    entry["patches"] =
        file(name("patches", patches, ".bin"), patched.patches.size(), patches.size());
    entry["wilt"] = file(name("wilt", wilt, ".f32"), layer.wilt.size(), wilt.size());
    entry["shading"] = file(name("shading", shading, ".bin"), shadingSlots.size(), shading.size());
    const std::pair<const char*, const std::string*> parts[] = {
        {"blades", &blades}, {"patches", &patches}, {"wilt", &wilt}, {"shading", &shading}};
    for (const auto& [part, bytes] : parts)
        if (auto written = staged.add(entry[part]["file"].get<std::string>(), *bytes); !written)
            return written.error();
    entry["maps"] = json::object();
    for (const NamedMap& map : paintedMaps(layer)) {
        const std::string bytes = rawFloatBytes(map.map->texels);
        const std::string mapFile = name(map.name, bytes, ".f32");
        if (auto written = staged.add(mapFile, bytes); !written)
            return written.error();
        entry["maps"][map.name] = {{"file", mapFile},
                                   {"width", map.map->width},
                                   {"height", map.map->height},
                                   {"bytes", bytes.size()}};
    }
    report.instances = patched.blades.size();
    return entry;
}

// The PNG file's bytes of a map, as staged files write it (16-bit greyscale), for a .glb that
// embeds it: written to a temporary file next to the export and read back.
Result<std::string> pngBytes(const MapImage& map, const fs::path& folder, const std::string& name) {
    // A staged file's temporary name (kept extension: the writer picks the format by it), so
    // an export killed here leaves what the next one clears (removeStaleTemporaries).
    const fs::path temporary = temporaryPathFor(folder / ("embedded-" + name + ".png"));
    if (auto saved = saveMapImage(map, temporary, MapSampleFormat::UInt16); !saved)
        return makeError(temporary.string(), saved.error().message);
    auto bytes = readFile(temporary);
    std::error_code ignored;
    fs::remove(temporary, ignored);
    if (!bytes)
        return bytes.error();
    return std::move(*bytes);
}

// Every layer in one .glb (buildSceneGlb).
Result<void> stageGlb(StagedFiles& staged, const LoadedProject& loaded, const Scene& scene,
                      const SourceMaterial& terrainMaterial, const json& runtime,
                      const ExportOptions& options,
                      const ExportProgress& progress, std::vector<ExportedLayer>& layers) {
    GltfSceneInput input;
    input.scene = &scene;
    input.name = loaded.project.name;
    input.lod = options.lod;
    input.segments = loaded.project.render.stripSegments;
    input.groundColor = loaded.project.render.groundColor;
    input.terrainMaterial = terrainMaterial;
    input.runtime = runtime;
    input.merged = options.format == ExportFormat::Mesh;
    if (input.merged) {
        // Refused before any work: a merged field over the budget, with the LOD that fits.
        const auto triangles = [&](int lod) {
            std::size_t sum = 0;
            for (const LayerField& layer : scene.layers)
                sum += mergedBladeTriangles(layer, lod, input.segments);
            return sum;
        };
        const std::size_t budget = options.maxMergedTriangles;
        if (const std::size_t count = triangles(options.lod); count > budget) {
            int fits = options.lod;
            while (fits < MAX_EXPORT_LOD && triangles(fits) > budget)
                ++fits;
            return makeError("lod", "the merged blades would be " + std::to_string(count) +
                                        " triangles, over the " +
                                        std::to_string(budget) +
                                        " a viewer is sure to draw: give --lod " +
                                        std::to_string(fits) + " or more");
        }
    }
    for (std::size_t i = 0; i < scene.layers.size(); ++i) {
        if (progress)
            progress(0.3f * float(i) / float(scene.layers.size()),
                     "layer \"" + scene.layers[i].name + "\": maps");
        std::vector<GltfMapImage> maps;
        for (const NamedMap& map : paintedMaps(scene.layers[i])) {
            auto png = pngBytes(*map.map, options.outDir, std::to_string(i) + "-" + map.name);
            if (!png)
                return png.error();
            maps.push_back({map.name, "", std::move(*png)});
        }
        input.layerMaps.push_back(std::move(maps));
    }
    if (auto wanted = unlessStopped(options); !wanted)
        return wanted;
    if (progress)
        progress(0.3f, "terrain and blade instances of every layer");
    const GltfSceneDocument doc = buildSceneGlb(input);
    if (auto wanted = unlessStopped(options); !wanted)
        return wanted;
    if (progress)
        progress(0.7f, "writing");
    if (auto written = staged.add(glbFileName(loaded.project, options.format), doc.glb); !written)
        return written.error();
    for (std::size_t i = 0; i < scene.layers.size(); ++i)
        layers.push_back({scene.layers[i].name, scene.layers[i].liveBlades, doc.instances[i]});
    return {};
}

// The out folder: made if missing (with its parents); anything else in its place is an error
// before any work. `created` says whether it was made here, so a failure can take it back.
Result<void> prepareOutDir(const fs::path& outDir, bool& created) {
    if (outDir.empty())
        return makeError("outDir", "no output folder given");
    std::error_code ec;
    const fs::file_status status = fs::status(outDir, ec);
    if (fs::exists(status)) {
        if (!fs::is_directory(status))
            return makeError(outDir.string(),
                             "exists and is not a folder (give a folder to "
                             "export into)");
        // An export killed mid-write left its staged temporaries: this one clears them.
        removeStaleTemporaries(outDir);
        return {};
    }
    created = fs::create_directories(outDir, ec);
    if (ec)
        return makeError(outDir.string(), "cannot create the output folder: " + ec.message());
    return {};
}

}  // namespace

std::string_view exportFormatName(ExportFormat format) {
    switch (format) {
        case ExportFormat::Raw: return "raw";
        case ExportFormat::Glb: return "glb";
        case ExportFormat::Mesh: return "mesh";
        case ExportFormat::Gltf: break;
    }
    return "gltf";
}

Result<ExportFormat> parseExportFormat(std::string_view name) {
    for (const ExportFormat format :
         {ExportFormat::Gltf, ExportFormat::Raw, ExportFormat::Glb, ExportFormat::Mesh})
        if (name == exportFormatName(format))
            return format;
    return makeError("", "unknown format \"" + std::string(name) + "\" (gltf, raw, glb, mesh)");
}

std::uint64_t ExportReport::totalBytes() const {
    std::uint64_t total = 0;
    for (const ExportedFile& file : files)
        total += file.bytes;
    return total;
}

// The scene's behaviour for runtimes (runtime_block.h), returned for the manifest or the glTF
// scene's extras; with `withMeshes` (raw) the terrain and props are staged as content-named
// files it names. What it cannot carry becomes notes.
static Result<json> stageRuntimeBlock(StagedFiles& staged, const LoadedProject& loaded,
                                      const Scene& scene, bool withMeshes,
                                      std::vector<std::string>& notes) {
    auto physics = buildScenePhysics(loaded, scene.groundOrigin);
    if (!physics)
        return physics.error();
    const std::vector<RuntimeMeshFile> meshes =
        withMeshes ? runtimeMeshes(loaded, scene) : std::vector<RuntimeMeshFile>{};
    std::vector<std::string> files;
    for (const RuntimeMeshFile& mesh : meshes) {
        files.push_back(contentAddressedName(fileSafeName(mesh.name) + ".mesh",
                                             contentHash(mesh.bytes), ".bin"));
        if (auto written = staged.add(files.back(), mesh.bytes); !written)
            return written.error();
    }
    if (withMeshes)  // the raw export is the runtime's: say what it will not show
        for (std::string& gap : runtimeBlockGaps(loaded, scene))
            notes.push_back(std::move(gap));
    return runtimeBlock(loaded, scene, *physics, meshes, files);
}

std::string exportFileStem(const std::string& layerName) {
    return fileSafeName(layerName);
}

namespace {

// The entry points (<layer>.gltf, manifest.json) checked against the project's inputs.
Result<void> refuseEntriesOverInputs(const LoadedProject& loaded, const ExportOptions& options,
                                     const std::vector<ProjectInput>& inputs) {
    std::vector<std::string> layerNames;
    for (const GrassLayer& layer : loaded.project.layers)
        layerNames.push_back(layer.name);
    std::vector<std::string> entries;
    if (options.format == ExportFormat::Raw)
        entries.push_back("manifest.json");
    else if (options.format == ExportFormat::Glb || options.format == ExportFormat::Mesh)
        entries.push_back(glbFileName(loaded.project, options.format));
    else
        for (const std::string& stem : layerStems(layerNames))
            entries.push_back(stem + ".gltf");
    for (const std::string& entry : entries)
        if (auto refused = refuseOverwritingInput(inputs, options.outDir / entry, "outDir");
            !refused)
            return refused;
    return {};
}

}  // namespace

Result<void> refuseExportOverInputs(const LoadedProject& loaded, const ExportOptions& options) {
    return refuseEntriesOverInputs(loaded, options, projectInputFiles(loaded));
}

Result<ExportReport> exportProject(const LoadedProject& loaded, const Scene& scene,
                                   const ExportOptions& options, const ExportProgress& progress) {
    // Listed once (it reads a glTF mesh's JSON): for the entry points now, for every staged file.
    std::vector<ProjectInput> inputs = projectInputFiles(loaded);
    if (auto refused = refuseEntriesOverInputs(loaded, options, inputs); !refused)
        return refused.error();
    if (options.lod < 0 || options.lod > MAX_EXPORT_LOD)
        return makeError("lod", "must be from 0 to " + std::to_string(MAX_EXPORT_LOD) + " (got " +
                                    std::to_string(options.lod) + ")");
    if (options.format == ExportFormat::Raw && options.lod != 0)
        return makeError("lod", "applies to the gltf format only (raw holds every blade exactly)");
    if (auto wanted = unlessStopped(options); !wanted)
        return wanted.error();
    bool createdDir = false;
    if (auto prepared = prepareOutDir(options.outDir, createdDir); !prepared)
        return prepared.error();
    auto lock = FolderLock::acquire(options.outDir, "grass export");
    if (!lock)
        return lock.error();

    ExportReport report;
    // Read once (the source file and its textures), shared by every layer's file.
    const SourceMaterial terrainMaterial =
        options.format != ExportFormat::Raw ? terrainMaterialOf(loaded) : SourceMaterial{};
    for (const std::string& note : terrainMaterial.notes)
        report.notes.push_back("terrain material: " + note);
    Result<void> staging = [&]() -> Result<void> {
        StagedFiles staged(options.outDir);
        staged.protect(std::move(inputs));
        std::vector<std::string> layerNames;
        for (const LayerField& layer : scene.layers)
            layerNames.push_back(layer.name);
        const std::vector<std::string> stems = layerStems(layerNames);
        json layers = json::array();
        // Every format carries the scene's behaviour: raw in its manifest (with the meshes as
        // files), glTF in its scene's extras (the terrain is in the file itself).
        auto runtime = stageRuntimeBlock(staged, loaded, scene, options.format == ExportFormat::Raw,
                                         report.notes);
        if (!runtime)
            return runtime.error();
        if (options.format == ExportFormat::Glb || options.format == ExportFormat::Mesh) {
            if (auto written = stageGlb(staged, loaded, scene, terrainMaterial, *runtime, options,
                                        progress,
                                          report.layers);
                !written)
                return written.error();
        }
        const auto layerCount = static_cast<float>(std::max<std::size_t>(scene.layers.size(), 1));
        const bool oneFile = options.format == ExportFormat::Glb || options.format == ExportFormat::Mesh;
        for (std::size_t i = 0; i < scene.layers.size() && !oneFile; ++i) {
            if (auto wanted = unlessStopped(options); !wanted)
                return wanted;
            const LayerField& layer = scene.layers[i];
            const auto step = [&](float within, const char* stage) {
                if (progress)
                    progress((static_cast<float>(i) + within) / layerCount,
                             "layer \"" + layer.name + "\": " + stage);
            };
            ExportedLayer exported{layer.name, layer.liveBlades, 0};
            if (options.format == ExportFormat::Gltf) {
                if (auto written = stageGltfLayer(staged, loaded, scene, terrainMaterial, *runtime,
                                                  i, stems[i], options, step, exported);
                    !written)
                    return written.error();
            } else {
                step(0.0f, "blades, patches and maps");
                auto entry = stageRawLayer(staged, layer, stems[i], exported);
                if (!entry)
                    return entry.error();
                layers.push_back(std::move(*entry));
            }
            report.layers.push_back(exported);
        }
        if (options.format == ExportFormat::Raw) {
            json manifest = {{"format", "grass-raw-export"},
                             {"version", 1},
                             {"project", loaded.project.name},
                             {"layout", rawLayoutManifest()},
                             {"layers", layers},
                             {"runtime", std::move(*runtime)}};
            if (auto written = staged.add("manifest.json", manifest.dump(2) + "\n"); !written)
                return written.error();
        }
        // The last moment a stop counts: renamed, the files are the export.
        if (auto wanted = unlessStopped(options); !wanted)
            return wanted;
        if (progress)
            progress(1.0f, "renaming files into place");
        auto files = staged.commit();
        if (!files)
            return files.error();
        report.files = std::move(*files);
        // Only now, with every entry point renamed into place, may what the previous export
        // named go: before, a kill would leave an entry point without its files.
        removeUnreferencedExportFiles(options.outDir);
        return {};
    }();
    if (!staging) {
        std::error_code ignored;
        if (createdDir)
            fs::remove(options.outDir, ignored);  // only removes it if it is still empty
        return staging.error();
    }
    return report;
}

}  // namespace grass::core
