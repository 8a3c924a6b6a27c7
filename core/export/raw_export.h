// The raw export: a layer's GPU data byte for byte, for runtimes that draw blades the way this
// renderer does (SPEC §1–2) and for tools that want exact numbers. Little-endian throughout.
//   <layer>.blades.bin   the patched blade array as uploaded: patchCount × patchSize records of
//                        64 bytes, four float32 vec4 (v0, θ) (v1, h) (v2, w) (up, s) (blade.h);
//                        padding and thinned slots are null blades (h = w = 0)
//   <layer>.patches.bin  one 32-byte record per patch: uint32 firstBlade, uint32 bladeCount
//                        (live), float32 boundsMin[3], float32 boundsMax[3] (metres)
//   <layer>.wilt.f32     float32 per blade slot: how far the colour leans to the poor colours
//   <layer>.<map>.f32    float32 width × height, row 0 = top of the image = v 0 (map_image.h)
//   manifest.json        all of the above: files, counts, offsets, strides, units, colours
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blade/blade.h"
#include "scatter/patches.h"
#include "util/result.h"

namespace grass::core {

inline constexpr std::size_t RAW_BLADE_STRIDE = sizeof(Blade);
inline constexpr std::size_t RAW_PATCH_STRIDE = 32;

std::string rawBladeBytes(const std::vector<Blade>& blades);
std::string rawPatchBytes(const std::vector<Patch>& patches);
std::string rawFloatBytes(const std::vector<float>& values);

// The layout part of manifest.json (units, axes, blade and patch record fields).
nlohmann::json rawLayoutManifest();

// Reading the files back, bit-exact; errors name the file (missing, a size that is not a whole
// number of records).
Result<std::vector<Blade>> readRawBlades(const std::filesystem::path& file);
Result<std::vector<Patch>> readRawPatches(const std::filesystem::path& file);

}  // namespace grass::core
