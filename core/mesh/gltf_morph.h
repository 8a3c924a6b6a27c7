// Morph targets at their default weights (glTF 2.0 §3.7.2.2): the shape a viewer shows before
// any animation runs is base + Σ weight_i · target_i, for POSITION and NORMAL. Values stay in
// the mesh's own space. Internal to the glTF loader; errors carry no path.
#pragma once

#include <tiny_gltf.h>
#include <cstddef>
#include <string>
#include <vector>

#include "mesh/gltf_accessors.h"
#include "util/result.h"

namespace grass::core::gltf {

// The weights `node` gives its mesh's targets: the node's `weights`, else the mesh's, else none
// (every target at 0). `node` < 0 (a file without scenes) takes the mesh's.
const std::vector<double>& defaultMorphWeights(const tinygltf::Model& model, int node,
                                               std::size_t mesh);

// Whether some weight moves the shape; all zero (or none) is the base shape, the common case.
bool anyNonZero(const std::vector<double>& weights);

// Adds Σ weights[i] · target_i to `data` (decoded from `primitive`); targets at weight 0 are not
// read. Precondition: weights.size() == primitive.targets.size() (the caller notes a file whose
// counts differ and keeps its base shape). NORMAL targets apply only where `data` has normals.
// Errors: a target accessor that is out of range, of the wrong type or not one element per
// vertex, a position made non-finite. `where` names the primitive.
Result<void> applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                               const std::vector<double>& weights, const std::string& where,
                               PrimitiveData& data);

}  // namespace grass::core::gltf
