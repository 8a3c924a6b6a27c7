// KHR_draco_mesh_compression: a triangle primitive whose attributes and indices are one Draco
// stream in a bufferView, decoded with Debian's libdraco into the same PrimitiveData the plain
// accessors give (gltf_accessors.h). Internal to the glTF loader; errors carry no path.
#pragma once

#include <tiny_gltf.h>
#include <string>

#include "mesh/gltf_accessors.h"
#include "util/result.h"

namespace grass::core::gltf {

// Where parseGltfFile keeps a Draco primitive's indices accessor (gltf_source.cpp).
inline constexpr const char* DRACO_INDICES_KEY = "grassIndicesAccessor";

// `extension` is the primitive's KHR_draco_mesh_compression object ({bufferView, attributes:
// {POSITION: id, ...}}). Reads POSITION (required), NORMAL, TEXCOORD_0 and, `withColors`,
// COLOR_0 by their Draco attribute ids. Errors: a missing or out-of-range bufferView, a stream
// libdraco refuses, a missing POSITION, an attribute with the wrong number of components, a
// decoded vertex or index count that differs from the primitive's accessors (the spec requires
// them equal), a non-finite position.
Result<PrimitiveData> readDracoPrimitive(const tinygltf::Model& model,
                                         const tinygltf::Primitive& primitive,
                                         const tinygltf::Value& extension, const std::string& where,
                                         bool withColors);

}  // namespace grass::core::gltf
