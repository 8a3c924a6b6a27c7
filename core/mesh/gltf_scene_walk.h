// Walking a parsed glTF 2.0 scene: which meshes its nodes place and where (node hierarchy,
// matrices or T·R·S, EXT_mesh_gpu_instancing), and a mesh's triangle primitives decoded. Shared
// by the geometry import (gltf_loader.cpp) and the stock viewer's picture (gltf_view.h). Errors
// carry no path: the caller adds the file's.
#pragma once

#include <tiny_gltf.h>
#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "mesh/gltf_accessors.h"
#include "util/result.h"

namespace grass::core::gltf {

// A mesh placed in the world by one node, or by one of its GPU instances (or by the file itself
// when it has no scenes).
struct MeshInstance {
    std::size_t mesh = 0;
    glm::dmat4 world{1.0};
    glm::vec4 color{1.0f};  // the instance's _COLOR_0; white for plain nodes
    int node = -1;          // the node that placed it; -1 for a file without scenes
    // The node's skin; `world` is then the identity, as the skin's joints place the mesh
    // (spec §3.7.3, gltf_skin_pose.h).
    int skin = -1;
};

// "node 3 "Hips"" when the node has a name, else "node 3": how messages name a node.
std::string describeNode(const tinygltf::Model& model, std::size_t index);

// The node's local transform: `matrix` (column-major) or T * R * S (spec §3.5.3). Errors: the
// wrong number of values, a non-finite result.
Result<glm::dmat4> nodeLocalTransform(const tinygltf::Model& model, std::size_t index);

// Whether every entry of `m` is finite.
bool isFinite(const glm::dmat4& m);

// Normals go by the inverse-transpose of `world`'s linear part, whose columns are the cross
// products of its columns over its determinant; only the direction matters, so this divides by
// the determinant's sign alone. A mirroring transform (determinant < 0) also reverses the
// winding (spec §3.7.4).
glm::dmat3 normalMatrix(const glm::dmat4& world);

// Every mesh the default scene (else scene 0) places, with its world transform. A file without
// scenes places each mesh once, untransformed (noted). Errors: a node index out of range, a
// cycle, more than a million node visits, a bad transform or instancing attribute, a skin
// index out of range. Instance
// colours are read only `withColors`.
Result<std::vector<MeshInstance>> collectInstances(const tinygltf::Model& model,
                                                   std::vector<std::string>& notes,
                                                   bool withColors = false);

// The triangle primitives of one mesh in its base shape (no morph target, no skin: see
// gltf_decoded_meshes.h); points, lines and primitives without POSITION are skipped with a
// note. COLOR_0 is decoded only `withColors`.
Result<std::vector<PrimitiveData>> decodeMesh(const tinygltf::Model& model, std::size_t meshIndex,
                                              std::vector<std::string>& notes,
                                              bool withColors = false);

}  // namespace grass::core::gltf
