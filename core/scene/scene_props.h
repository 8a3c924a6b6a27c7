// Props: the project's colliders as the user sees them (SPEC §5): a sphere collider is a ball,
// a mesh collider its glTF mesh, both moving along their path. The renderer draws them with
// the terrain as opaque objects, so they also occlude grass in the cull pass (SPEC §6). The
// physics never reads these meshes: it collides with the packed spheres (scene_physics.h).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/gltf_loader.h"
#include "mesh/surface_mesh.h"
#include "physics/wind.h"
#include "project/project.h"

namespace grass::core {

struct SceneProp {
    std::string name;
    MovableSurfaceMesh mesh;    // in the prop's own frame: unit sphere or the file's coordinates
    glm::vec3 position{0.0f};   // origin (sphere centre, mesh origin) when there is no path
    float scale = 1.0f;         // sphere radius, or the mesh collider's scale
    std::vector<PathKey> path;  // moves the origin over time, as the physics does
    glm::vec3 albedo{0.6f};     // linear RGB

    glm::vec3 originAt(float timeS) const { return samplePath(path, timeS, position); }
    // Model matrix at `timeS`: translate(origin) · scale.
    glm::mat4 modelAt(float timeS) const;
};

// The glTF file of mesh collider `index` (its path resolved in the project folder) and its mesh:
// what the props draw and the physics packs. Errors name the project field or the file. A mesh
// far from its file's origin is taken to share a moved ground's georeferenced frame
// (GltfPlacement::InGroundFrame): moved by minus `groundOrigin` (Scene::groundOrigin) and given
// the ground's unit and up axis, as the ground was; its collider's position and scale apply
// after that.
struct ColliderMesh {
    std::filesystem::path file;
    GltfImport imported;
};
// The glTF `file` (a path already resolved) read as a mesh collider of `project` is read: what
// loadColliderMesh reads, and what the editor reads before it adds a collider.
Result<GltfImport> readColliderMesh(const Project& project, const std::filesystem::path& file,
                                    glm::dvec3 groundOrigin = glm::dvec3(0.0));
Result<ColliderMesh> loadColliderMesh(const LoadedProject& loaded, const ColliderDesc& collider,
                                      std::size_t index, glm::dvec3 groundOrigin = glm::dvec3(0.0));

// Places `prop` (its mesh already made from `collider`) where `collider` stands, at its size,
// on its path, in its colour: what a prop takes from its collider besides the mesh, so a moved
// collider's prop follows it without its mesh read again (core::onlyMotionChanged).
void placeSceneProp(SceneProp& prop, const ColliderDesc& collider);

// One prop per collider, in project order; errors name the collider's file or field.
Result<std::vector<SceneProp>> loadSceneProps(const LoadedProject& loaded,
                                              glm::dvec3 groundOrigin = glm::dvec3(0.0));
// The same after colliders were added or deleted: `props`, made for the colliders `madeFor`,
// give up their meshes to the colliders of the same shape (and mesh file) in order, so only a
// new collider's mesh is made or read (the editor adding a ball reads no rock's file again).
// `readAhead`, when given, holds meshes already read by collider file (the editor's add mesh…
// reads its file on a worker): a new collider of such a file is given a copy, read no more.
Result<std::vector<SceneProp>> remakeSceneProps(
    const LoadedProject& loaded, std::vector<SceneProp> props,
    const std::vector<ColliderDesc>& madeFor, glm::dvec3 groundOrigin = glm::dvec3(0.0),
    const std::map<std::string, MovableSurfaceMesh>* readAhead = nullptr);

}  // namespace grass::core
