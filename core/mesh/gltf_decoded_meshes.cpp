#include "mesh/gltf_decoded_meshes.h"

#include <utility>

#include "mesh/gltf_morph.h"

namespace grass::core::gltf {

DecodedMeshes::DecodedMeshes(const tinygltf::Model& model, std::vector<std::string>& notes,
                             bool withColors)
    : mModel(model),
      mNotes(notes),
      mWithColors(withColors),
      mBase(model.meshes.size()),
      mSkinNoted(model.meshes.size(), 0),
      mMorphNoted(model.meshes.size(), 0),
      mMorphRefusedNoted(model.meshes.size(), 0),
      mPoseSkippedNoted(model.meshes.size(), 0) {}

Result<const std::vector<PrimitiveData>*> DecodedMeshes::primitives(const MeshInstance& instance) {
    const std::vector<double>& weights = defaultMorphWeights(mModel, instance.node, instance.mesh);
    const bool morphs = anyNonZero(weights);
    if (instance.skin < 0 && !morphs)
        return baseShape(instance.mesh);
    auto key =
        std::make_tuple(instance.mesh, instance.skin, morphs ? weights : std::vector<double>{});
    if (const auto known = mPosed.find(key); known != mPosed.end())
        return &known->second;
    const bool nodeWeights =
        instance.node >= 0 && !mModel.nodes[static_cast<std::size_t>(instance.node)].weights.empty();
    auto shape =
        posed(instance.mesh, instance.skin, std::get<2>(key),
              nodeWeights ? describeNode(mModel, static_cast<std::size_t>(instance.node)) + "'s"
                          : std::string("the mesh's"));
    if (!shape)
        return shape.error();
    return &mPosed.emplace(std::move(key), std::move(*shape)).first->second;
}

Result<const std::vector<PrimitiveData>*> DecodedMeshes::baseShape(std::size_t mesh) {
    auto& decoded = mBase[mesh];
    if (!decoded) {
        auto read = decodeMesh(mModel, mesh, mNotes, mWithColors);
        if (!read)
            return read.error();
        decoded = std::move(*read);
    }
    return &*decoded;
}

// Morphing comes before skinning (spec §3.7.2.2): the targets move the bind-pose vertices.
Result<std::vector<PrimitiveData>> DecodedMeshes::posed(std::size_t mesh, int skin,
                                                        const std::vector<double>& weights,
                                                        const std::string& weightsOwner) {
    const auto base = baseShape(mesh);
    if (!base)
        return base.error();
    std::vector<PrimitiveData> shape = **base;
    const std::string meshName = describeMesh(mModel, mesh);
    const std::vector<glm::dmat4>* jointMatrices = nullptr;
    std::string skinName;
    if (skin >= 0) {
        if (!mRestPose)
            mRestPose.emplace(mModel);
        const auto matrices = mRestPose->jointMatrices(static_cast<std::size_t>(skin));
        if (!matrices)
            return matrices.error();
        jointMatrices = *matrices;
        skinName = describeSkin(mModel, static_cast<std::size_t>(skin));
    }
    bool morphed = false;
    bool skinned = false;
    for (PrimitiveData& data : shape) {
        const tinygltf::Primitive& primitive = mModel.meshes[mesh].primitives[data.primitive];
        const std::string where = meshName + " primitive " + std::to_string(data.primitive);
        const bool morphs = !weights.empty() && !primitive.targets.empty();
        // The Draco stream may order the vertices its own way and holds the skin attributes;
        // the uncompressed targets and JOINTS_0 no longer line up with what it decodes.
        if ((morphs || jointMatrices) &&
            primitive.extensions.count("KHR_draco_mesh_compression") != 0) {
            noteOnce(mPoseSkippedNoted, mesh,
                     where + " is Draco-compressed: its morph targets and skin are not applied");
            continue;
        }
        if (morphs && weights.size() != primitive.targets.size()) {
            // The geometry is sound, only its weights are not: the base shape, with a note,
            // serves a user better than refusing the file.
            noteOnce(mMorphRefusedNoted, mesh,
                     where + " has " + std::to_string(weights.size()) + " default weights (" +
                         weightsOwner + ") for " + std::to_string(primitive.targets.size()) +
                         " morph targets: its base shape used");
        } else if (morphs) {
            if (auto applied = applyMorphTargets(mModel, primitive, weights, where, data); !applied)
                return applied.error();
            morphed = true;
        }
        if (!jointMatrices)
            continue;
        const auto applied = applySkin(mModel, primitive, *jointMatrices, skinName, where, data);
        if (!applied)
            return applied.error();
        skinned = skinned || *applied;
        if (!*applied)
            noteOnce(mPoseSkippedNoted, mesh,
                     where + " has no JOINTS_0 and WEIGHTS_0 for its node's " + skinName +
                         ": placed as stored");
    }
    if (morphed)
        noteOnce(mMorphNoted, mesh, meshName + ": morph targets applied at their default weights");
    if (skinned)
        noteOnce(mSkinNoted, mesh,
                 meshName + " is skinned: placed in its skeleton's rest pose (" + skinName + ")");
    return shape;
}

void DecodedMeshes::noteOnce(std::vector<char>& noted, std::size_t mesh, std::string note) {
    if (noted[mesh])
        return;
    noted[mesh] = 1;
    mNotes.push_back(std::move(note));
}

}  // namespace grass::core::gltf
