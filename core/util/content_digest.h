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

std::uint64_t contentDigest(std::string_view bytes);

// The digest of the file's bytes, or none when it cannot be read (gone, not a regular file,
// over the JSON cap).
std::optional<std::uint64_t> fileDigest(const std::filesystem::path& file);

}  // namespace grass
