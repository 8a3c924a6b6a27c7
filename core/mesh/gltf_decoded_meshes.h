// The primitives each placement of a glTF mesh shows, decoded once and shared: the base shape
// (gltf_scene_walk.h's decodeMesh) for a plain node, or the shape posed by its default morph
// weights (gltf_morph.h) and its skin's rest pose (gltf_skin_pose.h), once per distinct
// (mesh, skin, weights). Positions are in the mesh's own space, to be placed by
// MeshInstance::world; a skinned placement's are already in world space (its world is the
// identity). Shared by the geometry import (gltf_loader.cpp) and the stock viewer's picture
// (gltf_view.cpp). Errors carry no path.
#pragma once

#include <tiny_gltf.h>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "mesh/gltf_accessors.h"
#include "mesh/gltf_scene_walk.h"
#include "mesh/gltf_skin_pose.h"
#include "util/result.h"

namespace grass::core::gltf {

class DecodedMeshes {
public:
    DecodedMeshes(const tinygltf::Model& model, std::vector<std::string>& notes, bool withColors);

    // What `instance` (from collectInstances, so its mesh and skin are in range) shows. A
    // placement without a skin or non-zero morph weight (nearly every one) gets the base shape
    // without a copy. Notes, once per mesh: its skin or morph targets applied, or why not.
    Result<const std::vector<PrimitiveData>*> primitives(const MeshInstance& instance);

private:
    Result<const std::vector<PrimitiveData>*> baseShape(std::size_t mesh);
    // `weightsOwner` names where the weights came from ("node 3 \"Leg\"" or "the mesh"), for
    // the note on weights that do not fit the targets.
    Result<std::vector<PrimitiveData>> posed(std::size_t mesh, int skin,
                                             const std::vector<double>& weights,
                                             const std::string& weightsOwner);
    void noteOnce(std::vector<char>& noted, std::size_t mesh, std::string note);

    const tinygltf::Model& mModel;
    std::vector<std::string>& mNotes;
    bool mWithColors;
    std::vector<std::optional<std::vector<PrimitiveData>>> mBase;
    // Keyed by (mesh, skin or -1, weights; empty when all are zero).
    std::map<std::tuple<std::size_t, int, std::vector<double>>, std::vector<PrimitiveData>> mPosed;
    std::optional<SkinRestPose> mRestPose;  // made for the first skinned placement
    std::vector<char> mSkinNoted, mMorphNoted, mMorphRefusedNoted, mPoseSkippedNoted;
};

}  // namespace grass::core::gltf
