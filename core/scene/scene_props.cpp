#include "scene/scene_props.h"

#include <glm/gtc/matrix_transform.hpp>

#include "mesh/mesh_frame.h"
#include "mesh/procedural.h"

namespace grass::core {

namespace {
// A ball of 24 × 24 quads: round to the eye at the sizes colliders have (0.1–5 m on screen).
constexpr int SPHERE_RESOLUTION = 24;
// Stone grey for balls, pale fur for meshes: both read against green grass and brown soil.
constexpr glm::vec3 SPHERE_ALBEDO{0.55f, 0.53f, 0.50f};
constexpr glm::vec3 MESH_ALBEDO{0.72f, 0.68f, 0.62f};
}  // namespace

glm::mat4 SceneProp::modelAt(float timeS) const {
    return glm::scale(glm::translate(glm::mat4(1.0f), originAt(timeS)), glm::vec3(scale));
}

void placeSceneProp(SceneProp& prop, const ColliderDesc& collider) {
    const bool sphere = collider.shape == ColliderShape::Sphere;
    prop.name = collider.name;
    prop.position = collider.position;
    prop.path = collider.path;
    prop.scale = sphere ? collider.radiusM : collider.scale;
    prop.albedo = collider.color.value_or(sphere ? SPHERE_ALBEDO : MESH_ALBEDO);
}

Result<GltfImport> readColliderMesh(const Project& project, const std::filesystem::path& file,
                                    glm::dvec3 groundOrigin) {
    const MeshSource& ground = project.mesh;
    const double groundMetresPerUnit = ground.isFile ? ground.metresPerUnit : 1.0;
    auto imported = loadGltf(file, GltfPlacement::InGroundFrame, groundMetresPerUnit, groundOrigin);
    if (!imported)
        return imported.error();
    if (imported->origin != glm::dvec3(0.0))
        applyMeshFrame(imported->mesh, ground.metresPerUnit, ground.up);
    return imported;
}

Result<ColliderMesh> loadColliderMesh(const LoadedProject& loaded, const ColliderDesc& collider,
                                      std::size_t index, glm::dvec3 groundOrigin) {
    const std::string field = "/colliders/" + std::to_string(index) + "/file";
    auto file = resolveAssetPath(loaded.folder, collider.file, field);
    if (!file)
        return Error{loaded.file.string(), file.error().str()};
    auto imported = readColliderMesh(loaded.project, *file, groundOrigin);
    if (!imported)
        return imported.error();
    return ColliderMesh{std::move(*file), std::move(*imported)};
}

namespace {

// The mesh of collider `index`: a unit sphere, or its glTF file read.
Result<MovableSurfaceMesh> colliderPropMesh(const LoadedProject& loaded, std::size_t index,
                                            glm::dvec3 groundOrigin) {
    const ColliderDesc& collider = loaded.project.colliders[index];
    if (collider.shape == ColliderShape::Sphere) {
        ProceduralMeshParams sphere;
        sphere.shape = ProceduralShape::Sphere;
        sphere.size = 1.0f;
        sphere.resolution = SPHERE_RESOLUTION;
        return makeProceduralMesh(sphere);
    }
    auto loadedMesh = loadColliderMesh(loaded, collider, index, groundOrigin);
    if (!loadedMesh)
        return loadedMesh.error();
    return std::move(loadedMesh->imported.mesh);
}

}  // namespace

Result<std::vector<SceneProp>> loadSceneProps(const LoadedProject& loaded,
                                              glm::dvec3 groundOrigin) {
    return remakeSceneProps(loaded, {}, {}, groundOrigin);
}

Result<std::vector<SceneProp>> remakeSceneProps(
    const LoadedProject& loaded, std::vector<SceneProp> props,
    const std::vector<ColliderDesc>& madeFor, glm::dvec3 groundOrigin,
    const std::map<std::string, MovableSurfaceMesh>* readAhead) {
    const auto& colliders = loaded.project.colliders;
    std::vector<bool> taken(std::min(props.size(), madeFor.size()), false);
    std::vector<SceneProp> remade;
    remade.reserve(colliders.size());
    for (std::size_t i = 0; i < colliders.size(); ++i) {
        const ColliderDesc& collider = colliders[i];
        SceneProp prop;
        std::size_t old = 0;
        while (old < taken.size() &&
               (taken[old] || madeFor[old].shape != collider.shape ||
                (collider.shape == ColliderShape::Mesh && madeFor[old].file != collider.file)))
            ++old;
        const MovableSurfaceMesh* known = nullptr;
        if (readAhead && collider.shape == ColliderShape::Mesh)
            if (const auto found = readAhead->find(collider.file); found != readAhead->end())
                known = &found->second;
        if (old < taken.size()) {
            taken[old] = true;
            prop.mesh = std::move(props[old].mesh);
        } else if (known) {
            prop.mesh = *known;
        } else {
            auto mesh = colliderPropMesh(loaded, i, groundOrigin);
            if (!mesh)
                return mesh.error();
            prop.mesh = std::move(*mesh);
        }
        placeSceneProp(prop, collider);
        remade.push_back(std::move(prop));
    }
    return remade;
}

}  // namespace grass::core
