// Scene: what a project becomes once its files are read and its grass grown: the surface mesh
// and, per grass layer, the patched blades ready for the GPU. The CLI and the editor both build
// scenes through buildScene, so they show the same field (ARCHITECTURE.md).
#pragma once

#include <functional>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "billboard/grass_texture.h"
#include "billboard/star_billboards.h"
#include "mesh/surface_mesh.h"
#include "scene/billboard_follow.h"
#include "scene/blade_shading.h"
#include "scene/layer_growth.h"
#include "scene/paint_uvs.h"
#include "scene/scene_props.h"
#include "scene/surface_look.h"
#include "project/project.h"
#include "scatter/patches.h"

namespace grass::core {

// A grown layer (layer_growth.h: patched blades, wilt, stem sets, live count) with what draws it
// and what it was grown from.
struct LayerField : GrownField {
    std::string name;
    LayerSource source;
    std::uint64_t seed = 0;  // the layer's stream: scatter and shading bake
    glm::vec3 rootColor{0.0f};
    glm::vec3 tipColor{0.0f};
    // The colours of poor conditions (wilt 1), growth model (SPEC §9).
    glm::vec3 poorRootColor{0.0f};
    glm::vec3 poorTipColor{0.0f};
    // The layer's blade outline and triangle-tip τ (SPEC §7), for the blade shaders.
    BladeShape shape = BladeShape::Triangle;
    float tipStart = 0.5f;
    // Lighting inputs baked per blade slot (SPEC §10), index for index with patched.blades;
    // waterAge.z holds the slot's wilt.
    std::vector<BladeShading> shading;
};

// What placing the billboards takes besides the scene's mesh and layers: kept by a scene whose
// technique does not draw them, so they are placed only once something draws them
// (placeBillboards). A field drawn by blades alone paid for a sampler pass over its mesh and
// ~100 bytes a billboard it never drew; a 1 km² terrain at the default density asked for 30
// million and was refused for them.
struct BillboardRecipe {
    StarBillboardParams placement;
    std::uint64_t seed = 0;
    std::vector<PlacementRules> rules;  // the layers', in order
    RuleWorld world;
    std::string projectFile;  // names the project in a refusal
};

// The star billboard grass objects of SPEC §8 and their texture: the billboard technique and
// the hybrid's far field (project "billboards").
struct BillboardLayer {
    std::vector<GrassObject> placed;   // every object placement made, before the layers speak
    BillboardFollow follow;            // what of the layers does not change with painting
    std::vector<GrassObject> objects;  // the ones drawn: followLayers(placed, follow, layers)
    Rgba8Pixels texture;
    std::optional<BillboardRecipe> unplaced;  // until placeBillboards has placed them
};

struct Scene {
    MovableSurfaceMesh mesh;
    Bounds bounds;
    double area = 0.0;
    std::vector<LayerField> layers;
    std::vector<SceneProp> props;    // the colliders, drawn as opaque objects
    BillboardLayer billboards;
    std::vector<std::string> notes;  // warnings from loading (mesh notes, map conversions)
    SurfaceLook look;                // the surface's own material (a glTF file's)
    PaintUvs paintUvs;               // how its UV0 became paintable (paint_uvs.h)
    // The ground file's point (its units and axes) that the scene's (0, 0, 0) stands for: zero
    // unless a ground far from its file's origin was moved next to grass's (GltfPlacement::
    // GroundNearOrigin). Exports carry it, so a host can put the field back where the file was.
    glm::dvec3 groundOrigin{0.0};
    std::size_t totalBlades() const;
};

// The colours, blade shape and tip of `layer`, which the renderer reads from the grown field
// every frame: a change to them needs no growing.
void takeLayerLook(LayerField& field, const GrassLayer& layer);
// Each grown layer takes its project layer's name and look (takeLayerLook), index for index:
// after an undo of a step that grew nothing (a colour, a shape, a rename).
void takeLayerLooks(Scene& scene, const Project& project);

// The most blades one scene may hold: with the CPU copies, the GPU copy and the physics state,
// sceneBytesPerBlade() each (296 bytes), 20 million is ~5.5 GiB; far beyond that a typo in a
// density would freeze the machine instead of failing. buildScene refuses more up front, naming
// the layer, the blade count and the memory it would need.
inline constexpr double MAX_SCENE_BLADES = 20.0e6;
std::size_t sceneBytesPerBlade();
// The most star billboards (SPEC §8) one scene may hold: ~0.3 kB each with their star instance
// (1.7 kB before the stars were drawn instanced), so ~0.6 GiB; 1000 /m² (the density limit) on
// 2000 m² of surface.
inline constexpr double MAX_SCENE_BILLBOARDS = 2.0e6;
std::size_t sceneBytesPerBillboard();

// Upper estimate of the blades a layer grows on `area` m²: uniform density × area plus, for
// clumps, the densest Poisson-disk packing (hexagonal, 2/(√3·spacing²) centres per m²).
double estimateLayerBlades(const ScatterParams& params, double area);

// Whether a technique draws the star billboards (the billboard technique, the hybrid's far field).
bool drawsBillboards(GrassTechnique technique);

// The texture of the project's billboards: its file, or one generated from the first layer's
// colours; errors name the file.
Result<Rgba8Pixels> billboardTexture(const LoadedProject& loaded);

// The billboards a scene kept unplaced (BillboardLayer::unplaced), placed on its mesh and
// following its layers (billboard_follow.h), with its texture; the scene's own when they are
// placed already. More than MAX_SCENE_BILLBOARDS are refused, naming the project's
// /billboards/density. A renderer asked to draw billboards a scene kept unplaced places them so.
Result<BillboardLayer> placedBillboards(const Scene& scene);
// The same without the objects that follow the layers' maps (BillboardLayer::objects, left
// empty: followLayers makes them). It reads the mesh, the layers' candidates and the rules, none
// of which painting changes, so a worker may run it while the maps are painted (the editor does:
// the 1.66 million billboards of an 8.4-million-triangle ground take 1.5 s to place).
// `stop`: a request ends the placing between its stages with an error (a renderer let go of
// while its worker places them need not wait for the rest).
Result<BillboardLayer> placedBillboardsUnfollowed(const Scene& scene, std::stop_token stop = {});
// The same, into the scene: buildScene does it at once when the project's technique draws them.
Result<void> placeBillboards(Scene& scene);

// After a layer's maps changed (a repaint, an undo): which billboards live, how tall and how
// tinted, from the layers' maps now (billboard_follow.h). The placements and rule factors stay.
void refreshBillboards(Scene& scene);

// The bake parameters of a project's lighting (AO kernel, normal blur, water range).
BladeShadingParams bladeShadingParams(const GrassLightingDesc& lighting);

// What a build is doing now, for a window that shows it (the editor's loading box): "reading
// ground.glb", "checking the UVs of ground.glb", "growing layer \"grass\" (1 of 2)", "placing
// the billboards". Called on the building thread, at the start of each stage.
using BuildProgress = std::function<void(const std::string& stage)>;

// Loads the mesh (file or procedural), each layer's density map, scatters, patches and bakes
// the per-blade lighting inputs.
// Errors name the file (mesh, map) or the project field. `alreadyRead`: as loadProjectMesh's.
// `stop`: a request ends the growing between its stages (buildStopped says so): the editor
// stops a re-grow that a later edit makes useless, and a load the user cancels.
Result<Scene> buildScene(const LoadedProject& project, GltfImport* alreadyRead = nullptr,
                         std::stop_token stop = {}, const BuildProgress& progress = {});
// The error of a build ended by its stop token.
Error buildStopped(const LoadedProject& project);

// What a repaint re-grew: the patches whose slots changed (renderers re-upload those) and the
// patches whose shading changed (the regrown ones, whose wilt moved, and, when blades were
// added or removed, every patch with a blade in the re-baked region).
struct RegrowReport {
    std::vector<std::uint32_t> patches;
    std::vector<std::uint32_t> shadedPatches;
    std::size_t bladesAddedOrRemoved = 0;
    Bounds shadedRegion;  // where the AO and blurred normals were re-baked (when rebakedBlades > 0)
    std::size_t rebakedBlades = 0;
    // ShadingUpdate::RegrownOnly: where the neighbours' shading still awaits the exact re-bake
    // (when shadingPending).
    bool shadingPending = false;
    Bounds pendingShadeRegion;
};

// How a re-grow that added or removed blades updates the shading (AO, blurred normal).
enum class ShadingUpdate {
    // Every blade whose kernels reach a regrown patch is re-baked: the result equals a re-bake
    // of the whole neighbourhood (127-335 ms for a density dab on a 1M-blade field).
    Exact,
    // Only the regrown patches' blades are baked (against their current neighbours); the
    // neighbours keep their values until an Exact re-bake of pendingShadeRegion (the brush does
    // it at the end of the stroke, issue 24). A dab then costs what its own patches cost.
    RegrownOnly,
};

// What the placement rules measure against: the project's gravity and the colliders' surfaces
// (`props`, placed as the project's colliders stand) at time 0.
RuleWorld ruleWorldOf(const Project& project, const std::vector<SceneProp>& props);

// After layer.source.maps changed inside `painted` (a box on the surface, e.g. a brush stroke's
// touched texels): re-grows the patches with a root within `texelMarginM` of it (a texel's
// bilinear footprint on the surface) and, when that added or removed blades (density paints),
// re-bakes the shading of the blades whose AO or blurred normal can see them. Everything else in
// the layer keeps its bits.
Result<RegrowReport> regrowLayerRegion(LayerField& layer, const Bounds& painted, float texelMarginM,
                                       const GrassLightingDesc& lighting,
                                       ShadingUpdate update = ShadingUpdate::Exact);
// The same for the patches `patches` (indices into layer.patched.patches, sorted, unique).
Result<RegrowReport> regrowLayerPatches(LayerField& layer, std::vector<std::uint32_t> patches,
                                        const GrassLightingDesc& lighting,
                                        ShadingUpdate update = ShadingUpdate::Exact);

// Cut and regrow (issue 30 item 10): at scene time timeS the layer's cut blades have grown back
// by regrowRate·timeS of their height, in steps of REGROWTH_STEP_SHARE; re-grows the patches
// holding cut blades when a step is due (only those: the report lists them for the renderers)
// and nothing otherwise. Without a cut map or a regrow rate, nothing.
inline constexpr float REGROWTH_STEP_SHARE = 0.01f;
float regrowthStepS(const LayerSource& source);
RegrowReport regrowCut(LayerField& layer, float timeS);

// The exact re-bake of `region`'s neighbourhood that RegrownOnly re-grows left pending: the
// shading of every blade within reach of `region` (3σ of the kernels); reports the patches to
// re-upload.
Result<RegrowReport> rebakeLayerShading(LayerField& layer, const Bounds& region,
                                        const GrassLightingDesc& lighting);

// The mesh of a project alone (no grass), for `render --mesh` and mesh-info. `look`, when given,
// gets the surface's own material (surface_look.h; nothing for a procedural surface).
// `paintUvs`, when given, gets how the surface's UVs were made paintable (paint_uvs.h);
// `groundOrigin` the file's point the mesh's origin stands for (Scene::groundOrigin).
// `alreadyRead`, when given, is the project's mesh file as loadGltf read it for the project
// (GltfPlacement::GroundNearOrigin, the project's unit): taken instead of reading the file again
// (a new project around a mesh has just read it to size the field; an 8-million-triangle ground
// takes seconds to read). `stop`: a request ends the read (loadGltf's) or the making of paintable
// UVs at their next look at it, with buildStopped's error.
Result<MovableSurfaceMesh> loadProjectMesh(
    const LoadedProject& project, std::vector<std::string>* notes, SurfaceLook* look = nullptr,
    PaintUvs* paintUvs = nullptr, glm::dvec3* groundOrigin = nullptr,
    GltfImport* alreadyRead = nullptr, std::stop_token stop = {},
    const BuildProgress& progress = {});

// The ground origin buildScene would find (Scene::groundOrigin), for a command that builds the
// physics before its scene: the ground file is loaded only when a mesh collider may need it.
glm::dvec3 groundOriginOf(const LoadedProject& project);

// Grows the layers of `project` on a mesh already loaded (so a file is read once);
// `groundOrigin` is loadProjectMesh's (the mesh colliders in a moved ground's frame follow it).
Result<Scene> buildSceneFromMesh(const LoadedProject& project, MovableSurfaceMesh mesh,
                                 std::vector<std::string> notes,
                                 glm::dvec3 groundOrigin = glm::dvec3(0.0),
                                 std::stop_token stop = {}, const BuildProgress& progress = {});

// Whether `next` grows on the surface the scene of `built` stands on: the same folder, mesh
// source (file, unit, up axis, kept UV atlas, or procedural shape) and coarsest layer map (the
// side a generated UV atlas keeps its gutters for).
bool sameSurface(const LoadedProject& built, const LoadedProject& next);

// Grows `project` on the surface of `previous` (built from a project of the sameSurface): what
// buildScene gives, without reading the mesh again. The mesh is shared, not copied
// (MovableSurfaceMesh::shared), its material, paintable UVs and ground origin carried over; the
// mesh's notes are not repeated. The editor re-grows so after each edit of the layers: an
// 8-million-triangle ground took seconds to read each time.
Result<Scene> regrowOnSameSurface(const LoadedProject& project, const Scene& previous,
                                  std::stop_token stop = {}, const BuildProgress& progress = {});

// How much a force must be scaled for blades of `blade`'s size to bend as the default blades
// (BladeRanges{}) do under it: their mean height over the default's. The physics is a
// displacement-rate model (SPEC §3, core/physics/physics.h): a force F holds a blade of
// stiffness k about F/k metres off its rest tip whatever the blade's height, so the same
// gravity lays short blades flat and leaves tall ones rigid.
float physicsScaleFor(const BladeRanges& blade);

// A default project growing grass on a loaded glTF file: density scaled so the field has about
// `targetBlades` blades whatever the file's units, blade size relative to the mesh, gravity
// scaled with the blades (physicsScaleFor) so they droop as the default field's do, and a
// camera framing its bounds (issue 3: `grass render --mesh`). Every value within what
// project.json takes (blades at most MAX_BLADE_HEIGHT_M tall: said in `notes`, when given, as
// the mesh's notes are, without the file's name). Null when the mesh has no area.
Result<LoadedProject> projectForMesh(const std::filesystem::path& meshFile, const SurfaceMesh& mesh,
                                     std::size_t targetBlades,
                                     std::vector<std::string>* notes = nullptr);

}  // namespace grass::core
