// Atomic saves (DEVELOPERS.md non-negotiable 4): write everything to a temporary file in the
// target's folder, flush it to disk, then rename it over the target. A crash or kill leaves
// either the old file or the new one, never half of one.
#pragma once

#include <filesystem>
#include <string_view>

#include "util/result.h"

namespace grass {

// A temporary name next to `target`, keeping its extension (image writers pick the format by
// extension): "dir/.name.tmp-<pid>.ext".
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Writes `bytes` to `target` atomically.
Result<void> writeFileAtomic(const std::filesystem::path& target, std::string_view bytes);

// Removes the temporaries (temporaryPathFor's ".name.tmp-<pid>[.ext]") in `folder` (not its
// subfolders) whose process no longer runs: what a save killed mid-write (SIGKILL, power loss)
// left. The target files themselves are never touched. Returns how many were removed; a folder
// that cannot be read removes nothing.
std::size_t removeStaleTemporaries(const std::filesystem::path& folder);

// Flushes a finished temporary file and renames it over `target`; removes it on failure.
Result<void> commitTemporaryFile(const std::filesystem::path& temporary,
                                 const std::filesystem::path& target);

// Fails early (before long work) when `target` cannot be a file to write: it is a folder or its
// folder does not exist. `example` names a valid file in the message ("report.json").
Result<void> checkFileWritable(const std::filesystem::path& target, std::string_view example);

// Reads a whole file; the error names the file.
Result<std::string> readFile(const std::filesystem::path& file);

}  // namespace grass
