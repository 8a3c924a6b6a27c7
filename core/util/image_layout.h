// Where an image's stored pixels go in the picture a viewer shows. Two things in a file move
// them: an orientation tag (EXIF/TIFF `Orientation`, 1–8: a camera held on its side stores its
// rows sideways and says so), and OpenEXR's data window, the stored rectangle inside the display
// window that is the picture (pixels outside it are black, by the format's definition). A map
// reads v = 0 as the top row a viewer shows, so both are applied after reading; `Orientation`
// as OpenImageIO reports it for JPEG, TIFF, PNG (eXIf) and WebP, the windows for every format
// (only OpenEXR's differ in practice).
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace grass::core {

struct ImageLayout {
    int orientation = 1;  // EXIF: 1 as stored, 2 mirrored, 3 turned 180°, … 6 turned 90° clockwise
    // The data window (what was read) within the display window, in the display's pixels (a
    // file may put it anywhere, even far outside: 64 bits, so no offset overflows).
    std::int64_t dataX = 0, dataY = 0;
    int dataWidth = 0, dataHeight = 0;
    int fullWidth = 0, fullHeight = 0;

    bool windowed() const {
        return dataX != 0 || dataY != 0 || dataWidth != fullWidth || dataHeight != fullHeight;
    }
    // The size of the picture a viewer shows: the display window, turned by the orientation.
    int shownWidth() const { return orientation >= 5 ? fullHeight : fullWidth; }
    int shownHeight() const { return orientation >= 5 ? fullWidth : fullHeight; }
};

// The alpha channel: OpenImageIO's, when it lies within the channels (its GIF reader names
// channel 4 of 4), else the one named A or Alpha; -1 when there is none.
int alphaChannelOf(const OIIO::ImageSpec& spec);

// The layout `spec` describes, read by OpenImageIO's `format` reader. Windows count for OpenEXR
// only: OpenImageIO also puts a PNG's oFFs chunk (written by a crop that kept its page offset)
// in the data window's origin, which viewers ignore, as grass does. An orientation outside 1–8
// reads as 1 (as stored); an empty display window, or an environment map's (one face of a
// cube), as the data window. The data window may lie partly or wholly outside the display
// window: what lies outside is not shown. The caller checks the shown size before showImage
// allocates it.
ImageLayout imageLayout(const OIIO::ImageSpec& spec, std::string_view format);

// What a user should be told about `layout` ("turned 90° clockwise by its EXIF orientation",
// "its data window 315×100 at (1012, 1097) placed in its 1920×1920 display window, black
// around it"); empty when the image is shown as stored.
std::vector<std::string> imageLayoutNotes(const ImageLayout& layout);

// `data` (dataWidth × dataHeight pixels of `channels` values, row 0 the first stored) as shown:
// shownWidth() × shownHeight() pixels, row 0 the top. Zero outside the data window.
template <typename T>
std::vector<T> showImage(const std::vector<T>& data, std::size_t channels,
                         const ImageLayout& layout);

}  // namespace grass::core
