// Writing 8-bit RGBA images (renders, screenshots) through OpenImageIO; the format follows the
// extension (.png, .tif, .jpg, .exr...). Atomic: a temporary file, then rename.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace grass {

// Checks before any work is done that `file` can be written: its folder exists, it is not a
// folder, and OpenImageIO knows its extension.
Result<void> checkImageWritable(const std::filesystem::path& file);

// `pixels`: width × height × 4 bytes, row 0 = top.
Result<void> writeRgba8Image(const std::filesystem::path& file, int width, int height,
                             std::span<const std::uint8_t> pixels);

struct Rgba8Pixels {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // RGBA, row 0 = top
};
// Reads a just-written image file back in full (size and every pixel) before it replaces
// anything: OpenImageIO's PNG writer can report success when the disk filled up under it.
// `name` is the file the user asked for, which the error names.
Result<void> verifyWrittenImage(const std::filesystem::path& written, const std::string& name,
                                int width, int height);

// OpenImageIO's error text on one line (its messages may hold newlines, trailing spaces and the
// same line twice), or a sentence saying it gave none.
std::string oneLine(std::string text);

// Reads any image as RGBA8 (grey → RGB, no alpha → 255). For tests and goldens.
Result<Rgba8Pixels> readRgba8Image(const std::filesystem::path& file);
// The same for an encoded image in memory (a texture inside a .glb): `extension` (".png",
// ".jpg") picks the decoder, `name` is what messages call it; sides beyond `maxSide` are
// refused before the pixels are allocated.
Result<Rgba8Pixels> decodeRgba8Image(std::string_view bytes, const std::string& name,
                                     std::string_view extension, int maxSide);

}  // namespace grass
