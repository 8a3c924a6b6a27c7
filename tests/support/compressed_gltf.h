// Compressed copies of a test primitive, made with the same Debian libraries grass decodes with
// (libdraco's encoder, meshoptimizer's codecs): a KHR_draco_mesh_compression document and an
// EXT_meshopt_compression one, both plain GltfDocuments (gltf_writer.h) a test may damage.
#pragma once

#include "support/gltf_writer.h"

namespace grass::test {

// One node placing one mesh whose primitive is `primitive` (triangles, indexed, float POSITION,
// NORMAL and TEXCOORD_0 when it has them) as one Draco stream, positions quantized to
// `positionBits`. The accessors keep type and count, without a bufferView (no fallback).
GltfDocument dracoDocument(const GltfPrimitive& primitive, int positionBits = 14);

// The same primitive with every bufferView meshopt-compressed into buffer 0 (ATTRIBUTES for
// POSITION, NORMAL with the OCTAHEDRAL filter at 16 bits when `octahedralNormals`, else plain,
// TEXCOORD_0; TRIANGLES for the indices), their uncompressed place in buffer 1, a fallback
// buffer without data.
GltfDocument meshoptDocument(const GltfPrimitive& primitive, bool octahedralNormals = false);

}  // namespace grass::test
