#include "mesh/mesh_parts.h"

#include <algorithm>

#include "util/assert.h"

namespace grass::core {

namespace {

// The property's name: OpenMesh finds a mesh property by it in any copy of the mesh.
constexpr const char* PARTS_PROPERTY = "grass:parts";

}  // namespace

const MeshParts* meshPartsOf(const SurfaceMesh& mesh) {
    OpenMesh::MPropHandleT<MeshParts> handle;
    if (!mesh.get_property_handle(handle, PARTS_PROPERTY))
        return nullptr;
    return &mesh.property(handle);
}

void setMeshParts(SurfaceMesh& mesh, MeshParts parts) {
    GRASS_ASSERT(parts.faceParts.size() == mesh.n_faces());
    for (const std::uint32_t part : parts.faceParts)
        GRASS_ASSERT(part < parts.parts.size());
    OpenMesh::MPropHandleT<MeshParts> handle;
    if (!mesh.get_property_handle(handle, PARTS_PROPERTY))
        mesh.add_property(handle, PARTS_PROPERTY);
    mesh.property(handle) = std::move(parts);
}

bool partHasName(const MeshPart& part, const std::string& name) {
    return part.mesh == name || part.material == name ||
           std::find(part.nodes.begin(), part.nodes.end(), name) != part.nodes.end();
}

std::vector<std::string> partNames(const SurfaceMesh& mesh) {
    std::vector<std::string> names;
    if (const MeshParts* table = meshPartsOf(mesh))
        for (const MeshPart& part : table->parts) {
            names.insert(names.end(), part.nodes.begin(), part.nodes.end());
            names.push_back(part.mesh);
            names.push_back(part.material);
        }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

}  // namespace grass::core
