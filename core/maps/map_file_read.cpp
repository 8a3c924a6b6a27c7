#include "maps/map_file_read.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "maps/map_channels.h"
#include "util/image_file.h"
#include "util/image_header.h"
#include "util/image_layout.h"
#include "util/image_open.h"
#include "util/tga_palette.h"

namespace grass::core {

namespace fs = std::filesystem;

namespace {

// Past this, a "map" is a mistake (a 16k² float map is already 1 GiB); refused before any
// pixel is allocated.
constexpr int MAX_MAP_SIDE = MAX_IMAGE_SIDE;
// Rows read at a time from scanline files, so an RGBA file never needs its whole float copy.
constexpr int ROWS_PER_BAND = 256;
// The most channels a TIFF map is read with (all of them are: see readMapFile).
constexpr int MAX_TIFF_CHANNELS = 16;
// The most a tiled or separate-plane file may take read whole: a 16384² RGBA float map.
constexpr std::size_t MAX_WHOLE_READ_BYTES = std::size_t{4} << 30;
// What a user can do about a file the reader cannot decode (a rare compression or layout).
constexpr const char* RESAVE_HINT =
    " (saving it again as PNG, TIFF or scanline OpenEXR in another program usually helps)";

// A colour-mapped TGA, decoded here (util/tga_palette.h; OpenImageIO 2.4's reader would look
// its indices up unchecked): its palette colours read as an RGBA image's.
Result<MapImage> readColourMappedTgaMap(const fs::path& file) {
    auto decoded = readColourMappedTga(file, MAX_MAP_SIDE);
    if (!decoded)
        return decoded.error();
    const Rgba8Pixels& image = decoded->pixels;
    MapImage map;
    map.width = image.width;
    map.height = image.height;
    map.warnings.push_back(file.string() +
                           ": a colour-mapped TGA: its palette's colours converted to luminance "
                           "(Rec. 709 weights on the stored values)" +
                           (decoded->alpha ? "; alpha ignored" : ""));
    map.texels.reserve(image.pixels.size() / 4);
    for (std::size_t i = 0; i + 4 <= image.pixels.size(); i += 4) {
        const float value =
            LUMA_R * image.pixels[i] + LUMA_G * image.pixels[i + 1] + LUMA_B * image.pixels[i + 2];
        map.texels.push_back(std::clamp(value / 255.0f, 0.0f, 1.0f));
    }
    return map;
}

}  // namespace

Result<MapImage> readMapFile(const fs::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    if (!fs::exists(file, ec))
        return makeError(name, "file not found");
    if (fs::is_directory(file, ec))
        return makeError(name, "is a folder, not an image");
    // OpenEXR and libpng allocate what a damaged header claims before reading it: look first.
    if (auto header = checkImageHeader(file, MAX_MAP_SIDE); !header)
        return header.error();
    if (isColourMappedTga(file))
        return readColourMappedTgaMap(file);
    // The stored values, not colour premultiplied by alpha: alpha is not density.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto opened = openImageInput(name, &config);
    if (!opened)
        return opened.error();
    auto& in = *opened;
    const OIIO::ImageSpec spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        return makeError(name, "the image has zero size (" + std::to_string(spec.width) + "×" +
                                   std::to_string(spec.height) + ", " +
                                   std::to_string(spec.nchannels) + " channels)");
    if (auto fits = checkImageSize(name, spec.width, spec.height, MAX_MAP_SIDE); !fits)
        return fits.error();
    if (spec.depth > 1)
        return makeError(name, "a volume image cannot be a map");

    if (spec.deep)
        return makeError(name,
                         "a deep image (several samples a pixel) cannot be a map: flatten "
                         "it (e.g. oiiotool --flatten) and save it again");
    const ImageLayout layout = imageLayout(spec, in->format_name());
    if (auto fits = checkImageSize(name, layout.shownWidth(), layout.shownHeight(), MAX_MAP_SIDE);
        !fits)
        return fits.error();

    MapImage map;
    map.width = spec.width;
    map.height = spec.height;
    // Every conversion is reported: a user who painted in colour should learn that we read
    // brightness.
    const MapChannels chosen = chooseMapChannels(spec);
    if (!chosen.note.empty())
        map.warnings.push_back(name + ": " + chosen.note);
    const bool several = in->seek_subimage(1, 0);
    (void)in->geterror();  // a reader that has no second image may say so: not this file's error
    if (several)
        map.warnings.push_back(name +
                               ": holds several images (parts, pages or frames): the "
                               "first read");
    if (!in->seek_subimage(0, 0))
        return makeError(name, "cannot read the pixels: " + oneLine(in->geterror()));
    // Alpha is read too, never as the value: OpenImageIO 2.4's WebP reader multiplies the colour
    // by it whatever oiio:UnassociatedAlpha says (divided back out here), and its GIF reader
    // makes transparent pixels 0 (said in a note).
    const std::string format = in->format_name();
    const int alpha = format == "webp" || format == "gif" ? alphaChannelOf(spec) : -1;
    // One read of the channels from the first used to the last: OpenImageIO hands R, G, B, A
    // (and Z) out first whatever the file's order (OpenEXR sorts channels by name), so this span
    // is at most four channels.
    int begin = alpha >= 0 ? alpha : chosen.weights.front().first, end = begin + 1;
    for (const auto& weighted : chosen.weights) {
        begin = std::min(begin, weighted.first);
        end = std::max(end, weighted.first + 1);
    }
    // OpenImageIO 2.4's TIFF reader frees memory it did not allocate when a damaged strip fails
    // a read of only some of a file's channels (found by the map_tiff fuzz target; reading all
    // of them is sound): TIFFs are read with every channel, and a TIFF of more channels than
    // any picture has is refused.
    if (format == "tiff") {
        if (spec.nchannels > MAX_TIFF_CHANNELS)
            return makeError(name, "a TIFF of " + std::to_string(spec.nchannels) +
                                       " channels is not read as a map (at most " +
                                       std::to_string(MAX_TIFF_CHANNELS) +
                                       "): save the channel you mean as a greyscale image");
        begin = 0;
        end = spec.nchannels;
    }
    const int channels = end - begin;
    const auto rowFloats =
        static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(channels);
    map.texels.reserve(static_cast<std::size_t>(spec.width) *
                       static_cast<std::size_t>(spec.height));
    std::size_t transparent = 0;
    const auto fold = [&](const std::vector<float>& pixels) {
        const auto stride = static_cast<std::size_t>(channels);
        for (std::size_t i = 0; i + stride <= pixels.size(); i += stride) {
            float value = 0.0f;
            for (const auto& [c, weight] : chosen.weights)
                value += weight * pixels[i + static_cast<std::size_t>(c - begin)];
            if (alpha >= 0) {
                const float coverage = pixels[i + static_cast<std::size_t>(alpha - begin)];
                if (coverage <= 0.0f)
                    ++transparent;
                else if (format == "webp")
                    value /= coverage;
            }
            map.texels.push_back(value);
        }
    };
    std::vector<float> band;
    // Bands keep an RGBA file from needing its whole float copy; libtiff reads the planes of a
    // separate-plane TIFF (one plane after another, compressed) only from the top, whole.
    const bool wholeOnly =
        spec.tile_width != 0 || spec.get_string_attribute("planarconfig") == "separate";
    const std::size_t wholeBytes =
        rowFloats * static_cast<std::size_t>(spec.height) * sizeof(float);
    if (wholeOnly && wholeBytes > MAX_WHOLE_READ_BYTES)
        return makeError(name, "a tiled or separate-plane image of " + std::to_string(spec.width) +
                                   "×" + std::to_string(spec.height) + " pixels and " +
                                   std::to_string(channels) + " channels needs " +
                                   std::to_string(wholeBytes >> 30) +
                                   " GiB to read, more than a map may take: save it with strips "
                                   "(scanlines) or fewer channels");
    for (int row = 0, bandRows = wholeOnly ? spec.height : ROWS_PER_BAND; row < spec.height;
         row += bandRows) {
        const int rows = std::min(bandRows, spec.height - row);
        band.assign(rowFloats * static_cast<std::size_t>(rows), 0.0f);
        const bool read = wholeOnly
                              ? in->read_image(0, 0, begin, end, OIIO::TypeDesc::FLOAT, band.data())
                              : in->read_scanlines(0, 0, spec.y + row, spec.y + row + rows, 0,
                                                   begin, end, OIIO::TypeDesc::FLOAT, band.data());
        if (!read)
            return makeError(name,
                             "cannot read the pixels: " + oneLine(in->geterror()) + RESAVE_HINT);
        fold(band);
    }
    in->close();
    if (transparent > 0)
        map.warnings.push_back(
            name + ": " + std::to_string(transparent) + " transparent texels read as 0 (" +
            (format == "gif" ? "the GIF reader keeps no colour for them"
                             : "the WebP reader keeps their colour multiplied by 0") +
            "); save the map without transparency to keep their values");
    if (layout.windowed() || layout.orientation != 1) {
        map.texels = showImage(map.texels, 1, layout);
        map.width = layout.shownWidth();
        map.height = layout.shownHeight();
        for (const std::string& note : imageLayoutNotes(layout))
            map.warnings.push_back(name + ": " + note);
    }

    bool clamped = false;
    for (std::size_t i = 0; i < map.texels.size(); ++i) {
        float& t = map.texels[i];
        if (!std::isfinite(t)) {
            const std::size_t x = i % static_cast<std::size_t>(map.width);
            const std::size_t y = i / static_cast<std::size_t>(map.width);
            return makeError(name, std::string("texel (") + std::to_string(x) + ", " +
                                       std::to_string(y) + ") is " +
                                       (std::isnan(t) ? "NaN" : "infinite") +
                                       "; maps must hold finite values in [0, 1]");
        }
        if (t < 0.0f || t > 1.0f) {
            clamped = true;
            t = std::clamp(t, 0.0f, 1.0f);
        }
    }
    if (clamped)
        map.warnings.push_back(name + ": values outside [0, 1] were clamped");
    return map;
}

}  // namespace grass::core
