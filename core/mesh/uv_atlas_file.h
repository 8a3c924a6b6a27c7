// Binary file of a generated UV atlas kept in the project folder, so maps painted on it stay
// valid each time the project opens (generating again after a change of the algorithm would
// move every texel). Little-endian:
//   8 bytes   magic "GRASSUV1"
//   uint32    face count
//   uint64    meshFingerprint of the mesh the atlas was made for
//   faces × 3 corners × 2 float32: the corner UVs (CornerUvs order)
#pragma once

#include <cstdint>
#include <filesystem>

#include "mesh/surface_mesh.h"
#include "mesh/uv_atlas.h"
#include "util/result.h"

namespace grass::core {

// A hash of the mesh geometry: face count and the position of every corner in face order,
// rounded to 1e-5 of the bounds' largest side, relative to the bounds' minimum (so moving the
// whole mesh keeps it; float noise below the rounding mostly does too).
std::uint64_t meshFingerprint(const SurfaceMesh& mesh);

// Written atomically (writeFileAtomic): a crash leaves the old atlas or the new one.
Result<void> saveUvAtlas(const std::filesystem::path& file, const CornerUvs& uvs,
                         std::uint64_t fingerprint);

// Errors (Error{file, message}) for an unreadable file, a bad magic, a truncated file or one
// with bytes after the UVs, a non-finite UV, and a face count or fingerprint that does not
// match `mesh` (the message says the mesh changed since the atlas was made).
Result<CornerUvs> loadUvAtlas(const std::filesystem::path& file, const SurfaceMesh& mesh);

}  // namespace grass::core
