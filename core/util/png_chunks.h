// A look at a PNG's chunks before libpng reads them (PNG, 3rd edition, §5.3 chunk layout, §11.2
// critical chunks). libpng allocates what a chunk's length claims, and, given no error handler
// (as OpenImageIO 2.4 gives it none), prints its own "libpng error: …" line before ours: a file
// whose faults are found here gets one line, naming the file and the chunk.
#pragma once

#include <cstdint>
#include <istream>
#include <string>

#include "util/result.h"

namespace grass::core {

// `in` is positioned after the 8-byte signature; `bytes` is the file's size. Fails, naming
// `name`, when a chunk's length exceeds 2^31 − 1 or the bytes left, the file ends before IEND,
// the first chunk is not a 13-byte IHDR, IHDR holds a size of 0 or beyond maxSide or a bit depth,
// colour type, compression, filter or interlace method the standard does not define, a critical
// chunk's CRC is wrong (ancillary chunks are left to libpng, which drops bad ones with a warning),
// a paletted image has no PLTE before its IDAT, or IEND comes before any IDAT.
Result<void> checkPngChunks(std::istream& in, std::int64_t bytes, const std::string& name,
                            int maxSide);

// The PNG chunk CRC (CRC-32, polynomial 0xEDB88320, ISO 3309) of `size` bytes, continuing from
// `crc` (start with 0).
std::uint32_t pngCrc(std::uint32_t crc, const unsigned char* data, std::size_t size);

}  // namespace grass::core
