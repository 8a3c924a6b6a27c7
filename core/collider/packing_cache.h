// The sphere-packing cache: a packing is computed once per mesh and parameters and stored as
// JSON next to the project (<project>/.grass-cache/), so opening a project does not repack.
// The file records a format name and version, a key, the params, the measures and the spheres
// (mesh coordinates, mesh units). Format: docs/sphere-packing.md.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "collider/sphere_packing.h"
#include "util/result.h"

namespace grass::core {

constexpr std::string_view PACKING_CACHE_FORMAT = "grass-sphere-packing";
// Bump when packSpheres or the file layout changes, so old caches are repacked.
constexpr int PACKING_CACHE_VERSION = 1;

// 16 hex digits: a 64-bit FNV-1a hash of the format version, the mesh file's bytes, the mesh's
// triangle corner positions (a .gltf's external .bin can change while the .gltf does not),
// sphereCount and resolution.
std::string packingCacheKey(std::string_view meshFileBytes, const SurfaceMesh& mesh,
                            const SpherePackingParams& params);

// Loads the packing from `cacheFile` when it exists, parses and its key matches; otherwise
// packs and writes it atomically (creating its folder). A corrupt or mismatched cache file is
// not an error: it is repacked and overwritten. Nor is a cache that cannot be written (a
// read-only project folder: an example installed read-only, a shared or mounted drive): the
// packing is returned all the same, and `cacheNote`, when given, says which file could not be
// written and why (the next load packs again). Errors: the mesh file cannot be read or the
// packing fails. `fromCache`, when given, says whether the packing came from the file.
Result<SpherePacking> loadOrPackSpheres(const std::filesystem::path& meshFile,
                                        const SurfaceMesh& mesh, const SpherePackingParams& params,
                                        const std::filesystem::path& cacheFile,
                                        bool* fromCache = nullptr,
                                        std::string* cacheNote = nullptr);

// <projectFolder>/.grass-cache/<mesh stem>.<sphereCount>-<resolution>.spheres.json
std::filesystem::path packingCachePath(const std::filesystem::path& projectFolder,
                                       const std::filesystem::path& meshFile,
                                       const SpherePackingParams& params);

}  // namespace grass::core
