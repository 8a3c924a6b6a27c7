// Atomic saves (DEVELOPERS.md non-negotiable 4): write everything to a temporary file in the
// target's folder, flush it to disk, then rename it over the target. A crash or kill leaves
// either the old file or the new one, never half of one.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>

#include "util/result.h"

namespace grass {

// A temporary name next to `target`, keeping its extension (image writers pick the format by
// extension), and unique within the process: "dir/.name.tmp-<pid>-<n>.ext".
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Writes `bytes` to `target` atomically.
Result<void> writeFileAtomic(const std::filesystem::path& target, std::string_view bytes);

// Removes the temporaries (temporaryPathFor's ".name.tmp-<pid>[-<n>][.ext]") in `folder` (not its
// subfolders) whose process no longer runs: what a save killed mid-write (SIGKILL, power loss)
// left. The target files themselves are never touched. Returns how many were removed; a folder
// that cannot be read removes nothing.
std::size_t removeStaleTemporaries(const std::filesystem::path& folder);

// Flushes a finished temporary file and renames it over `target`; removes it on failure. A
// temporary shorter than `minimumBytes` (default: empty) is refused as a failed write: some
// writers (libpng inside OpenImageIO) drop the error of a full disk and report success.
Result<void> commitTemporaryFile(const std::filesystem::path& temporary,
                                 const std::filesystem::path& target,
                                 std::uint64_t minimumBytes = 1);

// Copies `source` to `target` through a temporary in the target's folder and never replaces a
// file: true when copied, false when `target` was there already (it is kept as it was, and the
// copy made meanwhile is removed). Two copies to one target at once (the editor's collider
// worker and an Import mesh… of the same file) leave one whole file, never a mixture, never an
// error; a killed copy leaves no half of one under the target's name.
Result<bool> copyFileAtomic(const std::filesystem::path& source,
                            const std::filesystem::path& target);

// Fails early (before long work) when `target` cannot be a file to write: it is a folder or its
// folder does not exist. `example` names a valid file in the message ("report.json").
Result<void> checkFileWritable(const std::filesystem::path& target, std::string_view example);

// The most any reader takes in by default (a glTF mesh with its buffers), and the most a JSON
// document of ours may be (project.json, tradeoff.json, bench results, an export's .gltf): a
// 200 MB project.json would take 4-5 GB of memory as a JSON tree before it could be refused.
constexpr std::uint64_t MAX_READ_BYTES = std::uint64_t{2} << 30;
constexpr std::uint64_t MAX_JSON_FILE_BYTES = std::uint64_t{64} << 20;

// Refuses anything but a regular file (after following links) without opening it for long: a
// folder, a device such as /dev/zero, a FIFO that would block for ever, a socket. The error
// names the file and what it is instead.
Result<void> checkRegularFile(const std::filesystem::path& file);

// Reads a whole regular file of at most `maxBytes` (checked before a byte is read); the error
// names the file, and the size and the cap when it is too large.
Result<std::string> readFile(const std::filesystem::path& file,
                             std::uint64_t maxBytes = MAX_READ_BYTES);

}  // namespace grass
