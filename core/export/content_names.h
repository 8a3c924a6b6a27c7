// Content-addressed names for the files an export's entry points refer to (a .gltf's buffer and
// map images, raw's blade, patch and map files named in manifest.json), so that an export is
// atomic as a set and not only file by file: new data never replaces old data under the same
// name. The referenced files are renamed into place first and the entry point last, so a kill at
// any moment leaves every entry point next to the very files it names. A re-export of unchanged
// data gives the same names. What no entry point names any more is removed afterwards.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "util/content_digest.h"

namespace grass::core {

// 64-bit FNV-1a, continued from `seed` (chain calls to hash several pieces as one):
// util/content_digest.h's.
inline constexpr std::uint64_t FNV_OFFSET = FNV1A_OFFSET;
std::uint64_t contentHash(std::span<const std::byte> bytes, std::uint64_t seed = FNV_OFFSET);
std::uint64_t contentHash(std::string_view bytes, std::uint64_t seed = FNV_OFFSET);

// "<prefix>-<16 lowercase hex digits of hash><suffix>"; `suffix` starts with '.' (".bin",
// ".blades.bin").
std::string contentAddressedName(std::string_view prefix, std::uint64_t hash,
                                 std::string_view suffix);

// Whether `fileName` has contentAddressedName's form.
bool isContentAddressedName(std::string_view fileName);

// Removes the content-addressed files in `folder` that no entry point there names: every
// string under a "uri" or "file" key of every *.gltf and of manifest.json. An entry point that
// cannot be read or parsed stops the clean-up (nothing is removed rather than something still
// named). Other files are never touched. Returns how many files were removed.
std::size_t removeUnreferencedExportFiles(const std::filesystem::path& folder);

}  // namespace grass::core
