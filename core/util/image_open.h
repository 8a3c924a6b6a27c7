// Opening an image file (or encoded bytes in memory) with one OpenImageIO reader chosen on
// purpose. OpenImageIO's own ImageInput::open tries the reader the extension names and, when
// that one fails, every other reader in turn: a damaged .exr map that OpenEXR refused was then
// taken by the TGA reader, which has no magic number to refuse it by, and OpenImageIO 2.4's TGA
// reader indexes a colour map without checking the index (a 141-byte file crashed the map
// loader; found by the map_exr fuzz target). Here the reader is the one the file's first bytes
// name, else the one its extension names, and no other; a colour-mapped TGA is refused before
// OpenImageIO reads it (maps and grass textures decode those themselves: util/tga_palette.h), and a tiled CMYK TIFF after its header is read (OpenImageIO 2.4 writes
// past its tile buffer on one: a crash). The signatures known are those of PNG, JPEG, OpenEXR and TIFF: readers
// whose open reads a header and allocates no pixels (PNG and EXR headers are looked at first,
// util/image_header.h), so that a damaged file of another name reaches no reader that does.
// GIF and WebP are left to their extension: OpenImageIO's GIF reader allocated a 41794×11683
// canvas claimed by a 45-byte file named .png (1.5 GB) before its size could be refused.
// Only the readers of formats artists keep maps and textures in are used (PNG, JPEG, TIFF,
// OpenEXR, TGA, BMP, GIF, WebP, Radiance HDR, PNM); an .ico, a camera raw, a DICOM file or a
// video is refused by its format's name.
#pragma once

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <string>

#include "util/image_header.h"
#include "util/result.h"

namespace grass::core {

// Opens `name` for reading (through `proxy` when given: `name` then only picks the extension
// and names the image in messages; the proxy must outlive the reader). The error, without the
// name, says why no reader took it: "not an image OpenImageIO can read: …" and the reader's
// own message, or why a TGA is refused.
Result<OIIO::ImageInput::unique_ptr> openImageInput(const std::string& name,
                                                    const OIIO::ImageSpec* config = nullptr,
                                                    OIIO::Filesystem::IOProxy* proxy = nullptr);

}  // namespace grass::core
