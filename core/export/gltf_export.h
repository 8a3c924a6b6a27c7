// One grass layer as a glTF 2.0 document (.gltf JSON + one .bin buffer + the maps as PNG files
// next to it), for engines and DCC tools:
//   node "terrain": the project's surface (POSITION, NORMAL, TEXCOORD_0, uint32 indices);
//   node "<layer> blades": the unit blade mesh (POSITION, NORMAL; blade_instances.h) drawn once
//     per blade through EXT_mesh_gpu_instancing: TRANSLATION, ROTATION, SCALE and the custom
//     per-instance attributes _STIFFNESS (SCALAR), _COLOR (VEC3, tip colour), _ROOT_COLOR
//     (VEC3), _TIP_OFFSET (VEC3, v2 − v0 in metres);
//   images/textures "density", "soil", "light": the layer's painted maps in the terrain's UV
//     space. They are data, not material inputs, so no material uses them: validators report
//     them as unused (information, not a warning).
// Metres, +Y up, right-handed, as glTF itself.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "export/source_material.h"
#include "scene/scene.h"

namespace grass::core {

// A map PNG written next to the .gltf: which map ("density", "soil", "light") and its file name.
struct GltfMapImage {
    std::string map;
    std::string uri;
    std::string png;  // the PNG's bytes, embedded instead of the uri when not empty (.glb)
};

struct GltfLayerDocument {
    std::string json;
    std::string binary;
    std::string binUri;  // content-addressed: "<binStem>-<hash>.bin" (content_names.h)
    std::size_t instances = 0;
};

struct GltfLayerInput {
    const Scene* scene = nullptr;
    std::size_t layer = 0;
    int lod = 0;
    // Segments along the unit blade (the project's strip segments, 1..32).
    int segments = 8;
    glm::vec3 groundColor{0.3f, 0.24f, 0.16f};
    // The source mesh's material and textures (source_material.h); a null material: the
    // ground colour.
    SourceMaterial terrainMaterial;
    // The buffer's file is named "<binStem>-<hash of its bytes>.bin" (content_names.h).
    std::string binStem;
    std::vector<GltfMapImage> maps;
    // The scene's behaviour for runtimes (runtime_block.h), written as the glTF scene's
    // extras.grass_runtime; null: none.
    nlohmann::json runtime;
};

GltfLayerDocument buildLayerGltf(const GltfLayerInput& input);

// Every layer in one binary glTF (`--format glb`, issue 25): one terrain shared by the layers,
// each layer's "<layer> blades" group as above, the maps embedded as PNG images named
// "<layer> density" etc.
struct GltfSceneInput {
    const Scene* scene = nullptr;
    std::string name;  // the glTF scene's name: the project's
    int lod = 0;
    int segments = 8;
    glm::vec3 groundColor{0.3f, 0.24f, 0.16f};
    SourceMaterial terrainMaterial;  // as GltfLayerInput's
    std::vector<std::vector<GltfMapImage>> layerMaps;  // per layer, with their PNG bytes
    // The blades baked into plain meshes per cell (merged_blades.h, --format mesh) instead of
    // instances.
    bool merged = false;
    nlohmann::json runtime;  // as GltfLayerInput's
};

struct GltfSceneDocument {
    std::string glb;
    std::vector<std::size_t> instances;  // per layer
};

GltfSceneDocument buildSceneGlb(const GltfSceneInput& input);

// The unit blade of `shape` (SPEC §7) as triangles: rows at the Bézier parameter v = i/segments
// of the resting blade of height 1 leaned by `leanRad` towards −Z (blade_instances.h; a
// straight blade's row is at height 2v − v², v1 = v2 at rest, blade.h), edges at
// x = 2·t(u, v) − 1 for u = 0, 1 (shaders/include/shapes.glsl), normals tangent × +X (−Z when
// straight).
struct UnitBladeMesh {
    std::vector<float> positions;  // xyz per vertex
    std::vector<float> normals;
    std::vector<float> heights;    // v per vertex: 0 at the root, 1 at the tip
    std::vector<std::uint32_t> indices;
};
UnitBladeMesh unitBladeMesh(BladeShape shape, float tipStart, int segments, float leanRad = 0.0f);

}  // namespace grass::core
