#include "mesh/gltf_loader.h"

#include <cmath>
#include <limits>
#include <optional>

#include "mesh/gltf_accessors.h"
#include "mesh/gltf_parts.h"
#include "mesh/gltf_scene_walk.h"
#include "mesh/gltf_source.h"

namespace grass::core {
namespace {

using gltf::MeshInstance;
using gltf::PrimitiveData;

constexpr std::uint32_t UNSET = std::numeric_limits<std::uint32_t>::max();

struct MergeStats {
    std::size_t primitives = 0;
    std::size_t withNormals = 0;
    std::size_t withUv = 0;
    std::size_t badNormals = 0;
};

// Adds one primitive placed by `world`. Vertices without a usable normal get a zero normal
// and those without UV0 a NaN UV: both are filled in once the whole mesh exists.
Result<void> addPrimitive(SurfaceMeshBuilder& builder, const PrimitiveData& data,
                          const glm::dmat4& world, const std::string& meshName, MergeStats& stats) {
    const glm::dmat3 normalMatrix = gltf::normalMatrix(world);
    const double det = glm::determinant(glm::dmat3(world));
    const bool hasNormals = !data.normals.empty();
    const bool hasUv = !data.uvs.empty();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<std::uint32_t> remap(data.positions.size(), UNSET);
    const auto vertex = [&](std::uint32_t i) -> Result<std::uint32_t> {
        if (remap[i] != UNSET)
            return remap[i];
        if (builder.mesh().n_vertices() >=
            static_cast<std::size_t>(std::numeric_limits<int>::max()))
            return makeError("", "has more vertices than grass can hold");
        const glm::vec3 position(world * glm::dvec4(data.positions[i], 1.0));
        if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z))
            return makeError("", meshName +
                                     " has non-finite positions once its node transform "
                                     "is applied");
        glm::vec3 normal(0.0f);
        if (hasNormals) {
            const glm::dvec3 n = normalMatrix * glm::dvec3(data.normals[i]);
            const double length = glm::length(n);
            if (length > 0.0 && std::isfinite(length))
                normal = glm::vec3(n / length);
            else
                ++stats.badNormals;
        }
        glm::vec2 uv(nan);
        if (hasUv && std::isfinite(data.uvs[i].x) && std::isfinite(data.uvs[i].y))
            uv = data.uvs[i];
        remap[i] = builder.addVertex(position, normal, uv);
        return remap[i];
    };
    for (const auto& triangle : data.triangles) {
        std::uint32_t v[3];
        for (int k = 0; k < 3; ++k) {
            const auto added = vertex(triangle[static_cast<std::size_t>(k)]);
            if (!added)
                return added.error();
            v[k] = *added;
        }
        if (det < 0.0)
            builder.addTriangle(v[0], v[2], v[1]);
        else
            builder.addTriangle(v[0], v[1], v[2]);
    }
    ++stats.primitives;
    stats.withNormals += hasNormals ? 1 : 0;
    stats.withUv += hasUv ? 1 : 0;
    return {};
}

// Area-weighted normals for vertices that came without a usable one; file normals are kept.
void fillMissingNormals(SurfaceMesh& mesh) {
    std::vector<OpenMesh::Vec3f> kept;
    kept.reserve(mesh.n_vertices());
    bool missing = false;
    for (const auto vh : mesh.vertices()) {
        kept.push_back(mesh.normal(vh));
        missing = missing || kept.back().sqrnorm() == 0.0f;
    }
    if (!missing)
        return;
    computeAreaWeightedNormals(mesh);
    for (const auto vh : mesh.vertices()) {
        const auto& normal = kept[static_cast<std::size_t>(vh.idx())];
        if (normal.sqrnorm() != 0.0f)
            mesh.set_normal(vh, normal);
    }
}

// Planar UVs for vertices that came without UV0; file UVs are kept.
void fillMissingUvs(SurfaceMesh& mesh) {
    std::vector<OpenMesh::Vec2f> kept;
    kept.reserve(mesh.n_vertices());
    bool missing = false;
    for (const auto vh : mesh.vertices()) {
        kept.push_back(mesh.texcoord2D(vh));
        missing = missing || std::isnan(kept.back()[0]);
    }
    if (!missing)
        return;
    generatePlanarUVs(mesh);
    for (const auto vh : mesh.vertices()) {
        const auto& uv = kept[static_cast<std::size_t>(vh.idx())];
        if (!std::isnan(uv[0]))
            mesh.set_texcoord2D(vh, uv);
    }
}

std::string ofPrimitives(std::size_t lacking, std::size_t total) {
    return std::to_string(lacking) + " of " + std::to_string(total) + " primitives";
}

}  // namespace

Result<GltfImport> loadGltf(const std::filesystem::path& file) {
    const std::string display = file.string();
    auto source = gltf::parseGltfFile(file);
    if (!source)
        return source.error();
    const tinygltf::Model& model = source->model;
    GltfImport result;
    result.notes = std::move(source->notes);
    const auto withPath = [&](const Error& error) { return makeError(display, error.message); };

    const auto instances = gltf::collectInstances(model, result.notes);
    if (!instances)
        return withPath(instances.error());
    gltf::DecodedMeshes decoded(model, result.notes, false);
    SurfaceMeshBuilder builder;
    gltf::PartTable parts(model, source->materialNames);
    MergeStats stats;
    for (const MeshInstance& instance : *instances) {
        const auto primitives = decoded.primitives(instance.mesh);
        if (!primitives)
            return withPath(primitives.error());
        const std::string meshName = gltf::describeMesh(model, instance.mesh);
        for (const PrimitiveData& data : **primitives) {
            const auto added = addPrimitive(builder, data, instance.world, meshName, stats);
            if (!added)
                return withPath(added.error());
            parts.addFaces(instance.node, instance.mesh, data.material, builder.mesh().n_faces());
        }
    }

    if (builder.mesh().n_faces() == 0) {
        const std::string why = instances->empty()      ? "its scene places no mesh"
                                : stats.primitives == 0 ? "no primitive is made of triangles"
                                                        : "every triangle is degenerate";
        return makeError(display, "contains no triangles (" + why + ")");
    }
    if (builder.degenerateTriangles() > 0)
        result.notes.push_back(std::to_string(builder.degenerateTriangles()) +
                               " degenerate triangles (a repeated vertex) skipped");
    if (builder.duplicatedForManifold() > 0)
        result.notes.push_back(std::to_string(builder.duplicatedForManifold()) +
                               " non-manifold triangles given their own vertices");
    result.mesh = builder.take();
    setMeshParts(result.mesh, parts.take());
    result.hasNormals = stats.withNormals == stats.primitives;
    result.hasUv = stats.withUv == stats.primitives;
    if (!result.hasNormals)
        result.notes.push_back(
            "normals computed (area-weighted): " +
            ofPrimitives(stats.primitives - stats.withNormals, stats.primitives) +
            " had no NORMAL");
    if (stats.badNormals > 0)
        result.notes.push_back(std::to_string(stats.badNormals) +
                               " zero or non-finite normals recomputed (area-weighted)");
    if (!result.hasUv)
        result.notes.push_back("UVs generated (planar projection): " +
                               ofPrimitives(stats.primitives - stats.withUv, stats.primitives) +
                               " had no TEXCOORD_0");
    fillMissingNormals(result.mesh);
    fillMissingUvs(result.mesh);
    return result;
}

}  // namespace grass::core
