#include "mesh/gltf_morph.h"

#include <cmath>

#include "mesh/gltf_pose_accessors.h"
#include "util/assert.h"

namespace grass::core::gltf {
namespace {

// Adds weight · the target attribute `name` to `values`; nothing when the target lacks it.
Result<void> addTarget(const tinygltf::Model& model, const std::map<std::string, int>& target,
                       const char* name, double weight, const std::string& where,
                       std::vector<glm::vec3>& values) {
    const auto attribute = target.find(name);
    if (attribute == target.end())
        return {};
    const bool normals = std::string_view(name) == "NORMAL";
    const auto deltas = readMorphDeltas(model, attribute->second, normals, values.size(), where);
    if (!deltas)
        return deltas.error();
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = glm::vec3(glm::dvec3(values[i]) + weight * glm::dvec3((*deltas)[i]));
    return {};
}

}  // namespace

const std::vector<double>& defaultMorphWeights(const tinygltf::Model& model, int node,
                                               std::size_t mesh) {
    if (node >= 0 && !model.nodes[static_cast<std::size_t>(node)].weights.empty())
        return model.nodes[static_cast<std::size_t>(node)].weights;
    return model.meshes[mesh].weights;
}

bool anyNonZero(const std::vector<double>& weights) {
    for (const double weight : weights)
        if (weight != 0.0)
            return true;
    return false;
}

Result<void> applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                               const std::vector<double>& weights, const std::string& where,
                               PrimitiveData& data) {
    GRASS_ASSERT(weights.size() == primitive.targets.size());
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
        if (weights[t] == 0.0)
            continue;
        const std::string targetWhere = where + " morph target " + std::to_string(t);
        const auto& target = primitive.targets[t];
        if (auto added =
                addTarget(model, target, "POSITION", weights[t], targetWhere, data.positions);
            !added)
            return added.error();
        if (data.normals.empty())
            continue;
        // A bad normal is recomputed downstream (gltf_loader.cpp), so none is refused here.
        if (auto added = addTarget(model, target, "NORMAL", weights[t], targetWhere, data.normals);
            !added)
            return added.error();
    }
    // As a non-finite stored position is refused (readTrianglePrimitive), so is a morphed one.
    for (std::size_t i = 0; i < data.positions.size(); ++i) {
        const glm::vec3 p = data.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return makeError("", where +
                                     ": its morph targets at their default weights move "
                                     "vertex " +
                                     std::to_string(i) + " to a non-finite position");
    }
    return {};
}

}  // namespace grass::core::gltf
