// EXT_meshopt_compression (and its ratified twin KHR_meshopt_compression): bufferViews whose
// bytes are stored compressed in another buffer, decoded with Debian's meshoptimizer into the
// bufferView's place before any accessor is read. The uncompressed "fallback" buffer a file
// may leave without data arrives zero-filled (gltf_source.cpp) and is filled here. Internal to
// the glTF loader; errors carry no path.
#pragma once

#include <tiny_gltf.h>
#include <cstdint>

#include "util/result.h"

namespace grass::core::gltf {

// Decodes every compressed bufferView of `model` in place: mode ATTRIBUTES (with the filters
// NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL), TRIANGLES or INDICES. Errors name the bufferView:
// a source range outside its buffer, a stride or count the mode does not allow, a decoded size
// larger than the bufferView, or data meshoptimizer refuses.
Result<void> decodeMeshoptBufferViews(tinygltf::Model& model);

}  // namespace grass::core::gltf
