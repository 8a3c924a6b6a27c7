// The accessors that pose a primitive (gltf_morph.h, gltf_skin_pose.h): morph target
// displacements, JOINTS_n, WEIGHTS_n and a skin's inverse bind matrices, read with the same
// checks as the primitive's own attributes (gltf_accessor_read.h). Errors carry no path.
#pragma once

#include <tiny_gltf.h>
#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::core::gltf {

// Each per-vertex accessor must hold exactly `vertexCount` elements, checked before anything is
// read or allocated. `where` names the owner in messages.

// A morph target's POSITION or (`normals`) NORMAL displacements; types as POSITION and NORMAL.
Result<std::vector<glm::vec3>> readMorphDeltas(const tinygltf::Model& model, int index,
                                               bool normals, std::size_t vertexCount,
                                               const std::string& where);
// JOINTS_n: VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT, indices into the skin's joints.
Result<std::vector<glm::uvec4>> readJoints(const tinygltf::Model& model, int index,
                                           std::size_t vertexCount, const std::string& where);
// WEIGHTS_n: VEC4 of FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT.
Result<std::vector<glm::vec4>> readJointWeights(const tinygltf::Model& model, int index,
                                                std::size_t vertexCount, const std::string& where);
// A skin's inverseBindMatrices (MAT4 of FLOAT, column-major): the first `jointCount`. Errors
// also: fewer matrices than joints.
Result<std::vector<glm::dmat4>> readInverseBindMatrices(const tinygltf::Model& model, int index,
                                                        std::size_t jointCount,
                                                        const std::string& where);

}  // namespace grass::core::gltf
