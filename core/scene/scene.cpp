#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "maps/map_image.h"
#include "mesh/gltf_loader.h"
#include "mesh/procedural.h"
#include "scatter/placement_rules.h"
#include "scene/camera.h"
#include "util/byte_size.h"
#include "util/rng.h"

namespace grass::core {

std::size_t Scene::totalBlades() const {
    std::size_t total = 0;
    for (const auto& layer : layers)
        total += layer.liveBlades;
    return total;
}

// A file named by the project that cannot be read: say which project field named it, so the
// user knows where to fix it ("project.json: /layers/0/density_map: maps/d.png: not found").
static Error fromProjectField(const LoadedProject& loaded, const std::string& field,
                              const Error& error) {
    return Error{loaded.file.string(), field + ": " + error.str()};
}

double estimateLayerBlades(const ScatterParams& params, double area) {
    double blades = static_cast<double>(params.density) * area;
    if (params.clumpSpacing > 0.0f) {
        const double spacing = static_cast<double>(params.clumpSpacing);
        blades += 2.0 / (std::sqrt(3.0) * spacing * spacing) * area * params.bladesPerClump;
    }
    return blades;
}

std::size_t sceneBytesPerBlade() {
    // The candidate (blade, uv, thinning, face; a rule factor only where rules thin, a bend only
    // where bending cues are on), the grown slot (blade, wilt, shading), the physics state (η,
    // rest tip) and the GPU copy (blade, shading).
    return sizeof(Blade) + sizeof(glm::vec2) + sizeof(CandidateThinning) + sizeof(std::uint32_t) +
           sizeof(Blade) + sizeof(float) + sizeof(BladeShading) + sizeof(float) +
           sizeof(glm::vec3) + sizeof(Blade) + sizeof(BladeShading);
}

std::size_t sceneBytesPerBillboard() {
    // The object placed and drawn, its rule factor per layer (one layer counted), and its star
    // instance on the CPU (while it is uploaded) and the GPU.
    return 2 * sizeof(GrassObject) + sizeof(float) + 2 * sizeof(StarInstance);
}

// "4e+08", "1600", "0.25": 3 significant digits for messages.
static std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

// Too many billboards for one scene, refused naming the project's /billboards/density.
static Result<void> refuseHugeBillboards(const std::string& projectFile, float density,
                                         double area) {
    const double objects = static_cast<double>(density) * area;
    if (!(objects <= MAX_SCENE_BILLBOARDS)) {
        const auto perObject = static_cast<double>(sceneBytesPerBillboard());
        return Error{
            projectFile,
            "/billboards/density: " + number(density) + " /m² on " + number(area) +
                " m² of surface asks for about " + number(objects) + " billboards, " +
                byteSizeText(objects * perObject) + "; the limit is " +
                number(MAX_SCENE_BILLBOARDS / 1e6) + " million per scene (" +
                byteSizeText(MAX_SCENE_BILLBOARDS * perObject) +
                "): lower it, or draw the field by blades (render technique), which places none"};
    }
    return {};
}

// Up front, before a blade or billboard is allocated: a typo'd density (or a 100 km mesh) is
// refused with what it would have needed, instead of running the machine out of memory. The
// billboards count only when the technique draws them (placeBillboards checks them then).
static Result<void> refuseHugeScene(const LoadedProject& loaded, double area) {
    const Project& project = loaded.project;
    if (!std::isfinite(area))
        return Error{loaded.file.string(), "/mesh: the surface area must be finite (got " +
                                               number(area) + " m²): lower size or hill_height"};
    double total = 0.0;
    for (std::size_t i = 0; i < project.layers.size(); ++i) {
        const ScatterParams& scatter = project.layers[i].scatter;
        const double blades = estimateLayerBlades(scatter, area);
        total += blades;
        // Written so that a NaN estimate is refused too.
        if (total <= MAX_SCENE_BLADES)
            continue;
        std::string asks = "density " + number(scatter.density) + " /m²";
        if (scatter.clumpSpacing > 0.0f && scatter.bladesPerClump > 0)
            asks += " and clumps of " + std::to_string(scatter.bladesPerClump) + " blades " +
                    number(scatter.clumpSpacing) + " m apart";
        const double bytes = blades * static_cast<double>(sceneBytesPerBlade());
        return Error{
            loaded.file.string(),
            "/layers/" + std::to_string(i) + ": " + asks + " on " + number(area) +
                " m² of surface asks for about " + number(blades) + " blades, " +
                byteSizeText(bytes) + " of blade data; the limit is " +
                number(MAX_SCENE_BLADES / 1e6) + " million blades per scene (" +
                byteSizeText(MAX_SCENE_BLADES * static_cast<double>(sceneBytesPerBlade())) +
                "): lower density, raise clump_spacing, lower blades_per_clump or shrink the "
                "/mesh"};
    }
    if (drawsBillboards(project.render.technique))
        return refuseHugeBillboards(loaded.file.string(), project.billboards.placement.density,
                                    area);
    return {};
}

// The side a generated UV atlas keeps its gutters for: the coarsest map of any layer.
static int coarsestMapSide(const Project& project) {
    int coarsest = MAX_MAP_RESOLUTION;
    for (const GrassLayer& layer : project.layers)
        coarsest = std::min({coarsest, layer.mapResolution.x, layer.mapResolution.y});
    return coarsest;
}

Result<MovableSurfaceMesh> loadProjectMesh(const LoadedProject& loaded,
                                           std::vector<std::string>* notes, SurfaceLook* look,
                                           PaintUvs* paintUvs, glm::dvec3* groundOrigin,
                                           GltfImport* alreadyRead, std::stop_token stop,
                                           const BuildProgress& progress) {
    const MeshSource& source = loaded.project.mesh;
    if (!source.isFile)
        return makeProceduralMesh(source.procedural);
    auto path = resolveAssetPath(loaded.folder, source.file, "/mesh/file");
    if (!path)
        return Error{loaded.file.string() + ": " + path.error().path, path.error().message};
    const std::string fileName = path->filename().string();
    if (progress && alreadyRead == nullptr)
        progress("reading " + fileName);
    auto imported = alreadyRead != nullptr ? Result<GltfImport>(std::move(*alreadyRead))
                                           : loadGltf(*path, GltfPlacement::GroundNearOrigin,
                                                      source.metresPerUnit, glm::dvec3(0.0), stop);
    if (stop.stop_requested())
        return buildStopped(loaded);
    if (!imported)
        return fromProjectField(loaded, "/mesh/file", imported.error());
    if (notes)
        for (auto& note : imported->notes)
            notes->push_back(path->string() + ": " + note);
    // The material is read when asked for, or when unpaintable UVs must know whether a texture
    // needs them; never twice.
    std::optional<SurfaceLook> surfaceLook;
    const auto readLook = [&]() -> SurfaceLook& {
        if (!surfaceLook)
            surfaceLook = surfaceLookOf(*path, imported->hasUv);
        return *surfaceLook;
    };
    std::filesystem::path atlasFile;
    if (!source.uvAtlas.empty()) {
        auto resolved = resolveAssetPath(loaded.folder, source.uvAtlas, "/mesh/uv_atlas");
        if (!resolved)
            return Error{loaded.file.string() + ": " + resolved.error().path,
                         resolved.error().message};
        atlasFile = *resolved;
    }
    std::vector<std::string> uvNotes;
    if (progress)
        progress("checking the UVs of " + fileName);
    PaintUvs uvs = makeUvsPaintable(
        imported->mesh, imported->hasUv, [&] { return !readLook().baseTexture.pixels.empty(); },
        atlasFile, coarsestMapSide(loaded.project), uvNotes, stop);
    if (stop.stop_requested())
        return buildStopped(loaded);
    if (notes)
        for (auto& note : uvNotes)
            notes->push_back(path->string() + ": " + note);
    if (paintUvs)
        *paintUvs = std::move(uvs);
    applyMeshFrame(imported->mesh, source.metresPerUnit, source.up);
    if (groundOrigin)
        *groundOrigin = imported->origin;
    // Drawn in the project's ground colour instead: the file's look is not read for it (the
    // UVs above still asked whether its texture needs them, so the painted maps keep their
    // UVs whichever way the surface is drawn).
    if (look && source.fileMaterial) {
        *look = std::move(readLook());
        if (notes)
            notes->insert(notes->end(), look->notes.begin(), look->notes.end());
    }
    return std::move(imported->mesh);
}

RuleWorld ruleWorldOf(const Project& project, const std::vector<SceneProp>& props) {
    RuleWorld world;
    world.gravity = project.physics.gravity;
    world.gravityMode = project.physics.gravityMode;
    for (const SceneProp& prop : props) {
        const glm::mat4 model = prop.modelAt(0.0f);
        for (const auto fh : prop.mesh->faces()) {
            auto corners = facePositions(prop.mesh, fh);
            for (glm::vec3& corner : corners)
                corner = glm::vec3(model * glm::vec4(corner, 1.0f));
            world.colliderTriangles.push_back(corners);
        }
        world.colliderEnds.push_back(world.colliderTriangles.size());
    }
    return world;
}

namespace {
// Texels of a generated billboard texture and the blades drawn in it: at 128² a tuft 0.4 m tall
// keeps 3 mm texels, finer than any pixel it covers beyond a metre.
constexpr int BILLBOARD_TEXTURE_SIDE = 128;
constexpr int BILLBOARD_TEXTURE_BLADES = 9;

// The billboards' own random stream, apart from the layers'.
std::uint64_t billboardSeed(const Project& project) {
    return Rng::splitMix(project.seed ^ 0xB111B0A2D5ULL);
}
}  // namespace

// Random points on the mesh for every layer of the project and its billboards, made once: on an
// 8.4-million-triangle ground each one took 0.4-1.5 s. With the neighbourhood index when a layer
// grows clumps. Not kept in the scene: it would hold ~0.5 GB there.
static SurfaceSampler projectSampler(const SurfaceMesh& mesh, const Project& project) {
    SurfaceSampler sampler(mesh);
    if (std::any_of(project.layers.begin(), project.layers.end(), [](const GrassLayer& layer) {
            return scatterNeedsNeighbourhoods(layer.scatter);
        }))
        sampler.buildNeighbourhoodIndex();
    return sampler;
}

static Result<BillboardLayer> placedBillboardsWith(const Scene& scene,
                                                   const SurfaceSampler* sampler, bool following,
                                                   std::stop_token stop);

Error buildStopped(const LoadedProject& project) {
    return Error{project.file.string(), "stopped before the field was grown"};
}

Result<Scene> buildSceneFromMesh(const LoadedProject& loaded, MovableSurfaceMesh mesh,
                                 std::vector<std::string> notes, glm::dvec3 groundOrigin,
                                 std::stop_token stop, const BuildProgress& progress) {
    // Before the mesh's bounds and area and the colliders' files (seconds for a large mesh).
    if (stop.stop_requested())
        return buildStopped(loaded);
    Scene scene;
    scene.groundOrigin = groundOrigin;
    scene.mesh = std::move(mesh);
    scene.bounds = meshBounds(scene.mesh);
    scene.area = surfaceArea(scene.mesh);
    scene.notes = std::move(notes);
    const Project& project = loaded.project;
    if (auto refused = refuseHugeScene(loaded, scene.area); !refused)
        return refused.error();
    auto props = loadSceneProps(loaded, groundOrigin);
    if (!props)
        return props.error();
    scene.props = std::move(*props);
    std::optional<SurfaceSampler> sampler;  // made when first needed
    const auto samplerOfMesh = [&]() -> const SurfaceSampler& {
        if (!sampler)
            sampler.emplace(projectSampler(*scene.mesh, project));
        return *sampler;
    };
    const RuleWorld ruleWorld = ruleWorldOf(project, scene.props);
    for (std::size_t i = 0; i < project.layers.size(); ++i) {
        if (stop.stop_requested())
            return buildStopped(loaded);
        const GrassLayer& layer = project.layers[i];
        if (progress)
            progress("growing layer \"" + layer.name + "\" (" + std::to_string(i + 1) + " of " +
                     std::to_string(project.layers.size()) + ")");
        LayerField field;
        field.name = layer.name;
        const std::string at = "/layers/" + std::to_string(i) + "/";
        const auto loadMap = [&](const std::string& relative, const char* key,
                                 MapImage& out) -> Result<void> {
            if (relative.empty())
                return {};
            auto path = resolveAssetPath(loaded.folder, relative, at + key);
            if (!path)
                return Error{loaded.file.string() + ": " + path.error().path, path.error().message};
            auto map = loadMapImageAt(*path, layer.mapResolution.x, layer.mapResolution.y);
            if (!map)
                return fromProjectField(loaded, at + key, map.error());
            // The loader's warnings already start with the file's name.
            for (const auto& warning : map->warnings)
                scene.notes.push_back(warning);
            out = std::move(*map);
            return {};
        };
        LayerSource& source = field.source;
        for (auto loadedMap : {loadMap(layer.densityMap, "density_map", source.maps.density),
                               loadMap(layer.soilMap, "soil_map", source.maps.soil),
                               loadMap(layer.lightMap, "light_map", source.maps.light),
                               loadMap(layer.cutMap, "cut_map", source.maps.cut)})
            if (!loadedMap)
                return loadedMap.error();
        if (!layer.growth.enabled && (!layer.soilMap.empty() || !layer.lightMap.empty()))
            scene.notes.push_back("layer \"" + layer.name +
                                  "\": soil_map and light_map take effect only with "
                                  "growth.enabled = true");
        // Each layer its own stream, so adding a layer does not reshuffle the others.
        field.seed = Rng::splitMix(project.seed ^ (0x9E3779B97F4A7C15ULL * (i + 1)));
        const SurfaceSampler& layerSampler = samplerOfMesh();
        if (stop.stop_requested())  // the sampler of a large mesh takes a while
            return buildStopped(loaded);
        source.candidates = scatterCandidates(layerSampler, layer.scatter, field.seed);
        // Its memory goes once nothing needs it (the growing's peak is later).
        if (i + 1 == project.layers.size() && !drawsBillboards(project.render.technique))
            sampler.reset();
        for (auto& warning : source.candidates.warnings)
            scene.notes.push_back("layer \"" + layer.name + "\": " + warning);
        source.ruleFactors = placementFactors(scene.mesh, source.candidates, layer.rules, ruleWorld);
        source.bends = candidateBends(layer.bending, source.candidates, source.ruleFactors,
                                      ruleWorld);
        if (stop.stop_requested())
            return buildStopped(loaded);
        source.sway = layer.bending.sway;
        source.growthEnabled = layer.growth.enabled;
        source.curves = layer.growth.curves;
        source.stemLevels = layer.growth.levels;
        source.stemTipWidth = layer.growth.stemTipWidth;
        source.regrowRate = layer.regrowRate;
        static_cast<GrownField&>(field) = growField(source, project.render.patchSize, stop);
        if (stop.stop_requested())
            return buildStopped(loaded);
        takeLayerLook(field, layer);
        auto shading = bakeBladeShading(field.patched.blades, bladeShadingParams(project.lighting),
                                        field.seed);
        if (!shading)
            return Error{loaded.file.string(), "lighting: " + shading.error().str()};
        field.shading = std::move(*shading);
        for (std::size_t slot = 0; slot < field.shading.size(); ++slot)
            field.shading[slot].waterAge.z = field.wilt[slot];
        scene.layers.push_back(std::move(field));
    }
    auto texture = billboardTexture(loaded);
    if (!texture)
        return texture.error();
    scene.billboards.texture = std::move(*texture);
    BillboardRecipe recipe{.placement = project.billboards.placement,
                           .seed = billboardSeed(project),
                           .rules = {},
                           .world = ruleWorld,
                           .projectFile = loaded.file.string()};
    for (const GrassLayer& layer : project.layers)
        recipe.rules.push_back(layer.rules);
    scene.billboards.unplaced = std::move(recipe);
    if (drawsBillboards(project.render.technique)) {
        if (progress)
            progress("placing the billboards");
        auto placed = placedBillboardsWith(scene, &samplerOfMesh(), true, stop);
        if (!placed)
            return placed.error();
        scene.billboards = std::move(*placed);
    }
    return scene;
}

bool drawsBillboards(GrassTechnique technique) {
    return technique == GrassTechnique::Billboards || technique == GrassTechnique::Hybrid;
}

Result<Rgba8Pixels> billboardTexture(const LoadedProject& loaded) {
    const BillboardDesc& desc = loaded.project.billboards;
    if (!desc.texture.empty()) {
        auto path = resolveAssetPath(loaded.folder, desc.texture, "/billboards/texture");
        if (!path)
            return Error{loaded.file.string(), path.error().str()};
        return loadGrassTexture(*path);
    }
    const GrassLayer colours =
        loaded.project.layers.empty() ? GrassLayer{} : loaded.project.layers.front();
    return generateGrassTexture(BILLBOARD_TEXTURE_SIDE, BILLBOARD_TEXTURE_SIDE,
                                BILLBOARD_TEXTURE_BLADES, billboardSeed(loaded.project),
                                colours.rootColor, colours.tipColor);
}

Result<BillboardLayer> placedBillboards(const Scene& scene) {
    return placedBillboardsWith(scene, nullptr, true, {});
}

Result<BillboardLayer> placedBillboardsUnfollowed(const Scene& scene, std::stop_token stop) {
    return placedBillboardsWith(scene, nullptr, false, stop);
}

// `sampler`: one of the scene's mesh already made (buildSceneFromMesh's), else one is made.
// `following`: with the objects that follow the layers' maps.
static Result<BillboardLayer> placedBillboardsWith(const Scene& scene,
                                                   const SurfaceSampler* sampler, bool following,
                                                   std::stop_token stop) {
    if (!scene.billboards.unplaced)
        return scene.billboards;
    const BillboardRecipe& recipe = *scene.billboards.unplaced;
    if (auto refused =
            refuseHugeBillboards(recipe.projectFile, recipe.placement.density, scene.area);
        !refused)
        return refused.error();
    BillboardLayer billboards;
    billboards.texture = scene.billboards.texture;
    std::optional<SurfaceSampler> ownSampler;
    if (sampler == nullptr)
        sampler = &ownSampler.emplace(*scene.mesh);
    const auto stopped = [&] {
        return Error{recipe.projectFile, "stopped before the billboards were placed"};
    };
    if (stop.stop_requested())
        return stopped();
    billboards.placed = placeGrassObjects(*sampler, recipe.placement, recipe.seed);
    ownSampler.reset();
    if (stop.stop_requested())
        return stopped();
    billboards.follow = billboardFollow(billboards.placed, scene.layers, recipe.rules, scene.mesh,
                                        recipe.world, meanGrassColour(billboards.texture));
    if (following)
        billboards.objects = followLayers(billboards.placed, billboards.follow, scene.layers);
    return billboards;
}

Result<void> placeBillboards(Scene& scene) {
    if (!scene.billboards.unplaced)
        return {};
    auto placed = placedBillboards(scene);
    if (!placed)
        return placed.error();
    scene.billboards = std::move(*placed);
    return {};
}

void refreshBillboards(Scene& scene) {
    scene.billboards.objects =
        followLayers(scene.billboards.placed, scene.billboards.follow, scene.layers);
}

void takeLayerLook(LayerField& field, const GrassLayer& layer) {
    field.rootColor = layer.rootColor;
    field.tipColor = layer.tipColor;
    field.poorRootColor = layer.growth.poorRootColor;
    field.poorTipColor = layer.growth.poorTipColor;
    field.shape = layer.shape;
    field.tipStart = layer.tipStart;
}

void takeLayerLooks(Scene& scene, const Project& project) {
    for (std::size_t i = 0; i < std::min(scene.layers.size(), project.layers.size()); ++i) {
        scene.layers[i].name = project.layers[i].name;
        takeLayerLook(scene.layers[i], project.layers[i]);
    }
}

BladeShadingParams bladeShadingParams(const GrassLightingDesc& lighting) {
    BladeShadingParams params;
    params.aoRadiusM = lighting.aoRadiusM;
    params.aoStrength = lighting.aoStrength;
    params.aoFloor = lighting.aoFloor;
    params.normalBlurRadiusM = lighting.normalBlurRadiusM;
    params.cellSigmas = lighting.aoCellSigmas;
    params.waterRange = lighting.water;
    return params;
}

namespace {

// Copies the wilt (waterAge.z, which regrown slots change and a re-bake resets) into the shading
// of `patches`.
void restoreWilt(LayerField& layer, const std::vector<std::uint32_t>& patches) {
    if (layer.shading.size() != layer.wilt.size())
        return;
    const std::size_t size = layer.patched.patchSize;
    for (std::uint32_t p : patches)
        for (std::size_t slot = p * size; slot < (p + 1) * size; ++slot)
            layer.shading[slot].waterAge.z = layer.wilt[slot];
}

glm::vec3 shadingReach(const BladeShadingParams& params) {
    return glm::vec3(3.0f * std::max(params.aoRadiusM, params.normalBlurRadiusM));
}

// The slots of the patches whose bounds (every blade's reach) overlap `box`, neighbouring
// patches joined into one range: where a re-bake near `box` finds its blades, without a scan
// of the whole layer.
std::vector<SlotRange> slotsOfPatchesNear(const LayerField& layer, const Bounds& box) {
    const auto size = static_cast<std::uint32_t>(layer.patched.patchSize);
    std::vector<SlotRange> slots;
    for (std::uint32_t p = 0; p < layer.patched.patches.size(); ++p) {
        if (!layer.patched.patches[p].bounds.overlaps(box))
            continue;
        if (!slots.empty() && slots.back().end == p * size)
            slots.back().end += size;
        else
            slots.push_back({p * size, (p + 1) * size});
    }
    return slots;
}

// Re-bakes the blades with a root in `region`; the patches holding them go into the report.
Result<void> rebakeRegion(LayerField& layer, const Bounds& region, const BladeShadingParams& params,
                          RegrowReport& report) {
    report.shadedRegion = region;
    const glm::vec3 reach = shadingReach(params);
    auto rebaked = rebakeBladeShading(layer.patched.blades, params, layer.seed, region,
                                      slotsOfPatchesNear(layer, {region.min - reach, region.max + reach}),
                                      layer.shading);
    if (!rebaked)
        return Error{"lighting", rebaked.error().str()};
    report.rebakedBlades = *rebaked;
    report.shadedPatches = patchesWithRootsIn(layer.source, layer, region);
    return {};
}

// The estimate a dab gets until the stroke's exact re-bake (ShadingUpdate::RegrownOnly): the
// AO of the regrown patches' blades alone (`grown` bounds them), whose kernel (3σ = 0.45 m by
// default) reaches few neighbours; their blurred normals, a 2.25 m average of the terrain that a
// density change barely moves, keep their values (a slot that was padding takes its own blade's
// up meanwhile).
Result<void> rebakeAoOnly(LayerField& layer, const std::vector<std::uint32_t>& patches,
                          const Bounds& grown, BladeShadingParams params, RegrowReport& report) {
    const auto size = static_cast<std::uint32_t>(layer.patched.patchSize);
    std::vector<glm::vec4> kept;
    kept.reserve(patches.size() * size);
    std::vector<SlotRange> targets;
    for (std::uint32_t p : patches) {
        targets.push_back({p * size, (p + 1) * size});
        for (std::size_t slot = p * size; slot < (p + 1) * size; ++slot)
            kept.push_back(layer.shading[slot].blurredNormalAo);
    }
    params.normalBlurRadiusM = 0.0f;
    // Cells of 0.75σ instead of 0.5σ: fewer clusters per blade, a coarser sum (AO within 0.0054
    // of the exact re-bake on the test plane, bound 0.01; scene_paint_test) for the 2 m dab to
    // fit the brush's 16 ms (bench_growth: 14.8 ms, 19.3 ms at 0.5σ).
    params.cellSigmas = 0.75f;
    const glm::vec3 reach = shadingReach(params);
    auto rebaked = rebakeBladeShading(layer.patched.blades, params, layer.seed, targets,
                                      slotsOfPatchesNear(layer, {grown.min - reach, grown.max + reach}),
                                      layer.shading);
    if (!rebaked)
        return Error{"lighting", rebaked.error().str()};
    report.rebakedBlades = *rebaked;
    report.shadedRegion = grown;
    report.shadedPatches = patches;
    const glm::vec4 padding = BladeShading{}.blurredNormalAo;
    std::size_t k = 0;
    for (std::uint32_t p : patches)
        for (std::size_t slot = p * size; slot < (p + 1) * size; ++slot, ++k) {
            BladeShading& s = layer.shading[slot];
            if (kept[k] != padding && s.blurredNormalAo != padding)
                s.blurredNormalAo = glm::vec4(glm::vec3(kept[k]), s.ao());
        }
    return {};
}

}  // namespace

Result<RegrowReport> regrowLayerRegion(LayerField& layer, const Bounds& painted, float texelMarginM,
                                       const GrassLightingDesc& lighting, ShadingUpdate update) {
    const glm::vec3 margin(std::max(texelMarginM, 0.0f));
    return regrowLayerPatches(
        layer,
        patchesWithRootsIn(layer.source, layer, {painted.min - margin, painted.max + margin}),
        lighting, update);
}

Result<RegrowReport> regrowLayerPatches(LayerField& layer, std::vector<std::uint32_t> patches,
                                        const GrassLightingDesc& lighting, ShadingUpdate update) {
    RegrowReport report;
    report.patches = std::move(patches);
    report.bladesAddedOrRemoved = regrowPatches(layer.source, report.patches, layer);
    report.shadedPatches = report.patches;
    if (report.bladesAddedOrRemoved > 0) {
        // The bake counts the blades around each one (AO) and averages their surface normals
        // (blurred normal); growth changes neither, so only a blade gained or lost changes
        // them: then every blade whose kernels (3σ) reach a regrown patch is re-baked — or,
        // RegrownOnly, the regrown patches' own blades now and their neighbours later.
        const BladeShadingParams params = bladeShadingParams(lighting);
        Bounds grown = layer.patched.patches[report.patches.front()].bounds;
        for (std::uint32_t p : report.patches) {
            grown.min = glm::min(grown.min, layer.patched.patches[p].bounds.min);
            grown.max = glm::max(grown.max, layer.patched.patches[p].bounds.max);
        }
        const glm::vec3 reach = shadingReach(params);
        const Bounds neighbourhood{grown.min - reach, grown.max + reach};
        if (update == ShadingUpdate::Exact) {
            if (auto rebaked = rebakeRegion(layer, neighbourhood, params, report); !rebaked)
                return rebaked.error();
        } else if (auto rebaked = rebakeAoOnly(layer, report.patches, grown, params, report); !rebaked) {
            return rebaked.error();
        }
        if (update == ShadingUpdate::RegrownOnly) {
            report.shadingPending = true;
            report.pendingShadeRegion = grown;
        }
    }
    restoreWilt(layer, report.shadedPatches);
    return report;
}

Result<RegrowReport> rebakeLayerShading(LayerField& layer, const Bounds& region,
                                        const GrassLightingDesc& lighting) {
    const BladeShadingParams params = bladeShadingParams(lighting);
    const glm::vec3 reach = shadingReach(params);
    RegrowReport report;
    if (auto rebaked = rebakeRegion(layer, {region.min - reach, region.max + reach}, params, report);
        !rebaked)
        return rebaked.error();
    restoreWilt(layer, report.shadedPatches);
    return report;
}

glm::dvec3 groundOriginOf(const LoadedProject& loaded) {
    const auto& colliders = loaded.project.colliders;
    const bool meshCollider = std::any_of(colliders.begin(), colliders.end(), [](const auto& c) {
        return c.shape == ColliderShape::Mesh;
    });
    glm::dvec3 origin{0.0};
    if (loaded.project.mesh.isFile && meshCollider)
        (void)loadProjectMesh(loaded, nullptr, nullptr, nullptr, &origin);
    return origin;
}

Result<Scene> buildScene(const LoadedProject& loaded, GltfImport* alreadyRead, std::stop_token stop,
                         const BuildProgress& progress) {
    std::vector<std::string> notes;
    SurfaceLook look;
    PaintUvs paintUvs;
    glm::dvec3 groundOrigin{0.0};
    auto mesh = loadProjectMesh(loaded, &notes, &look, &paintUvs, &groundOrigin, alreadyRead, stop,
                                progress);
    if (!mesh)
        return mesh.error();
    auto scene = buildSceneFromMesh(loaded, std::move(*mesh), std::move(notes), groundOrigin, stop,
                                    progress);
    if (scene) {
        scene->look = std::move(look);
        scene->paintUvs = std::move(paintUvs);
    }
    return scene;
}

bool sameSurface(const LoadedProject& built, const LoadedProject& next) {
    return built.folder == next.folder && built.project.mesh == next.project.mesh &&
           coarsestMapSide(built.project) == coarsestMapSide(next.project);
}

Result<Scene> regrowOnSameSurface(const LoadedProject& loaded, const Scene& previous,
                                  std::stop_token stop, const BuildProgress& progress) {
    auto scene = buildSceneFromMesh(loaded, previous.mesh.shared(), {}, previous.groundOrigin, stop,
                                    progress);
    if (scene) {
        scene->look = previous.look;
        scene->paintUvs = previous.paintUvs;
    }
    return scene;
}

float physicsScaleFor(const BladeRanges& blade) {
    const BladeRanges reference;
    const float height = 0.5f * (blade.heightMin + blade.heightMax);
    const float referenceHeight = 0.5f * (reference.heightMin + reference.heightMax);
    const float scale = height / referenceHeight;
    return std::isfinite(scale) && scale > 0.0f ? scale : 1.0f;
}

Result<LoadedProject> projectForMesh(const std::filesystem::path& meshFile, const SurfaceMesh& mesh,
                                     std::size_t targetBlades, std::vector<std::string>* notes) {
    const double area = surfaceArea(mesh);
    const Bounds bounds = meshBounds(mesh);
    if (!(area > 0.0))
        return makeError(meshFile.string(), "the mesh has no surface area");

    LoadedProject loaded;
    loaded.folder = std::filesystem::absolute(meshFile).parent_path();
    loaded.file = meshFile;
    Project& project = loaded.project;
    project.name = meshFile.stem().string();
    project.mesh.isFile = true;
    project.mesh.file = meshFile.filename().string();
    GrassLayer& layer = project.layers.front();
    layer.scatter.density = static_cast<float>(static_cast<double>(targetBlades) / area);
    layer.scatter.clumpSpacing = 0.0f;
    // Blades sized to the mesh whatever its units: a few blade spacings tall, but never more
    // than a small fraction of the object, so a bunny gets fur-like grass and a terrain a lawn.
    const float spacing = static_cast<float>(std::sqrt(area / static_cast<double>(targetBlades)));
    const float diagonal = glm::length(bounds.size());
    float height = std::min(6.0f * spacing, 0.06f * diagonal);
    // Within what project.json takes, so that the project saves: a 105 km mesh asked for blades
    // of 2.3 to 4.2 km, which the editor then could not save. Such a mesh is most often in
    // other units than metres.
    constexpr float HEIGHT_SPREAD = 1.3f;  // the tallest blade over the mean
    if (const float tallest = MAX_BLADE_HEIGHT_M / HEIGHT_SPREAD; height > tallest) {
        if (notes)
            notes->push_back("blades are at most " + number(MAX_BLADE_HEIGHT_M) +
                             " m tall, on this mesh of " + number(diagonal) +
                             " m across (they would be " + number(HEIGHT_SPREAD * height) +
                             " m): if its unit is not the metre, "
                             "say which it is (--unit, or \"unit\" in project.json's \"mesh\")");
        height = tallest;
    }
    layer.scatter.blade.heightMin = (2.0f - HEIGHT_SPREAD) * height;
    layer.scatter.blade.heightMax = HEIGHT_SPREAD * height;
    layer.scatter.blade.widthMin = 0.03f * height;
    layer.scatter.blade.widthMax = 0.05f * height;
    // Gravity follows them (physicsScaleFor): at 9.81 a 1 m box's 8 cm blades lay flat within
    // seconds of play, and a 60 km sphere's 3 km blades stood rigid.
    project.physics.gravity.w *= physicsScaleFor(layer.scatter.blade);
    // Billboards follow the field's size too: the default density per m² on a large mesh (a
    // model in millimetres) asked for millions of them, refused in terms of a setting the user
    // of --mesh never gave. One billboard per 16 blades at most.
    // Distances follow it as well: at the default 100 m a kilometre-wide terrain seen whole
    // would thin to nothing, and its blades would all draw at the lowest detail.
    // Both within what project.json takes (100 km).
    project.render.thinningDistanceM =
        std::clamp(4.0f * diagonal, project.render.thinningDistanceM,
                   std::max(project.render.thinningDistanceM, MAX_CAMERA_DISTANCE_M));
    project.render.lodDistanceM =
        std::clamp(0.5f * diagonal, project.render.lodDistanceM,
                   std::max(project.render.lodDistanceM, MAX_CAMERA_DISTANCE_M));
    StarBillboardParams& billboards = project.billboards.placement;
    billboards.density = std::min(
        billboards.density, static_cast<float>(static_cast<double>(targetBlades) / 16.0 / area));

    // The bulk of the surface, filling most of the picture at the project's aspect.
    const float aspect = float(project.render.width) / float(std::max(project.render.height, 1));
    const OrbitCamera framed = frameSurface(mesh, aspect);
    CameraDesc& camera = project.cameras.front();
    camera.name = "framed";
    camera.position = framed.position();
    camera.target = framed.target;
    camera.fovYDeg = 45.0f;
    return loaded;
}

float regrowthStepS(const LayerSource& source) {
    return source.regrowRate > 0.0f ? REGROWTH_STEP_SHARE / source.regrowRate : 0.0f;
}

RegrowReport regrowCut(LayerField& layer, float timeS) {
    RegrowReport report;
    LayerSource& source = layer.source;
    if (source.maps.cut.texels.empty() || !(source.regrowRate > 0.0f))
        return report;
    // In whole steps of REGROWTH_STEP_SHARE of a blade's height: a frame between steps changes
    // nothing, and no blade ever waits more than a step.
    const float step = regrowthStepS(source);
    const float due = std::floor(std::max(timeS, 0.0f) / step) * step;
    if (due == source.regrowthS)
        return report;
    const float before = source.regrowthS;
    source.regrowthS = due;
    // The patches holding a blade cut below full height at either time.
    const std::uint32_t size = layer.patched.patchSize;
    const float lowest = std::min(before, due) * source.regrowRate;
    for (std::uint32_t p = 0; p < layer.patched.patches.size(); ++p)
        for (std::size_t slot = std::size_t(p) * size; slot < std::size_t(p + 1) * size; ++slot) {
            const std::uint32_t candidate = layer.patched.sourceIndex[slot];
            if (candidate != UINT32_MAX &&
                source.maps.cut.sample(source.candidates.uvs[candidate]) + lowest < 1.0f) {
                report.patches.push_back(p);
                break;
            }
        }
    regrowPatches(source, report.patches, layer);
    restoreWilt(layer, report.patches);
    report.shadedPatches = report.patches;
    return report;
}

}  // namespace grass::core
