// What every fuzz target shares. The readers take paths (as the application calls them), so
// each input is written to a file in a per-process scratch folder, read through the
// application's entry point, and removed: $TMPDIR/grass-fuzz-<pid>/ (/tmp without TMPDIR),
// itself removed when the process exits normally. tests/fuzz/run_fuzz.sh also points TMPDIR at
// a folder of its own, so that not even a crashed run leaves anything behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

#include "util/result.h"

namespace grass::fuzz {

const std::filesystem::path& scratchDir();

// Aborts when the file cannot be written: the harness is broken, not the reader.
void writeBytes(const std::filesystem::path& file, std::span<const std::uint8_t> bytes);

// Removes everything inside the scratch folder (the folder stays).
void clearScratch();

// A failed check of what the reader promises: prints `what` and aborts, so that libFuzzer
// keeps the input as a crash.
[[noreturn]] void fail(std::string_view what);

// What every reader promises of its errors: one line that names the file. Aborts otherwise.
void checkError(const Error& error);

}  // namespace grass::fuzz
