// A look at a BMP file's headers before OpenImageIO 2.4's reader opens it. Two kinds of valid
// file go wrong there (found with bmpsuite and Pillow's test images): a 32-bit image whose colour
// masks (BI_BITFIELDS) put the channels in another order is read as if they were B, G, R, A
// (wrong colours, silently), and a header size the reader does not know (OS/2 2.x's 64 bytes) is
// read from uninitialised memory (a random image size). Both are refused, saying what to do.
#pragma once

#include <string>
#include <string_view>

#include "util/result.h"

namespace grass::core {

// The bytes a BMP's check reads: the file header (14), the DIB header up to the colour masks
// that follow a 40-byte header (54 .. 66).
inline constexpr std::size_t BMP_HEAD_BYTES = 66;

// `head`: the file's first bytes (up to BMP_HEAD_BYTES; a shorter file is damaged). Fails,
// naming `name`, on a DIB header of a size OpenImageIO 2.4 does not read (it reads 12, 40, 52,
// 56, 108 and 124), an image wider or taller than maxSide, or a 32-bit image whose red, green
// and blue masks are not 0x00ff0000, 0x0000ff00 and 0x000000ff.
Result<void> checkBmpHeader(std::string_view head, const std::string& name, int maxSide);

}  // namespace grass::core
