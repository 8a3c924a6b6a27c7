#include "mesh/gltf_skin_pose.h"

#include <cmath>

#include "mesh/gltf_scene_walk.h"
#include "mesh/gltf_accessor_read.h"
#include "mesh/gltf_pose_accessors.h"

namespace grass::core::gltf {
namespace {

// One JOINTS_n / WEIGHTS_n pair, read.
struct InfluenceSet {
    std::vector<glm::uvec4> joints;
    std::vector<glm::vec4> weights;
};

// Every JOINTS_n / WEIGHTS_n pair of the primitive, n = 0, 1, ... until one is missing.
Result<std::vector<InfluenceSet>> readInfluences(const tinygltf::Model& model,
                                                 const tinygltf::Primitive& primitive,
                                                 std::size_t vertexCount,
                                                 const std::string& where) {
    std::vector<InfluenceSet> sets;
    for (std::size_t n = 0; n < primitive.attributes.size(); ++n) {
        const std::string suffix = "_" + std::to_string(n);
        const int joints = attributeAccessor(primitive, "JOINTS" + suffix);
        const int weights = attributeAccessor(primitive, "WEIGHTS" + suffix);
        if (joints < 0 && weights < 0)
            break;
        if (joints < 0 || weights < 0)
            return makeError("", where + " has " + (joints < 0 ? "WEIGHTS" : "JOINTS") + suffix +
                                     " without " + (joints < 0 ? "JOINTS" : "WEIGHTS") + suffix);
        const std::string setWhere = n == 0 ? where : where + " set " + std::to_string(n);
        auto readJ = readJoints(model, joints, vertexCount, setWhere);
        if (!readJ)
            return readJ.error();
        auto readW = readJointWeights(model, weights, vertexCount, setWhere);
        if (!readW)
            return readW.error();
        sets.push_back({std::move(*readJ), std::move(*readW)});
    }
    return sets;
}

}  // namespace

std::string describeSkin(const tinygltf::Model& model, std::size_t skin) {
    const std::string& name = model.skins[skin].name;
    return name.empty() ? "skin " + std::to_string(skin) : "skin \"" + name + "\"";
}

SkinRestPose::SkinRestPose(const tinygltf::Model& model)
    : mModel(model), mParent(model.nodes.size(), -1), mRestWorld(model.nodes.size()) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (const int child : model.nodes[n].children)
            if (child >= 0 && static_cast<std::size_t>(child) < mParent.size() &&
                mParent[static_cast<std::size_t>(child)] < 0)
                mParent[static_cast<std::size_t>(child)] = static_cast<int>(n);
}

Result<glm::dmat4> SkinRestPose::restWorld(std::size_t node) {
    // Up to the first ancestor already known (or the root), then down, remembering each.
    std::vector<std::size_t> chain;
    glm::dmat4 world(1.0);
    for (int n = static_cast<int>(node); n >= 0; n = mParent[static_cast<std::size_t>(n)]) {
        const auto& known = mRestWorld[static_cast<std::size_t>(n)];
        if (known) {
            world = *known;
            break;
        }
        // Longer than the node count: the walk is going round a cycle.
        if (chain.size() == mParent.size())
            return makeError("", describeNode(mModel, node) +
                                     " has an ancestor that is its own ancestor: the node "
                                     "hierarchy has a cycle");
        chain.push_back(static_cast<std::size_t>(n));
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const auto local = nodeLocalTransform(mModel, *it);
        if (!local)
            return local.error();
        world = world * *local;
        if (!isFinite(world))
            return makeError("", describeNode(mModel, *it) + " has a non-finite global transform");
        mRestWorld[*it] = world;
    }
    return world;
}

Result<const std::vector<glm::dmat4>*> SkinRestPose::jointMatrices(std::size_t skin) {
    if (const auto known = mJointMatrices.find(skin); known != mJointMatrices.end())
        return &known->second;
    const tinygltf::Skin& file = mModel.skins[skin];
    const std::string skinName = describeSkin(mModel, skin);
    std::vector<glm::dmat4> inverseBind(file.joints.size(), glm::dmat4(1.0));
    if (file.inverseBindMatrices >= 0) {
        auto read =
            readInverseBindMatrices(mModel, file.inverseBindMatrices, file.joints.size(), skinName);
        if (!read)
            return read.error();
        inverseBind = std::move(*read);
    }
    std::vector<glm::dmat4> matrices(file.joints.size());
    for (std::size_t k = 0; k < file.joints.size(); ++k) {
        const int joint = file.joints[k];
        if (joint < 0 || static_cast<std::size_t>(joint) >= mModel.nodes.size())
            return makeError("", skinName + ": joint " + std::to_string(k) + " is node " +
                                     std::to_string(joint) + ", but the file has " +
                                     std::to_string(mModel.nodes.size()) + " nodes");
        const auto world = restWorld(static_cast<std::size_t>(joint));
        if (!world)
            return world.error();
        matrices[k] = *world * inverseBind[k];
        if (!isFinite(matrices[k]))
            return makeError("", skinName + ": joint " + std::to_string(k) +
                                     " has a non-finite rest transform times inverse bind matrix");
    }
    return &mJointMatrices.emplace(skin, std::move(matrices)).first->second;
}

Result<bool> applySkin(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                       const std::vector<glm::dmat4>& jointMatrices, const std::string& skinName,
                       const std::string& where, PrimitiveData& data) {
    const std::size_t vertexCount = data.positions.size();
    const auto sets = readInfluences(model, primitive, vertexCount, where);
    if (!sets)
        return sets.error();
    if (sets->empty())
        return false;
    for (std::size_t v = 0; v < vertexCount; ++v) {
        glm::dmat4 blended(0.0);
        double sum = 0.0;
        for (std::size_t s = 0; s < sets->size(); ++s) {
            const InfluenceSet& set = (*sets)[s];
            for (int k = 0; k < 4; ++k) {
                const double weight = set.weights[v][k];
                // Only weighted joints are looked up: exporters pad unused slots with any index,
                // and viewers draw such files.
                if (weight == 0.0)
                    continue;
                const std::uint32_t joint = set.joints[v][k];
                if (joint >= jointMatrices.size())
                    return makeError("", where + ": JOINTS_" + std::to_string(s) + " holds joint " +
                                             std::to_string(joint) + " at element " +
                                             std::to_string(v) + ", but " + skinName + " has " +
                                             std::to_string(jointMatrices.size()) + " joints");
                blended += weight * jointMatrices[joint];
                sum += weight;
            }
        }
        if (!(sum > 0.0) || !std::isfinite(sum))
            continue;
        blended /= sum;
        // Checked as stored positions are (readTrianglePrimitive), after the narrowing to float.
        const glm::vec3 p(blended * glm::dvec4(data.positions[v], 1.0));
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return makeError("", where + ": its skin's rest pose moves vertex " +
                                     std::to_string(v) + " to a non-finite position");
        data.positions[v] = p;
        if (!data.normals.empty()) {
            // A zero or non-finite normal is recomputed downstream (gltf_loader.cpp).
            const glm::dvec3 n = normalMatrix(blended) * glm::dvec3(data.normals[v]);
            const double length = glm::length(n);
            data.normals[v] =
                length > 0.0 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0.0f);
        }
    }
    return true;
}

}  // namespace grass::core::gltf
