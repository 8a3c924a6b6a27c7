#include "util/image_open.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <utility>

#include "util/file_extension.h"
#include "util/image_file.h"
#include "util/tga_palette.h"

namespace grass::core {

namespace {

// Enough for the longest signature (PNG's 8 bytes) and the TGA header's image type (byte 2).
constexpr std::size_t HEAD_BYTES = 8;

// TIFF 6.0's PhotometricInterpretation 5: separated (CMYK).
constexpr int TIFF_PHOTOMETRIC_SEPARATED = 5;

std::string readHead(const std::string& name, OIIO::Filesystem::IOProxy* proxy) {
    std::string head(HEAD_BYTES, '\0');
    std::size_t got = 0;
    if (proxy) {
        got = proxy->pread(head.data(), head.size(), 0);
    } else {
        std::ifstream in(name, std::ios::binary);
        in.read(head.data(), static_cast<std::streamsize>(head.size()));
        got = static_cast<std::size_t>(in.gcount());
    }
    head.resize(got);
    return head;
}

}  // namespace

Result<OIIO::ImageInput::unique_ptr> openImageInput(const std::string& name,
                                                    const OIIO::ImageSpec* config,
                                                    OIIO::Filesystem::IOProxy* proxy) {
    const std::string head = readHead(name, proxy);
    const std::string bySignature = imageFormatBySignature(head);
    // A format name or a bare extension makes OpenImageIO create that reader without looking
    // at the file (given a whole file name, create() tries the file on every reader until one
    // takes it, the trial this avoids).
    const std::string extension = lowerExtension(name);
    if (bySignature.empty() && extension.size() < 2)
        return makeError(name,
                         "not an image OpenImageIO can read: no known signature and no "
                         "extension to choose a reader by");
    auto in = OIIO::ImageInput::create(bySignature.empty() ? extension.substr(1) : bySignature);
    if (!in) {
        (void)OIIO::geterror();  // taken, so that no later message of this thread repeats it
        return makeError(name, "not an image OpenImageIO can read: no reader for \"" + extension +
                                   "\" files, and no known signature");
    }
    // The formats maps and textures are kept in (util/file_extension.h). OpenImageIO 2.4 also
    // reads icons, camera raws, DICOM, video frames (FFmpeg), OpenVDB volumes and more, whose
    // readers see few such files and no fuzzing here: its ICO reader divides by zero (SIGFPE)
    // on image-rs's regression inputs, for one. The signatures name readable formats only.
    const auto& readable = readableImageExtensions();
    if (bySignature.empty() &&
        std::find(readable.begin(), readable.end(), extension) == readable.end())
        return makeError(name, std::string("an image in OpenImageIO's \"") + in->format_name() +
                                   "\" format, which grass does not read: use PNG, JPEG, TIFF, "
                                   "OpenEXR, TGA, BMP, GIF, WebP, Radiance HDR or PNM");
    if (isColourMappedTga(name, head))
        return makeError(name,
                         "a colour-mapped (palette) TGA is not read: OpenImageIO 2.4 "
                         "looks its pixels up in the palette without checking them, and a "
                         "damaged one crashes it; save the image as greyscale or "
                         "true-colour TGA, or as PNG");
    if (proxy && !in->set_ioproxy(proxy))
        return makeError(
            name, std::string("the ") + in->format_name() + " reader cannot read from memory");
    OIIO::ImageSpec spec;
    const bool opened = config ? in->open(name, spec, *config) : in->open(name, spec);
    if (!opened)
        return makeError(name, "not an image OpenImageIO can read: " + oneLine(in->geterror()));
    // CMYK ("separated") TIFF in tiles: OpenImageIO 2.4 converts each tile to RGB in a buffer
    // sized for fewer channels than libtiff writes into it (a heap overrun, a crash; found with a
    // real JPEG-compressed file, and LZW does it too). In strips it reads them.
    const OIIO::ImageSpec& openedSpec = in->spec();
    if (std::string(in->format_name()) == "tiff" && openedSpec.tile_width > 0 &&
        openedSpec.get_int_attribute("tiff:PhotometricInterpretation", -1) ==
            TIFF_PHOTOMETRIC_SEPARATED)
        return makeError(name,
                         "a tiled CMYK TIFF is not read: OpenImageIO 2.4 writes past its tile "
                         "buffer on it (a crash); save the image as RGB, or with strips instead "
                         "of tiles, or as PNG");
    return in;
}

}  // namespace grass::core
