#include "mesh/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "mesh/gltf_accessors.h"
#include "mesh/gltf_blade_nodes.h"
#include "mesh/gltf_decoded_meshes.h"
#include "mesh/gltf_parts.h"
#include "mesh/gltf_scene_walk.h"
#include "mesh/gltf_source.h"
#include "util/file_extension.h"

namespace grass::core {
namespace {

using gltf::MeshInstance;
using gltf::PrimitiveData;

constexpr std::uint32_t UNSET = std::numeric_limits<std::uint32_t>::max();
// Triangles between two looks at the stop token (a few milliseconds of building).
constexpr std::size_t TRIANGLES_PER_STOP_CHECK = 65536;
constexpr const char* STOPPED_WHILE_READING = "stopped while reading";

struct MergeStats {
    std::size_t primitives = 0;
    std::size_t withNormals = 0;
    std::size_t withUv = 0;
    std::size_t badNormals = 0;
};

// Adds one primitive placed by `world`. Vertices without a usable normal get a zero normal
// and those without UV0 a NaN UV: both are filled in once the whole mesh exists.
Result<void> addPrimitive(SurfaceMeshBuilder& builder, const PrimitiveData& data,
                          const glm::dmat4& world, const glm::dvec3& origin,
                          const std::string& meshName, MergeStats& stats,
                          const std::stop_token& stop) {
    const glm::dmat3 normalMatrix = gltf::normalMatrix(world);
    const double det = glm::determinant(glm::dmat3(world));
    const bool hasNormals = !data.normals.empty();
    const bool hasUv = !data.uvs.empty();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<std::uint32_t> remap(data.positions.size(), UNSET);
    builder.reserveMore(data.positions.size(), data.triangles.size());
    const auto vertex = [&](std::uint32_t i) -> Result<std::uint32_t> {
        if (remap[i] != UNSET)
            return remap[i];
        if (builder.mesh().n_vertices() >=
            static_cast<std::size_t>(std::numeric_limits<int>::max()))
            return makeError("", "has more vertices than grass can hold");
        const glm::vec3 position(glm::dvec3(world * glm::dvec4(data.positions[i], 1.0)) - origin);
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
    for (std::size_t t = 0; t < data.triangles.size(); ++t) {
        if (t % TRIANGLES_PER_STOP_CHECK == 0 && stop.stop_requested())
            return makeError("", STOPPED_WHILE_READING);
        const auto& triangle = data.triangles[t];
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

// The bounds, in double precision, of every triangle's corners as the instances place them;
// false when there is no triangle.
bool tryWorldBounds(const std::vector<MeshInstance>& instances, gltf::DecodedMeshes& decoded,
                    glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(std::numeric_limits<double>::infinity());
    hi = -lo;
    bool any = false;
    for (const MeshInstance& instance : instances) {
        const auto primitives = decoded.primitives(instance);
        if (!primitives)
            continue;  // reported when the primitives are added
        for (const PrimitiveData& data : **primitives)
            for (const auto& triangle : data.triangles)
                for (const std::uint32_t i : triangle) {
                    const glm::dvec3 p(instance.world * glm::dvec4(data.positions[i], 1.0));
                    lo = glm::min(lo, p);
                    hi = glm::max(hi, p);
                    any = true;
                }
    }
    return any && std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z);
}

std::string coordinates(const glm::dvec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.0f, %.0f, %.0f)", p.x, p.y, p.z);
    return text;
}

std::string ofPrimitives(std::size_t lacking, std::size_t total) {
    return std::to_string(lacking) + " of " + std::to_string(total) + " primitives";
}

// A grass export imported as ground: its terrain is the ground, its blades are not (gltf_blade_nodes.h).
void dropExportedBlades(const tinygltf::Model& model, std::vector<MeshInstance>& instances,
                        std::vector<std::string>& notes) {
    const std::vector<char> blades = gltf::bladeGroupNodes(model);
    const auto before = instances.size();
    std::erase_if(instances, [&](const MeshInstance& instance) {
        return instance.node >= 0 && blades[static_cast<std::size_t>(instance.node)];
    });
    if (instances.size() != before)
        notes.push_back("a grass export: its blades left out (" +
                        std::to_string(before - instances.size()) +
                        " placements), its terrain is the ground");
}

// How far the centre of the bounds [lo, hi] (file units) lies from the file's origin, in whole
// kilometres, for the notes of a mesh moved (or left) far from it.
std::string kilometresAway(const glm::dvec3& lo, const glm::dvec3& hi, double metresPerUnit) {
    char text[48];
    std::snprintf(text, sizeof text, "%.0f", glm::length(0.5 * (lo + hi)) * metresPerUnit / 1000.0);
    return text;
}

}  // namespace

glm::dvec3 groundOrigin(const glm::dvec3& lo, const glm::dvec3& hi, double metresPerUnit) {
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double farthest = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)});
    if (!(farthest * metresPerUnit > GROUND_RECENTRE_BEYOND_M))
        return glm::dvec3(0.0);
    return glm::round(centre);
}

bool isGltfPath(const std::filesystem::path& path) {
    const std::string extension = lowerExtension(path);
    return extension == ".gltf" || extension == ".glb";
}

Error readStopped(const std::filesystem::path& file) {
    return Error{file.string(), STOPPED_WHILE_READING};
}

Result<GltfImport> loadGltf(const std::filesystem::path& file, GltfPlacement placement,
                            double metresPerUnit, glm::dvec3 groundOrigin, std::stop_token stop) {
    const std::string display = file.string();
    if (stop.stop_requested())
        return readStopped(file);
    auto source = gltf::parseGltfFile(file);
    if (!source)
        return source.error();
    if (stop.stop_requested())
        return readStopped(file);
    const tinygltf::Model& model = source->model;
    GltfImport result;
    result.notes = std::move(source->notes);
    const auto withPath = [&](const Error& error) { return makeError(display, error.message); };

    auto instances = gltf::collectInstances(model, result.notes);
    if (!instances)
        return withPath(instances.error());
    if (!instances->empty()) {
        dropExportedBlades(model, *instances, result.notes);
        if (instances->empty())
            return makeError(display, "holds only the blades of a grass export, no terrain to grow on");
    }
    gltf::DecodedMeshes decoded(model, result.notes, false);
    SurfaceMeshBuilder builder;
    gltf::PartTable parts(model, source->materialNames);
    MergeStats stats;
    glm::dvec3 lo, hi;
    if (placement == GltfPlacement::InGroundFrame && tryWorldBounds(*instances, decoded, lo, hi) &&
        core::groundOrigin(lo, hi, metresPerUnit) != glm::dvec3(0.0)) {
        const std::string distance = kilometresAway(lo, hi, metresPerUnit);
        if (groundOrigin != glm::dvec3(0.0)) {
            result.origin = groundOrigin;
            result.placementNote = "lies " + distance +
                                   " km from the file's origin, as the ground does: placed in "
                                   "the ground's frame (the file's point " +
                                   coordinates(groundOrigin) +
                                   " is grass's origin, in the ground's unit and up axis)";
        } else {
            result.placementNote = "lies " + distance +
                                   " km from the file's origin, out of the field's reach: the "
                                   "ground is not that far from its own origin, so this mesh "
                                   "is not in its frame (docs/meshes.md)";
        }
        result.notes.push_back(result.placementNote);
    }
    if (placement == GltfPlacement::GroundNearOrigin && tryWorldBounds(*instances, decoded, lo, hi)) {
        result.origin = core::groundOrigin(lo, hi, metresPerUnit);
        if (result.origin != glm::dvec3(0.0)) {
            // The gap between neighbouring 32-bit floats at the mesh's largest coordinate.
            const double largest = std::max({std::abs(result.origin.x), std::abs(result.origin.y),
                                             std::abs(result.origin.z)});
            char spacing[32];
            std::snprintf(spacing, sizeof spacing, "%.2g",
                          std::ldexp(1.0, std::ilogb(largest) - 23) * metresPerUnit);
            const std::string distance = kilometresAway(lo, hi, metresPerUnit);
            result.notes.push_back(
                "lies " + distance +
                " km from the file's origin, where 32-bit positions are " + spacing +
                " m apart: moved so that the file's point " + coordinates(result.origin) +
                " is grass's origin (the project's cameras, colliders and wind are placed from "
                "there; docs/meshes.md)");
        }
    }
    for (const MeshInstance& instance : *instances) {
        const auto primitives = decoded.primitives(instance);
        if (!primitives)
            return withPath(primitives.error());
        if (stop.stop_requested())
            return readStopped(file);
        const std::string meshName = gltf::describeMesh(model, instance.mesh);
        for (const PrimitiveData& data : **primitives) {
            const auto added =
                addPrimitive(builder, data, instance.world, result.origin, meshName, stats, stop);
            if (!added)
                return withPath(added.error());
            parts.addFaces(instance.node, instance.mesh, data.material, builder.mesh().n_faces());
        }
    }

    if (stop.stop_requested())
        return readStopped(file);
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
