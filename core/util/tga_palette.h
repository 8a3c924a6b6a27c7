// Colour-mapped (palette) TGA files, decoded here (Truevision TGA File Format 2.0: image types 1,
// uncompressed, and 9, run-length encoded). OpenImageIO 2.4 looks each pixel's index up in the
// palette without checking it (a damaged file crashed the map loader), so its TGA reader is not
// given such files; this decoder checks every index, the palette's and the pixels' extent, and
// reads 8- and 16-bit indices into 15-, 16-, 24- and 32-bit palette entries.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "util/image_file.h"
#include "util/result.h"

namespace grass::core {

// The header bytes that decide (at least 3): a colour-mapped image type (1 or 9) in a file the
// TGA reader would take (named .tga, no other format's signature).
bool isColourMappedTga(const std::filesystem::path& file, std::string_view head);
// The same, reading the file's first bytes.
bool isColourMappedTga(const std::filesystem::path& file);

struct PalettedImage {
    Rgba8Pixels pixels;  // row 0 the top row shown, whatever the file's origin
    bool alpha = false;  // the palette holds alpha (32-bit entries, or 16-bit with its bit used)
};

// Decodes the whole file's bytes; fails naming `name` on a damaged or unsupported file (an
// index outside the palette, data that ends early, a side beyond maxSide, an entry size or
// index size TGA does not define).
Result<PalettedImage> decodeColourMappedTga(std::string_view bytes, const std::string& name,
                                            int maxSide);

// Reads `file` (no more than a valid image of its header's size needs) and decodes it.
Result<PalettedImage> readColourMappedTga(const std::filesystem::path& file, int maxSide);

}  // namespace grass::core
