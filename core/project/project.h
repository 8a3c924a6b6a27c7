// Project: everything a grass scene is, as stored in projects/<name>/project.json (issue 3,
// SPEC §12). A versioned JSON document: {"format": "grass-project", "version": 1, ...}. Asset
// paths are relative to the project folder and may not leave it. Load validates every field
// and names the file, the JSON path and the problem; save is atomic; load → save → load gives
// an identical document. Field reference: docs/project-format.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "billboard/star_billboards.h"
#include "blade/blade_shape.h"
#include "growth/growth_curves.h"
#include "mesh/mesh_frame.h"
#include "mesh/procedural.h"
#include "physics/physics.h"
#include "scatter/scatter.h"
#include "snow/snow_params.h"
#include "util/result.h"

namespace grass::core {

// Raised with every change to what project.json holds or accepts; older files are raised to it
// as they are read (project_migration.h). 2: the limits of issue 22 (steps, blade sizes, lists).
inline constexpr int PROJECT_FORMAT_VERSION = 3;

// Lists a project may hold (docs/project-format.md "Limits"): every frame draws each layer and
// every physics step visits each wind source and collider, so beyond these nothing runs at an
// interactive rate; no scene of ours uses more than 4.
inline constexpr std::size_t MAX_LAYERS = 256;
inline constexpr std::size_t MAX_CAMERAS = 256;
inline constexpr std::size_t MAX_WIND_SOURCES = 256;
inline constexpr std::size_t MAX_COLLIDERS = 256;
// Blades up to 100 m tall and 10 m wide (ours are 0.15-0.9 m): far beyond, the float positions
// of a blade's control points lose the bits its length is kept to (1e30 broke it by 100 %).
inline constexpr float MAX_BLADE_HEIGHT_M = 100.0f;
inline constexpr float MAX_BLADE_WIDTH_M = 10.0f;
// Camera distances (the LOD and thinning distances) beyond 100 km are typos, and push the LOD
// bands out of float range.
inline constexpr float MAX_CAMERA_DISTANCE_M = 1e5f;

// Where the surface comes from: a procedural shape by name, or a glTF file.
struct MeshSource {
    bool isFile = false;
    std::string file;                 // relative to the project folder (when isFile)
    ProceduralMeshParams procedural;  // (when !isFile)
    // The file's units and up axis (when isFile; mesh_frame.h): "unit", "up".
    float metresPerUnit = 1.0f;
    UpAxis up = UpAxis::Y;
    // The UVs grass maps are painted in, when the file's cannot be (missing or overlapping):
    // a generated atlas kept next to the project (core/mesh/uv_atlas_file.h); "" until a save
    // writes one.
    std::string uvAtlas;
    // The surface is drawn (and exported) in the file's own material, its base colour and
    // base-colour texture (scene/surface_look.h); false: in the project's ground colour, as a
    // procedural surface is (a file whose default white material shows between the blades).
    bool fileMaterial = true;
    bool operator==(const MeshSource&) const = default;
};

// Kim & Cho's growth model on a layer (SPEC §9): the soil and light maps, through the control
// curves, set every blade's height, width, rest lean and colour. Off by default: a layer
// without it keeps the blade ranges as they are (the curves at g = l = 1 would still shorten
// and lean every blade).
struct GrowthDesc {
    bool enabled = false;
    GrowthCurves curves;
    // Levels of the stem sets the growth technique draws (1..4).
    int levels = 4;
    // The width of a stem set's stems at their tips as a share of their root width: 0 narrows
    // each to a point (ours), 1 is the paper's constant-width strip (core::stemRibbon).
    float stemTipWidth = 0.0f;
    // The colours of grass in poor conditions (b = 0), linear RGB; rootColor/tipColor of the
    // layer are the healthy ones (b = 1). Straw-like by default.
    glm::vec3 poorRootColor{0.30f, 0.24f, 0.08f};
    glm::vec3 poorTipColor{0.72f, 0.62f, 0.30f};
    bool operator==(const GrowthDesc&) const = default;
};

// Where a layer may grow, besides its painted density map (issue 27). Every rule gives each
// candidate blade a factor in [0, 1] and the candidate lives where keep < map(uv) · factor, so
// rules combine with the maps and, like them, only remove blades. Names match a glTF node (or
// any node above it), mesh or material by its name ("node 3" for an unnamed one, as the
// editor's checklist shows it).
struct PlacementRules {
    std::vector<std::string> include;  // empty: the whole surface
    std::vector<std::string> exclude;  // wins over include
    // The angle between the surface and the ground plane (0 flat, 90 a wall), measured against
    // gravity (its direction, or the centre a planet's grass leans from); soft: degrees outside
    // the window over which the factor falls from 1 to 0.
    float slopeMinDeg = 0.0f;
    float slopeMaxDeg = 180.0f;
    float slopeSoftDeg = 0.0f;
    // Height along "up" (for centre gravity: distance from the centre), metres.
    float altitudeMinM = -1.0e6f;
    float altitudeMaxM = 1.0e6f;
    float altitudeSoftM = 0.0f;
    // No grass within this distance of the colliders (at time 0) and of the surfaces of the
    // parts named in clearOf.
    float clearanceM = 0.0f;
    bool clearColliders = false;
    std::vector<std::string> clearOf;
    bool operator==(const PlacementRules&) const = default;
};

// Bending cues (SPEC §10, article 003 "the bend of grass"): how a layer's blades lean at rest
// besides the growth model's lean. Grass on steep ground bends downhill, grass among tall,
// dense neighbours grows sideways towards the light, and a blade that grows sideways sways more
// easily. All off by default: a layer without them grows exactly as before
// (core/scene/bending_cues.h has the formulas).
// Below a centimetre the neighbour kernel covers no neighbour in any field we can grow; above
// ten metres it blurs a whole scene's density into one value.
inline constexpr double MIN_BENDING_RADIUS_M = 0.01;
inline constexpr double MAX_BENDING_RADIUS_M = 10.0;
struct BendingCues {
    // Rest lean downhill as a share of the slope (0.5: a 40° slope leans its blades 20°); the
    // slope is measured against gravity, as the placement rules measure it.
    float slope = 0.0f;
    // Rest lean, in degrees, of a blade fully shaded by taller, denser neighbours (towards its
    // front); a blade alone does not lean.
    float neighboursDeg = 0.0f;
    // Gaussian σ (metres) over which neighbours count.
    float neighbourRadiusM = 0.15f;
    // How much a leaning blade's stiffness drops: s·(1 − sway·sin(lean)).
    float sway = 0.0f;
    bool operator==(const BendingCues&) const = default;
};

// Every map of a layer is resampled to this size when loaded and created at it when painted.
inline constexpr int DEFAULT_MAP_RESOLUTION = 512;
inline constexpr int MAX_MAP_RESOLUTION = 8192;

struct GrassLayer {
    std::string name = "grass";
    ScatterParams scatter;
    // Environment maps in the mesh's UV space, relative paths; empty = 1 everywhere. Density
    // thins the scatter; soil quality g and light amount l drive the growth model.
    std::string densityMap;
    std::string soilMap;
    std::string lightMap;
    // Cut and regrow (issue 30 item 10): the height blades are cut to, as a share of their own
    // (1 uncut, 0 mown to the ground), regrowing by regrowRate of their height a second of
    // scene time.
    std::string cutMap;
    float regrowRate = 0.0f;
    glm::ivec2 mapResolution{DEFAULT_MAP_RESOLUTION, DEFAULT_MAP_RESOLUTION};
    GrowthDesc growth;
    PlacementRules rules;
    BendingCues bending;
    // Outline of every blade of the layer (SPEC §7); triangle is what files without the key got
    // before shapes were per layer.
    BladeShape shape = BladeShape::Triangle;
    // τ of the triangle-tip shape: the height (0 root, 1 tip) where the blade starts to narrow;
    // in [0, 1). Other shapes ignore it.
    float tipStart = 0.5f;
    glm::vec3 rootColor{0.10f, 0.28f, 0.05f};  // linear RGB
    glm::vec3 tipColor{0.45f, 0.70f, 0.20f};
    bool operator==(const GrassLayer&) const = default;
};

struct CameraDesc {
    std::string name = "default";
    glm::vec3 position{8.0f, 5.0f, 8.0f};
    glm::vec3 target{0.0f};
    float fovYDeg = 45.0f;
    bool operator==(const CameraDesc&) const = default;
};

struct SunDesc {
    glm::vec3 direction{-0.4f, -1.0f, -0.3f};  // direction the light travels (normalized on use)
    glm::vec3 color{1.0f, 0.96f, 0.88f};
    float intensity = 1.0f;
    // Shadows of the surface and the colliders on the grass, the ground and the colliders
    // (a depth map along the sun, docs/rendering.md); off: no pass, no map, no lookups.
    bool shadows = false;
    int shadowResolution = 2048;  // texels a side of the sun's depth map
    bool operator==(const SunDesc&) const = default;
};

// How blades are lit: SPEC §10's grass model as we draw it, the foundation's wrapped Lambert
// (kept for comparison and for the lighting-off golden images), or article 003's model exactly
// as the article writes it (no N·L on the lobes, α = roughness², no clamp, no ambient;
// docs/rendering.md compares them).
enum class LightingModel { Grass, Simple, Article };

// Grass lighting of SPEC §10 (article 003). Colours are multipliers of the sun colour; distances
// are metres. The AO and blurred-normal terms are baked per blade when the scene is built.
struct GrassLightingDesc {
    LightingModel model = LightingModel::Grass;
    // Diffuse ramp: NL ∈ [−1, 0] maps low → mid, NL ∈ [0, 1] mid → high.
    glm::vec3 diffuseLow{0.18f, 0.20f, 0.16f};
    glm::vec3 diffuseMid{0.45f, 0.48f, 0.40f};
    glm::vec3 diffuseHigh{1.0f, 1.0f, 1.0f};
    // Diffuse normal: the blade normal leaned this far towards the (SSS) terrain normal; a
    // blade's own normal is nearly horizontal, so alone it paints a field in stripes.
    float terrainNormalWeight = 0.5f;
    float specular = 0.6f;                // weight of the GGX lobes
    glm::vec2 specularFadeM{0.5f, 6.0f};  // specular rises from 0 to full over these distances
    float transmission = 0.8f;            // I of SPEC §10
    float transmissionDistortion = 0.3f;  // k: fakeN = −normalize(mix(N, L, k))
    float transmissionPower = 4.0f;       // e
    float sss = 0.35f;                    // weight of the SSS term
    float sssIntensity = 0.7f;            // terrain normal → blurred terrain normal
    float aoRadiusM = 0.15f;              // Gaussian σ of the neighbour-density AO kernel
    float aoStrength = 0.007f;            // m² one neighbour occludes (Beer–Lambert)
    float aoFloor = 0.35f;                // darkest AO
    float normalBlurRadiusM = 0.75f;      // Gaussian σ of the terrain-normal blur
    // The bake's clustering cells in kernel σ (BladeShadingParams::cellSigmas); 0: exact sums.
    float aoCellSigmas = 0.5f;
    glm::vec2 water{0.15f, 0.6f};  // water of the oldest .. youngest blade
    bool operator==(const GrassLightingDesc&) const = default;
};

enum class GeometryPath { Auto, Tessellation, Strips };

// What draws the grass: the geometric blades (SPEC §6–7), star billboards alone (SPEC §8),
// blades near the camera cross-faded into billboards far away, or Kim & Cho's instanced stem
// sets (SPEC §9).
enum class GrassTechnique { Blades, Billboards, Hybrid, Growth };

// Star billboard grass objects (SPEC §8): the billboard technique and the hybrid's far field.
struct BillboardDesc {
    StarBillboardParams placement{30.0f, {0.3f, 0.5f}, 1.2f, 2.0f};
    // An RGBA image with alpha, relative to the project folder; empty: generated from the first
    // layer's colours.
    std::string texture;
    BillboardWindMode animation = BillboardWindMode::PerObject;
    BillboardWind wind;
    // Hybrid: over this camera distance the blades fade out and the billboards fade in.
    glm::vec2 crossFadeM{10.0f, 16.0f};
    bool operator==(const BillboardDesc&) const = default;
};

// Bytes of GPU frame buffers one render of width × height pixels takes: colour (RGBA8) and depth
// (32-bit float) per sample, the resolved colour, a depth texture and the read-back image
// (editor/gl/framebuffer.cpp). Project loading and `grass render` refuse renders above
// MAX_FRAMEBUFFER_BYTES before any buffer is made: 16384² at 2 samples fits, at 4 it does not.
double framebufferBytes(int width, int height, int msaaSamples);
inline constexpr double MAX_FRAMEBUFFER_BYTES = 8.0 * 1024.0 * 1024.0 * 1024.0;

struct RenderSettings {
    int width = 1280;
    int height = 720;
    GeometryPath geometry =
        GeometryPath::Auto;  // Auto: strips on software GL, tessellation on GPUs
    int tessLevel = 8;       // tessellation level along the blade (1..64)
    int stripSegments = 8;   // segments of an instanced strip (1..32)
    int msaaSamples = 4;     // 0, 1, 2, 4 or 8
    glm::vec3 skyColor{0.55f, 0.70f, 0.90f};
    glm::vec3 groundColor{0.30f, 0.24f, 0.16f};
    std::uint32_t patchSize = 256;  // blades per patch, a multiple of 32 (the cull work-group)
    GrassTechnique technique = GrassTechnique::Blades;
    // Level of detail (SPEC §7): full segments up to this camera distance, half to 3×, a quarter
    // beyond; 0 keeps every blade at full detail.
    float lodDistanceM = 8.0f;
    // Distance thinning (SPEC §6): the field thins in eighths out to this distance; 0 = off.
    float thinningDistanceM = 100.0f;
    bool operator==(const RenderSettings&) const = default;
};

// A wind source of SPEC §4 with the name the UI and the CLI select it by.
struct WindDesc {
    std::string name = "wind";
    WindSource source;
    bool operator==(const WindDesc&) const = default;
};

enum class ColliderShape { Sphere, Mesh };

// A collider (SPEC §5): a sphere, or a glTF mesh packed into `sphereCount` spheres (cached next
// to the project). `position` places the sphere centre or the mesh origin; `path`, when not
// empty, moves it over time instead.
struct ColliderDesc {
    std::string name = "collider";
    ColliderShape shape = ColliderShape::Sphere;
    glm::vec3 position{0.0f};
    float radiusM = 0.5f;                  // sphere
    std::string file;                      // mesh: relative .gltf/.glb path
    float scale = 1.0f;                    // mesh: uniform scale of the file's coordinates
    std::uint32_t sphereCount = 32;        // mesh: spheres to pack it into
    std::uint32_t packingResolution = 64;  // mesh: voxels along the longest side when packing
    std::vector<PathKey> path;
    // Linear RGB the prop is drawn with; unset: grey for spheres, stone for meshes.
    std::optional<glm::vec3> color;
    bool operator==(const ColliderDesc&) const = default;
};

struct Project {
    std::string name = "untitled";
    std::uint64_t seed = 1;
    MeshSource mesh;
    std::vector<GrassLayer> layers{GrassLayer{}};
    std::vector<CameraDesc> cameras{CameraDesc{}};
    SunDesc sun;
    GrassLightingDesc lighting;
    RenderSettings render;
    BillboardDesc billboards;
    // Physics: gravity and the integration policy (dtS is the simulation step), wind, colliders.
    PhysicsParams physics;
    std::vector<WindDesc> wind;
    std::vector<ColliderDesc> colliders;
    // Snow accumulation (SPEC §11); off by default, so files without "snow" stay snow-free.
    SnowParams snow;
    bool operator==(const Project&) const = default;
};

std::string_view geometryPathName(GeometryPath path);
// "blades" | "billboards" | "hybrid" | "growth"
std::string_view grassTechniqueName(GrassTechnique technique);
Result<GrassTechnique> parseGrassTechnique(std::string_view name);
// "per-cluster" | "per-vertex" | "per-object"
std::string_view billboardAnimationName(BillboardWindMode mode);
Result<BillboardWindMode> parseBillboardAnimation(std::string_view name);
Result<GeometryPath> parseGeometryPath(std::string_view name);  // "auto" | "tess" | "strips"

// Load: `path` is a project folder (reads path/project.json) or a .json file. Temporaries that a
// killed save left in the project's folders (removeStaleTemporaries) are removed.
// On success, `folder` receives the folder assets are relative to.
struct LoadedProject {
    Project project;
    std::filesystem::path folder;
    std::filesystem::path file;
    // The digest of `file`'s bytes as read (util/content_digest.h), or as the editor last wrote
    // them: its Save asks before replacing a file another program has changed since.
    std::optional<std::uint64_t> fileDigest = std::nullopt;
};
Result<LoadedProject> loadProject(const std::filesystem::path& path);

// Parses a document already in memory; `sourceName` names it in errors.
Result<Project> parseProject(std::string_view jsonText, const std::string& sourceName);
// The full document (every field, defaults included), 2-space indented, newline-terminated.
std::string serializeProject(const Project& project);
// Atomic save to a .json file.
Result<void> saveProject(const Project& project, const std::filesystem::path& file);
// What saveProject refuses before it writes anything (a folder or a name without .json, a value
// the loader would refuse): for a save that copies files first, so that a refused save leaves
// no half-made project folder behind.
Result<void> checkProjectSaves(const Project& project, const std::filesystem::path& file);

// Every file the project names (mesh, maps, billboard texture, collider meshes), as written:
// relative to the project folder, each once, in document order. What "Save As" to another
// folder must bring along.
std::vector<std::string> projectAssetPaths(const Project& project);

// A name kept to characters safe in any file system (letters, digits, '-', '_'; anything else
// becomes '_'), so it never forms ".." or a path; "layer" when empty.
std::string fileSafeName(const std::string& name);
// Where a layer's painted map goes when the layer names none yet: maps/<layer>-<map>.png.
std::string defaultMapFile(const std::string& layerName, std::string_view mapName);

// Resolves an asset path relative to the project folder; refuses absolute paths and paths that
// leave the folder (".."), naming the JSON field.
Result<std::filesystem::path> resolveAssetPath(const std::filesystem::path& folder,
                                               const std::string& relative,
                                               const std::string& fieldPath);

}  // namespace grass::core
