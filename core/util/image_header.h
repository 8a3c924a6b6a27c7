// A look at an image file's header before OpenImageIO opens it. The libraries under it allocate
// what a size field claims before they read it: a damaged 391-byte EXR whose "capDate"
// attribute claimed 1.8 GB, and a PNG whose tEXt chunk claimed 1.85 GB, each took 2 GB of
// memory (found by the map_exr and map_png fuzz targets). Here every size field is checked
// against the bytes the file has left, and the image size against a limit, without allocating.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "util/result.h"

namespace grass::core {

// The largest image side grass reads (maps, grass textures): a 16384² float map is 1 GiB.
inline constexpr int MAX_IMAGE_SIDE = 16384;

// Every image grass reads becomes 4 bytes a pixel (float map texels, RGBA8 texture pixels):
// an image wider or taller than maxSide is refused, naming the memory it would need. Used on
// the header here and on OpenImageIO's spec for the formats not looked at first.
Result<void> checkImageSize(const std::string& name, std::int64_t width, std::int64_t height,
                            int maxSide);

// The OpenImageIO format name for the signature at the start of `head` ("png", "jpeg",
// "openexr", "tiff"), or "" for any other start: the formats whose readers allocate no pixels
// on open (util/image_open.h chooses a reader by it).
std::string imageFormatBySignature(std::string_view head);

// True when the file starts with the OpenEXR magic number (76 2f 31 01); false when not or
// when it cannot be read.
bool hasExrMagic(const std::filesystem::path& file);
// The same for the PNG signature (89 50 4E 47 0D 0A 1A 0A).
bool startsWithPngSignature(const std::filesystem::path& file);

// For a file with the PNG signature: util/png_chunks.h's look at its chunks (lengths against
// the bytes left, IHDR, critical chunks' CRCs, PLTE and IDAT before IEND).
Result<void> checkPngChunks(const std::filesystem::path& file, int maxSide);

// For a file with a GIF signature: fails when the logical screen (GIF89a §18), the canvas
// OpenImageIO's GIF reader allocates on open, is wider or taller than maxSide.
Result<void> checkGifScreen(const std::filesystem::path& file, int maxSide);

// checkExrHeader, checkPngChunks, checkGifScreen or checkBmpHeader (util/bmp_header.h) by the
// file's first bytes; other files pass unchecked.
Result<void> checkImageHeader(const std::filesystem::path& file, int maxSide);

// The same look at an encoded image in memory (a texture inside a .glb); `name` is what errors
// call it.
Result<void> checkImageHeaderBytes(std::string_view bytes, const std::string& name, int maxSide);

// For a file with the OpenEXR magic number: walks every header (one, or the parts of a
// multi-part file; OpenEXR file layout: name\0 type\0 int32 size, value; a header ends with an
// empty name) and fails, naming the file and the attribute, when a name runs past 255
// characters, an attribute's size is negative or beyond the end of the file, an attribute of a
// fixed-size type (box2i, int, tiledesc, …) has another size, a channel list (chlist) does not
// end where its size says or a floatvector is not whole floats (in each case OpenEXR would read
// on from elsewhere than this walk), the header is cut short, or a dataWindow (box2i) is empty
// or wider or taller than maxSide.
Result<void> checkExrHeader(const std::filesystem::path& file, int maxSide);

}  // namespace grass::core
