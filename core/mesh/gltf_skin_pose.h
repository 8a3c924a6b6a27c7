// A skinned mesh in its skeleton's rest pose (glTF 2.0 §3.7.3), as viewers show it before any
// animation runs: vertex v goes to Σ_k w_k · (globalTransform(joint_k) · inverseBindMatrix_k) · v,
// with the joints' global transforms from the node hierarchy (their TRS or matrix, no
// animation) and the skinned node's own transform ignored. The result is in the scene's world
// space. Internal to the glTF loader; errors carry no path.
#pragma once

#include <tiny_gltf.h>
#include <cstddef>
#include <glm/glm.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "mesh/gltf_accessors.h"
#include "util/result.h"

namespace grass::core::gltf {

// `skin "Armature"` when the skin has a name, else `skin 2`: how messages name a skin.
std::string describeSkin(const tinygltf::Model& model, std::size_t skin);

// The joint matrices of a file's skins, each computed once; node transforms memoised, so a
// file with many skins over a deep hierarchy stays linear in its nodes.
class SkinRestPose {
public:
    explicit SkinRestPose(const tinygltf::Model& model);

    // globalTransform(joint_k) · inverseBindMatrix_k for each joint k of `skin`
    // (< model.skins.size()); a missing inverseBindMatrices is the identity (spec). Errors: a
    // joint that is not a node, too few inverse bind matrices, a cycle above a joint, a bad or
    // non-finite transform.
    Result<const std::vector<glm::dmat4>*> jointMatrices(std::size_t skin);

private:
    // The node's global transform at rest: its ancestors' local transforms times its own.
    Result<glm::dmat4> restWorld(std::size_t node);

    const tinygltf::Model& mModel;
    std::vector<int> mParent;  // per node, the first node listing it as a child; -1 for none
    std::vector<std::optional<glm::dmat4>> mRestWorld;
    std::map<std::size_t, std::vector<glm::dmat4>> mJointMatrices;
};

// Moves `data`'s positions and normals (decoded from `primitive`) by its JOINTS_n and WEIGHTS_n
// (every set the primitive has) and `jointMatrices`. A vertex's weights are divided by their
// sum, as viewers effectively do; a vertex whose weights sum to 0 (or are not finite) stays as
// stored. Returns false, `data` untouched, when the primitive has no JOINTS_0 and WEIGHTS_0.
// Errors: a set with one of the pair only, an accessor that is out of range, of the wrong type
// or not one element per vertex, a weighted joint index not below jointMatrices.size(), a
// position made non-finite. `where` names the primitive, `skinName` the skin.
Result<bool> applySkin(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                       const std::vector<glm::dmat4>& jointMatrices, const std::string& skinName,
                       const std::string& where, PrimitiveData& data);

}  // namespace grass::core::gltf
