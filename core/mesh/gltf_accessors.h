// Reading glTF 2.0 accessors and triangle primitives out of a parsed tinygltf::Model, with every
// index and byte range checked before memory is touched (the file is outside input). Values
// come back in the file's own space (node transforms are applied by the caller). Internal to
// the glTF loader (gltf_loader.cpp); errors carry no path, the loader adds the file's.
// Besides the core types: KHR_mesh_quantization and EXT_mesh_gpu_instancing.
#pragma once

#include <tiny_gltf.h>
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::core::gltf {

// "mesh "Rock"" when the mesh has a name, else "mesh 3": how messages and notes name a mesh.
std::string describeMesh(const tinygltf::Model& model, std::size_t meshIndex);

// T * R * S (spec §3.5.3), the rotation a quaternion stored x, y, z, w as glTF stores it and
// normalized here (exporters write slightly off-unit ones).
glm::dmat4 composeTrs(glm::dvec3 translation, glm::dvec4 rotationXyzw, glm::dvec3 scale);

// One triangle primitive, decoded: vertices as the accessors hold them, triangles as vertex
// indices in the file's winding (strips and fans already unrolled, spec §3.7.2.1).
struct PrimitiveData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // empty when the primitive has no NORMAL
    std::vector<glm::vec2> uvs;      // empty when the primitive has no TEXCOORD_0
    std::vector<glm::vec4> colors;   // COLOR_0 as RGBA (alpha 1 for RGB); empty when absent
    int material = -1;               // the primitive's material index as the file holds it
    std::size_t primitive = 0;       // its index in the mesh's primitives (set by decodeMesh)
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Decodes a primitive whose mode is TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN and which has a
// POSITION attribute. `where` names it in messages: `mesh "Rock" primitive 0`. Accepts float
// attributes, normalized integer TEXCOORD_0 and COLOR_0, and KHR_mesh_quantization's integer POSITION,
// NORMAL and TEXCOORD_0; honours byteStride and sparse accessors. Errors: any index out of
// range, an accessor reading past its bufferView or buffer, a non-finite position, attribute
// counts that differ, a vertex index not below the vertex count.
// COLOR_0 is read only `withColors` (the geometry import does not use it, so a broken one
// cannot refuse a file there).
Result<PrimitiveData> readTrianglePrimitive(const tinygltf::Model& model,
                                            const tinygltf::Primitive& primitive,
                                            const std::string& where, bool withColors = false);

// EXT_mesh_gpu_instancing: the instance transforms (T * R * S, each applied before the node's
// world transform) listed by a node's extension object; `where` names the node in messages.
Result<std::vector<glm::dmat4>> readInstanceTransforms(const tinygltf::Model& model,
                                                       const tinygltf::Value& extension,
                                                       const std::string& where);

// The per-instance colours of an EXT_mesh_gpu_instancing node: its `_COLOR_0` attribute (the
// convention stock loaders such as three.js read; not part of the extension), RGBA, alpha 1 for
// RGB; empty when the node has none. Same types as COLOR_0.
Result<std::vector<glm::vec4>> readInstanceColors(const tinygltf::Model& model,
                                                  const tinygltf::Value& extension,
                                                  const std::string& where);

}  // namespace grass::core::gltf
