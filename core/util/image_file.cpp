#include "util/image_file.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "util/atomic_file.h"
#include "util/image_header.h"
#include "util/image_open.h"
#include "util/printable_text.h"

namespace grass {

namespace fs = std::filesystem;

std::string oneLine(std::string text) {
    // A reader that fails on every strip says so for each (200 lines for one damaged TIFF):
    // the first three are the message.
    constexpr std::size_t MOST_LINES = 3;
    const std::string joined = joinedLines(text, MOST_LINES);
    return joined.empty() ? "the reader gave no reason (a damaged file, or a kind of it the "
                            "reader does not know)"
                          : joined;
}

Result<void> checkImageWritable(const fs::path& file) {
    if (auto writable = checkFileWritable(file, "render.png"); !writable)
        return writable;
    if (!OIIO::ImageOutput::create(file.string()))
        return makeError(file.string(), "unknown image format \"" + file.extension().string() +
                                            "\" (use .png, .tif, .jpg or .exr)");
    return {};
}

Result<void> verifyWrittenImage(const fs::path& written, const std::string& name, int width,
                                int height) {
    const std::string failed = "write failed: the file did not read back whole (disk full?); ";
    // A PNG is whole when its chunks run to IEND: walked here, since libpng would print its
    // own lines on stderr about a truncated file.
    if (core::startsWithPngSignature(written)) {
        if (auto png = core::checkPngChunks(written, core::MAX_IMAGE_SIDE); !png)
            return makeError(name, failed + png.error().message);
        return {};
    }
    auto opened = core::openImageInput(written.string());
    if (!opened)
        return makeError(name, failed + opened.error().message);
    auto& in = *opened;
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width != width || spec.height != height)
        return makeError(name, failed + "it holds " + std::to_string(spec.width) + "×" +
                                   std::to_string(spec.height) + " pixels");
    std::vector<float> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                              static_cast<std::size_t>(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
        return makeError(name, failed + oneLine(in->geterror()));
    return {};
}

Result<void> writeRgba8Image(const fs::path& file, int width, int height,
                             std::span<const std::uint8_t> pixels) {
    if (width <= 0 || height <= 0 ||
        pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
        return makeError(file.string(), "internal: image size does not match its pixels");
    if (auto writable = checkImageWritable(file); !writable)
        return writable;
    std::error_code ec;
    const fs::path temporary = temporaryPathFor(file);
    auto out = OIIO::ImageOutput::create(file.string());
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    if (!out->open(temporary.string(), spec)) {
        fs::remove(temporary, ec);
        return makeError(file.string(), "cannot write: " + oneLine(out->geterror()));
    }
    const bool written = out->write_image(OIIO::TypeDesc::UINT8, pixels.data());
    const bool closed = out->close();
    if (!written || !closed) {
        fs::remove(temporary, ec);
        return makeError(file.string(), "write failed: " + oneLine(out->geterror()));
    }
    out.reset();
    if (auto whole = verifyWrittenImage(temporary, file.string(), width, height); !whole) {
        fs::remove(temporary, ec);
        return whole;
    }
    return commitTemporaryFile(temporary, file);
}

namespace {

// An open image read whole as RGBA8 (grey → RGB, no alpha → 255), refused beyond `maxSide`
// before its pixels are allocated.
Result<Rgba8Pixels> readOpenImage(OIIO::ImageInput& in, const std::string& name, int maxSide) {
    const OIIO::ImageSpec& spec = in.spec();
    if (spec.nchannels <= 0)
        return makeError(name, "the image has no channels");
    if (auto fits = core::checkImageSize(name, spec.width, spec.height, maxSide); !fits)
        return fits.error();
    const int channels = spec.nchannels;
    std::vector<std::uint8_t> raw(static_cast<std::size_t>(spec.width) *
                                  static_cast<std::size_t>(spec.height) *
                                  static_cast<std::size_t>(channels));
    if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
        return makeError(name, "cannot read: " + oneLine(in.geterror()));
    Rgba8Pixels image;
    image.width = spec.width;
    image.height = spec.height;
    image.pixels.resize(static_cast<std::size_t>(spec.width) *
                        static_cast<std::size_t>(spec.height) * 4);
    for (std::size_t i = 0; i < image.pixels.size() / 4; ++i) {
        const std::uint8_t* p = raw.data() + i * static_cast<std::size_t>(channels);
        const bool grey = channels < 3;
        image.pixels[4 * i + 0] = p[0];
        image.pixels[4 * i + 1] = grey ? p[0] : p[1];
        image.pixels[4 * i + 2] = grey ? p[0] : p[2];
        image.pixels[4 * i + 3] = channels == 4 ? p[3] : (channels == 2 ? p[1] : 255);
    }
    return image;
}

}  // namespace

Result<Rgba8Pixels> readRgba8Image(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec))
        return makeError(file.string(), "file not found");
    if (auto header = core::checkImageHeader(file, core::MAX_IMAGE_SIDE); !header)
        return header.error();
    auto in = core::openImageInput(file.string());
    if (!in)
        return in.error();
    return readOpenImage(**in, file.string(), core::MAX_IMAGE_SIDE);
}

Result<Rgba8Pixels> decodeRgba8Image(std::string_view bytes, const std::string& name,
                                     std::string_view extension, int maxSide) {
    if (auto header = core::checkImageHeaderBytes(bytes, name, maxSide); !header)
        return header.error();
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    // The extension picks the decoder; the name is only for messages.
    auto in = core::openImageInput("memory" + std::string(extension), nullptr, &memory);
    if (!in)
        return makeError(name, in.error().message);
    return readOpenImage(**in, name, maxSide);
}

}  // namespace grass
