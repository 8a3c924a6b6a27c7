// A file's bytes in 64 bits, to tell whether a file is still the one a program read or wrote:
// the editor's Save refuses to replace a project.json that another program (a text editor, a
// second editor window, `git checkout`) changed since (editor/app/panels.cpp, saveTo). FNV-1a:
// not for adversaries, only for noticing a change; a change that keeps the digest would have to
// be made on purpose. GL-free.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace grass {

// 64-bit FNV-1a of `bytes`, continued from `seed` (chain calls to hash several pieces as one):
// the one implementation the export's content-addressed names and the sphere-packing cache's
// key use too.
inline constexpr std::uint64_t FNV1A_OFFSET = 14695981039346656037ull;
std::uint64_t contentDigest(std::string_view bytes, std::uint64_t seed = FNV1A_OFFSET);

// The digest of the file's bytes, or none when it cannot be read (gone, not a regular file,
// over the JSON cap).
std::optional<std::uint64_t> fileDigest(const std::filesystem::path& file);

}  // namespace grass
