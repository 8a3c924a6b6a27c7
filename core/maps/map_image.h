// MapImage: a single-channel float map in the mesh's UV space (density now; soil and light
// later, SPEC §9/§12), loaded through OpenImageIO from PNG (8/16-bit), TIFF, OpenEXR, JPEG...
// Values are in [0, 1]. Sampling is bilinear with clamp-to-edge, u right, v up (glTF's UV
// origin is the top-left of the image, so v = 0 is the top row: we follow glTF).
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.h"

namespace grass::core {

struct MapImage {
    int width = 0;
    int height = 0;
    std::vector<float> texels;  // row-major, row 0 = top of the image = v 0
    std::vector<std::string> warnings;  // e.g. channel conversion, for the caller to print

    float at(int x, int y) const { return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
    float sample(glm::vec2 uv) const;  // bilinear, clamp to edge, uv wraps are clamped
    float maxValue() const;
};

MapImage makeConstantMap(int width, int height, float value);

// Loads any image OpenImageIO reads. Multi-channel images are converted: RGB(A) to luminance
// (Rec. 709 weights) with a warning; NaN/Inf texels are an error; values are clamped to [0, 1].
Result<MapImage> loadMapImage(const std::filesystem::path& file);

// Writes a map (8 or 16 bit PNG, TIFF, EXR by extension) atomically.
Result<void> saveMapImage(const MapImage& map, const std::filesystem::path& file);

}  // namespace grass::core
