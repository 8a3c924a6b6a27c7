#include "mesh/gltf_loader.h"

#include <cmath>
#include <limits>
#include <optional>

#include "mesh/gltf_accessors.h"
#include "mesh/gltf_source.h"

namespace grass::core {
namespace {

using gltf::PrimitiveData;

// A mesh placed in the world by one node (or by the file itself when it has no scenes).
struct MeshInstance {
    std::size_t mesh = 0;
    glm::dmat4 world{1.0};
};

// Nodes with several parents (invalid, but they load) are walked once per parent; this bounds
// the walk when such nodes are stacked into an exponential lattice.
constexpr std::size_t MAX_NODE_VISITS = 1'000'000;
constexpr std::uint32_t UNSET = std::numeric_limits<std::uint32_t>::max();

std::string describeNode(const tinygltf::Model& model, std::size_t index) {
    const std::string& name = model.nodes[index].name;
    return "node " + std::to_string(index) + (name.empty() ? "" : " \"" + name + "\"");
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r]))
                return false;
    return true;
}

// The node's local transform: `matrix` (column-major) or T * R * S (spec §3.5.3).
Result<glm::dmat4> localTransform(const tinygltf::Model& model, std::size_t index) {
    const tinygltf::Node& node = model.nodes[index];
    const auto bad = [&](const std::string& why) {
        return makeError("", describeNode(model, index) + " has " + why);
    };
    glm::dmat4 local(1.0);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16)
            return bad("a matrix without 16 numbers");
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                local[c][r] = node.matrix[static_cast<std::size_t>(c * 4 + r)];
    } else {
        const auto& t = node.translation;
        const auto& r = node.rotation;
        const auto& s = node.scale;
        if ((!t.empty() && t.size() != 3) || (!r.empty() && r.size() != 4) ||
            (!s.empty() && s.size() != 3))
            return bad("a translation, rotation or scale with the wrong number of values");
        local = gltf::composeTrs(
            t.empty() ? glm::dvec3(0.0) : glm::dvec3(t[0], t[1], t[2]),
            r.empty() ? glm::dvec4(0, 0, 0, 1) : glm::dvec4(r[0], r[1], r[2], r[3]),
            s.empty() ? glm::dvec3(1.0) : glm::dvec3(s[0], s[1], s[2]));
    }
    if (!isFinite(local))
        return bad("a non-finite transform");
    return local;
}

// Every mesh the chosen scene places, with its world transform.
Result<std::vector<MeshInstance>> collectInstances(const tinygltf::Model& model,
                                                   std::vector<std::string>& notes) {
    std::vector<MeshInstance> instances;
    if (model.scenes.empty()) {
        notes.push_back("the file has no scenes: each of its " +
                        std::to_string(model.meshes.size()) + " meshes placed once, untransformed");
        for (std::size_t m = 0; m < model.meshes.size(); ++m)
            instances.push_back({m});
        return instances;
    }
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size())
        return makeError("", "the default scene " + std::to_string(sceneIndex) +
                                 " does not exist (the file has " +
                                 std::to_string(model.scenes.size()) + " scenes)");
    struct Frame {
        int node;
        int parent;  // -1 for the scene's roots
        glm::dmat4 parentWorld;
        bool leaving;
    };
    std::vector<Frame> stack;
    const auto& roots = model.scenes[static_cast<std::size_t>(sceneIndex)].nodes;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, -1, glm::dmat4(1.0), false});
    std::vector<char> onPath(model.nodes.size(), 0);
    std::vector<std::size_t> visits(model.nodes.size(), 0);
    std::vector<char> skinNoted(model.meshes.size(), 0);
    std::size_t totalVisits = 0;
    bool sharedNoted = false;
    while (!stack.empty()) {
        const Frame frame = stack.back();
        stack.pop_back();
        const auto index = static_cast<std::size_t>(frame.node);
        if (frame.leaving) {
            onPath[index] = 0;
            continue;
        }
        if (frame.node < 0 || index >= model.nodes.size())
            return makeError(
                "",
                (frame.parent < 0 ? "scene " + std::to_string(sceneIndex)
                                  : describeNode(model, static_cast<std::size_t>(frame.parent))) +
                    " refers to node " + std::to_string(frame.node) + ", but the file has " +
                    std::to_string(model.nodes.size()) + " nodes");
        if (onPath[index])
            return makeError("", describeNode(model, index) +
                                     " is its own ancestor: the node hierarchy has a cycle");
        if (++visits[index] == 2 && !sharedNoted) {
            notes.push_back(describeNode(model, index) +
                            " has more than one parent: placed once per parent");
            sharedNoted = true;
        }
        if (++totalVisits > MAX_NODE_VISITS)
            return makeError("", "the node hierarchy expands to more than " +
                                     std::to_string(MAX_NODE_VISITS) + " node instances");
        const auto local = localTransform(model, index);
        if (!local)
            return local.error();
        const glm::dmat4 world = frame.parentWorld * *local;
        const tinygltf::Node& node = model.nodes[index];
        if (node.mesh >= 0) {
            const auto mesh = static_cast<std::size_t>(node.mesh);
            if (mesh >= model.meshes.size())
                return makeError("", describeNode(model, index) + " refers to mesh " +
                                         std::to_string(node.mesh) + ", but the file has " +
                                         std::to_string(model.meshes.size()) + " meshes");
            // Spec §3.7.3: a skinned mesh ignores its node's transform; without the joints,
            // its bind pose is the mesh as stored.
            if (node.skin >= 0 && !skinNoted[mesh]) {
                notes.push_back(gltf::describeMesh(model, mesh) +
                                " is skinned: placed in its bind pose");
                skinNoted[mesh] = 1;
            }
            const glm::dmat4 meshWorld = node.skin >= 0 ? glm::dmat4(1.0) : world;
            const auto gpuInstancing = node.extensions.find("EXT_mesh_gpu_instancing");
            if (gpuInstancing == node.extensions.end()) {
                instances.push_back({mesh, meshWorld});
            } else {
                // Instances replace the plain mesh; each goes node world * instance (T R S).
                const auto transforms = gltf::readInstanceTransforms(model, gpuInstancing->second,
                                                                     describeNode(model, index));
                if (!transforms)
                    return transforms.error();
                for (const glm::dmat4& instance : *transforms)
                    instances.push_back({mesh, meshWorld * instance});
            }
        }
        onPath[index] = 1;
        stack.push_back({frame.node, frame.parent, world, true});
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
            stack.push_back({*it, frame.node, world, false});
    }
    return instances;
}

// Decodes the triangle primitives of one mesh; other primitives are skipped with a note.
Result<std::vector<PrimitiveData>> decodeMesh(const tinygltf::Model& model, std::size_t meshIndex,
                                              std::vector<std::string>& notes) {
    std::vector<PrimitiveData> primitives;
    const auto& mesh = model.meshes[meshIndex];
    const std::string meshName = gltf::describeMesh(model, meshIndex);
    bool morphNoted = false;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const auto& primitive = mesh.primitives[p];
        const std::string where = meshName + " primitive " + std::to_string(p);
        switch (primitive.mode) {
            case TINYGLTF_MODE_POINTS:
                notes.push_back(where + ": points ignored");
                continue;
            case TINYGLTF_MODE_LINE:
            case TINYGLTF_MODE_LINE_LOOP:
            case TINYGLTF_MODE_LINE_STRIP:
                notes.push_back(where + ": lines ignored");
                continue;
            case TINYGLTF_MODE_TRIANGLES:
            case TINYGLTF_MODE_TRIANGLE_STRIP:
            case TINYGLTF_MODE_TRIANGLE_FAN:
                break;
            default:
                notes.push_back(where + ": unknown mode " + std::to_string(primitive.mode) +
                                " ignored");
                continue;
        }
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) {
            // Spec §3.7.2.1: without positions a primitive SHOULD be skipped.
            notes.push_back(where + ": no POSITION, skipped");
            continue;
        }
        // A Draco primitive whose uncompressed fallback is absent has POSITION without data.
        if (primitive.extensions.count("KHR_draco_mesh_compression") && position->second >= 0 &&
            static_cast<std::size_t>(position->second) < model.accessors.size()) {
            const auto& accessor = model.accessors[static_cast<std::size_t>(position->second)];
            if (accessor.bufferView < 0 && !accessor.sparse.isSparse)
                return makeError("", where +
                                         " is Draco-compressed (KHR_draco_mesh_compression), "
                                         "which grass cannot decode");
        }
        if (!primitive.targets.empty() && !morphNoted) {
            notes.push_back(meshName + ": morph targets ignored (base shape used)");
            morphNoted = true;
        }
        auto data = gltf::readTrianglePrimitive(model, primitive, where);
        if (!data)
            return data.error();
        primitives.push_back(std::move(*data));
    }
    return primitives;
}

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
    const glm::dmat3 linear(world);
    // Normals go by the inverse-transpose, whose columns are the cross products of the
    // matrix's columns over its determinant; only the direction matters, so divide by the
    // determinant's sign. A mirroring transform reverses winding (spec §3.7.4).
    const glm::dmat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                              glm::cross(linear[0], linear[1]));
    const double det = glm::determinant(linear);
    const glm::dmat3 normalMatrix = det < 0.0 ? -cofactor : cofactor;
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

    const auto instances = collectInstances(model, result.notes);
    if (!instances)
        return withPath(instances.error());
    // Decoded once per mesh, shared by every node that places it.
    std::vector<std::optional<std::vector<PrimitiveData>>> decoded(model.meshes.size());
    SurfaceMeshBuilder builder;
    MergeStats stats;
    for (const MeshInstance& instance : *instances) {
        auto& primitives = decoded[instance.mesh];
        if (!primitives) {
            auto read = decodeMesh(model, instance.mesh, result.notes);
            if (!read)
                return withPath(read.error());
            primitives = std::move(*read);
        }
        const std::string meshName = gltf::describeMesh(model, instance.mesh);
        for (const PrimitiveData& data : *primitives) {
            const auto added = addPrimitive(builder, data, instance.world, meshName, stats);
            if (!added)
                return withPath(added.error());
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
