#include "util/image_layout.h"

#include <algorithm>
#include <cstdint>

#include "util/file_extension.h"

namespace grass::core {

namespace {

struct Pixel {
    int x, y;
};

// The stored pixel (in the display window, stored orientation: width w, height h) that shows
// at (X, Y) of the shown picture. EXIF's orientations name where the stored row 0 and column
// 0 lie as shown: 5 row 0 left, column 0 top (a transpose); 6 row 0 right, column 0 top (turn
// 90° clockwise to show); 7 row 0 right, column 0 bottom; 8 row 0 left, column 0 bottom.
Pixel storedPixel(int orientation, int X, int Y, int w, int h) {
    switch (orientation) {
        case 2:
            return {w - 1 - X, Y};
        case 3:
            return {w - 1 - X, h - 1 - Y};
        case 4:
            return {X, h - 1 - Y};
        case 5:
            return {Y, X};
        case 6:
            return {Y, h - 1 - X};
        case 7:
            return {w - 1 - Y, h - 1 - X};
        case 8:
            return {w - 1 - Y, X};
        default:
            return {X, Y};
    }
}

const char* orientationWords(int orientation) {
    switch (orientation) {
        case 2:
            return "mirrored left to right";
        case 3:
            return "turned 180°";
        case 4:
            return "mirrored top to bottom";
        case 5:
            return "mirrored along its diagonal";
        case 6:
            return "turned 90° clockwise";
        case 7:
            return "mirrored along its other diagonal";
        case 8:
            return "turned 90° anticlockwise";
        default:
            return "as stored";
    }
}

}  // namespace

int alphaChannelOf(const OIIO::ImageSpec& spec) {
    if (spec.alpha_channel >= 0 && spec.alpha_channel < spec.nchannels)
        return spec.alpha_channel;
    for (int c = 0; c < spec.nchannels; ++c) {
        const std::string lower = asciiLowerCase(std::string(spec.channel_name(c)));
        if (lower == "a" || lower == "alpha")
            return c;
    }
    return -1;
}

ImageLayout imageLayout(const OIIO::ImageSpec& spec, std::string_view format) {
    ImageLayout layout;
    const int orientation = spec.get_int_attribute("Orientation", 1);
    layout.orientation = orientation >= 1 && orientation <= 8 ? orientation : 1;
    layout.dataWidth = std::max(spec.width, 0);
    layout.dataHeight = std::max(spec.height, 0);
    // An OpenEXR environment map's display window is one face of its cube (six stacked in the
    // data window): the whole data is the picture.
    const bool environment =
        spec.get_string_attribute("textureformat").find("Environment") != std::string::npos;
    if (format == "openexr" && spec.full_width > 0 && spec.full_height > 0 && !environment) {
        layout.fullWidth = spec.full_width;
        layout.fullHeight = spec.full_height;
        layout.dataX = std::int64_t{spec.x} - spec.full_x;
        layout.dataY = std::int64_t{spec.y} - spec.full_y;
    } else {
        layout.fullWidth = layout.dataWidth;
        layout.fullHeight = layout.dataHeight;
    }
    return layout;
}

std::vector<std::string> imageLayoutNotes(const ImageLayout& layout) {
    std::vector<std::string> notes;
    if (layout.windowed())
        notes.push_back("its data window " + std::to_string(layout.dataWidth) + "×" +
                        std::to_string(layout.dataHeight) + " at (" + std::to_string(layout.dataX) +
                        ", " + std::to_string(layout.dataY) + ") placed in its " +
                        std::to_string(layout.fullWidth) + "×" + std::to_string(layout.fullHeight) +
                        " display window, black (0) outside it");
    if (layout.orientation != 1)
        notes.push_back(std::string("shown ") + orientationWords(layout.orientation) +
                        " as its orientation tag says (" + std::to_string(layout.orientation) +
                        "), as viewers show it");
    return notes;
}

template <typename T>
std::vector<T> showImage(const std::vector<T>& data, std::size_t channels,
                         const ImageLayout& layout) {
    const int shownWidth = layout.shownWidth(), shownHeight = layout.shownHeight();
    std::vector<T> shown(
        static_cast<std::size_t>(shownWidth) * static_cast<std::size_t>(shownHeight) * channels,
        T(0));
    for (int Y = 0; Y < shownHeight; ++Y) {
        for (int X = 0; X < shownWidth; ++X) {
            const Pixel stored =
                storedPixel(layout.orientation, X, Y, layout.fullWidth, layout.fullHeight);
            const std::int64_t dx = stored.x - layout.dataX, dy = stored.y - layout.dataY;
            if (dx < 0 || dy < 0 || dx >= layout.dataWidth || dy >= layout.dataHeight)
                continue;
            const std::size_t from =
                (static_cast<std::size_t>(dy) * static_cast<std::size_t>(layout.dataWidth) +
                 static_cast<std::size_t>(dx)) *
                channels;
            const std::size_t to =
                (static_cast<std::size_t>(Y) * static_cast<std::size_t>(shownWidth) +
                 static_cast<std::size_t>(X)) *
                channels;
            std::copy_n(data.begin() + static_cast<std::ptrdiff_t>(from), channels,
                        shown.begin() + static_cast<std::ptrdiff_t>(to));
        }
    }
    return shown;
}

template std::vector<float> showImage(const std::vector<float>&, std::size_t, const ImageLayout&);
template std::vector<std::uint8_t> showImage(const std::vector<std::uint8_t>&, std::size_t,
                                             const ImageLayout&);

}  // namespace grass::core
