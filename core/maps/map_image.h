// MapImage: a single-channel float map in the mesh's UV space (density now; soil and light
// later, SPEC §9/§12), loaded through OpenImageIO from PNG (8/16-bit), TIFF, OpenEXR, JPEG...
// Values are in [0, 1]. Sampling is bilinear with clamp-to-edge, texel centres at
// ((i + 0.5) / width, (j + 0.5) / height); u runs right and v runs down the image: glTF's UV
// origin is the image's top-left corner, so v = 0 is the top row (we follow glTF).
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.h"

namespace grass::core {

struct MapImage {
    int width = 0;
    int height = 0;
    std::vector<float> texels;          // row-major, row 0 = top of the image = v 0
    std::vector<std::string> warnings;  // e.g. channel conversion, for the caller to print

    float at(int x, int y) const {
        return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
    float sample(glm::vec2 uv) const;  // bilinear, clamp to edge, uv wraps are clamped
    float maxValue() const;
};

MapImage makeConstantMap(int width, int height, float value);

// Loads any image OpenImageIO reads. Multi-channel images are converted: RGB(A) to luminance
// (Rec. 709 weights) with a warning; NaN/Inf texels are an error; values are clamped to [0, 1].
Result<MapImage> loadMapImage(const std::filesystem::path& file);

// How saved texels are stored. Auto: 16-bit for .png/.tif/.tiff (1/65535 steps, finer than any
// brush stroke), 32-bit float for .exr (lossless).
enum class MapSampleFormat { Auto, UInt8, UInt16, Float };

// Writes a map (8 or 16 bit PNG, TIFF, EXR by extension) atomically. The format must suit the
// extension (PNG holds 8 or 16 bits, EXR half or float: Float there is float, UInt* is refused).
Result<void> saveMapImage(const MapImage& map, const std::filesystem::path& file,
                          MapSampleFormat format = MapSampleFormat::Auto);

}  // namespace grass::core
