#include "mesh/gltf_scene_walk.h"

#include "mesh/gltf_draco.h"

#include <cmath>

namespace grass::core::gltf {
namespace {

// Nodes with several parents (invalid, but they load) are walked once per parent; this bounds
// the walk when such nodes are stacked into an exponential lattice.
constexpr std::size_t MAX_NODE_VISITS = 1'000'000;

}  // namespace

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

Result<glm::dmat4> nodeLocalTransform(const tinygltf::Model& model, std::size_t index) {
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
        local = composeTrs(
            t.empty() ? glm::dvec3(0.0) : glm::dvec3(t[0], t[1], t[2]),
            r.empty() ? glm::dvec4(0, 0, 0, 1) : glm::dvec4(r[0], r[1], r[2], r[3]),
            s.empty() ? glm::dvec3(1.0) : glm::dvec3(s[0], s[1], s[2]));
    }
    if (!isFinite(local))
        return bad("a non-finite transform");
    return local;
}

glm::dmat3 normalMatrix(const glm::dmat4& world) {
    const glm::dmat3 linear(world);
    const glm::dmat3 cofactor(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                              glm::cross(linear[0], linear[1]));
    return glm::determinant(linear) < 0.0 ? -cofactor : cofactor;
}

// Every mesh the chosen scene places, with its world transform.
Result<std::vector<MeshInstance>> collectInstances(const tinygltf::Model& model,
                                                   std::vector<std::string>& notes,
                                                   bool withColors) {
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
        const auto local = nodeLocalTransform(model, index);
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
            if (node.skin >= 0 && static_cast<std::size_t>(node.skin) >= model.skins.size())
                return makeError("", describeNode(model, index) + " refers to skin " +
                                         std::to_string(node.skin) + ", but the file has " +
                                         std::to_string(model.skins.size()) + " skins");
            // Spec §3.7.3: a skinned mesh ignores its node's transform; its joints place it.
            const int skin = node.skin >= 0 ? node.skin : -1;
            const glm::dmat4 meshWorld = skin >= 0 ? glm::dmat4(1.0) : world;
            const auto gpuInstancing = node.extensions.find("EXT_mesh_gpu_instancing");
            if (gpuInstancing == node.extensions.end()) {
                instances.push_back(
                    {mesh, meshWorld, glm::vec4(1.0f), static_cast<int>(index), skin});
            } else {
                // Instances replace the plain mesh; each goes node world * instance (T R S).
                const auto transforms = readInstanceTransforms(model, gpuInstancing->second,
                                                                     describeNode(model, index));
                if (!transforms)
                    return transforms.error();
                const auto colors =
                    withColors ? readInstanceColors(model, gpuInstancing->second,
                                                    describeNode(model, index))
                               : Result<std::vector<glm::vec4>>(std::vector<glm::vec4>{});
                if (!colors)
                    return colors.error();
                if (!colors->empty() && colors->size() != transforms->size())
                    return makeError("", describeNode(model, index) +
                                             ": EXT_mesh_gpu_instancing _COLOR_0 holds " +
                                             std::to_string(colors->size()) + " colours for " +
                                             std::to_string(transforms->size()) + " instances");
                for (std::size_t i = 0; i < transforms->size(); ++i)
                    instances.push_back({mesh, meshWorld * (*transforms)[i],
                                         colors->empty() ? glm::vec4(1.0f) : (*colors)[i],
                                         static_cast<int>(index), skin});
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
                                              std::vector<std::string>& notes,
                                              bool withColors) {
    std::vector<PrimitiveData> primitives;
    const auto& mesh = model.meshes[meshIndex];
    const std::string meshName = describeMesh(model, meshIndex);
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
        // Draco data wins over any uncompressed copy the file also carries (the extension's
        // advice to loaders that decode it).
        const auto draco = primitive.extensions.find("KHR_draco_mesh_compression");
        auto data = draco != primitive.extensions.end()
                        ? readDracoPrimitive(model, primitive, draco->second, where, withColors)
                        : readTrianglePrimitive(model, primitive, where, withColors);
        if (!data)
            return data.error();
        data->primitive = p;
        primitives.push_back(std::move(*data));
    }
    return primitives;
}

}  // namespace grass::core::gltf
