// The scene's behaviour for runtimes (issue 28): what a field needs besides its blades to sway,
// react and look as in the editor. The raw export writes it as manifest.json's "runtime" object
// and the meshes it names as files; the reference runtime (editor/runtime) reads nothing else.
//   physics    the step, gravity and the constants of SPEC §3–5 (core::PhysicsParams)
//   wind       every wind source with its path (core::WindSource)
//   spheres    the colliders' spheres as the physics sees them (core::SphereCollider: a packed
//              mesh's spheres, each with its own path and the group's broad phase)
//   colliders  one entry per project collider: its origin and path, which spheres it moves and
//              which mesh draws it, so a host can move a collider as a whole
//   lighting   the frame's LightingBlock (core/scene/lighting_block.h), value by value
//   render     geometry path, segments, LOD and thinning distances, sky colour, MSAA
//   camera     the project's first camera
//   meshes     the terrain (first) and the collider props: 32-byte vertices (position, normal,
//              uv; float32) then uint32 triangle indices, in one little-endian file each
// Versioned ("version"): a runtime refuses a version it does not know. docs/runtime.md.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "project/project.h"
#include "scene/scene.h"
#include "scene/scene_physics.h"

namespace grass::core {

inline constexpr int RUNTIME_BLOCK_VERSION = 1;
inline constexpr std::size_t RUNTIME_MESH_VERTEX_STRIDE = 32;

// One mesh of the block: its bytes (vertices, then indices) and what the manifest says of it.
struct RuntimeMeshFile {
    std::string name;  // "terrain", or the collider's name
    std::string bytes;
    std::size_t vertexCount = 0;
    std::size_t indexCount = 0;
    glm::vec3 albedo{0.6f};
};

// The terrain and every prop, in that order.
std::vector<RuntimeMeshFile> runtimeMeshes(const LoadedProject& loaded, const Scene& scene);

// The block, with meshes[i] written to meshFiles[i] (the caller names and stages the files).
nlohmann::json runtimeBlock(const LoadedProject& loaded, const Scene& scene,
                            const ScenePhysics& physics, const std::vector<RuntimeMeshFile>& meshes,
                            const std::vector<std::string>& meshFiles);

// What the block leaves behind for this project (snow, billboards, a surface texture), one line
// each: the export reports them as notes.
std::vector<std::string> runtimeBlockGaps(const LoadedProject& loaded, const Scene& scene);

}  // namespace grass::core
