// MapImage: a single-channel float map in the mesh's UV space (density now; soil and light
// later, SPEC §9/§12), loaded through OpenImageIO from PNG (8/16-bit), TIFF, OpenEXR, JPEG...
// Values are in [0, 1]. Sampling is bilinear with clamp-to-edge, texel centres at
// ((i + 0.5) / width, (j + 0.5) / height); u runs right and v runs down the image: glTF's UV
// origin is the image's top-left corner, so v = 0 is the top row (we follow glTF).
#pragma once

#include <filesystem>
#include <string>
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

// A width × height map of `value` clamped to [0, 1] (NaN gives 0). A size <= 0 gives an empty
// 0 × 0 map, which saveMapImage and resampleMap refuse.
MapImage makeConstantMap(int width, int height, float value);

// The map at another size, texel centres matched in UV space (as MapImage::sample). Per axis:
// growing or shrinking by at most 2× samples bilinearly at the new texel centres (clamp to
// edge); shrinking by more than 2× averages each new texel's whole footprint in the source
// (area-weighted box), so fine detail becomes its mean instead of aliasing. The same size
// gives a bit-exact copy. Values stay in [0, 1]; the warnings are kept.
// Preconditions (GRASS_ASSERT): width, height >= 1 and `map` is non-empty with matching texels.
MapImage resampleMap(const MapImage& map, int width, int height);

// Loads any image OpenImageIO reads; errors name the file (missing, a folder, not an image,
// truncated, zero or more than 16384 texels a side, NaN/Inf texels with the first one's
// position). Channels become one value, each conversion with a warning saying what was done:
//   1 channel: used as is (no warning);   2: grey + alpha, grey used, alpha ignored;
//   3: RGB to luminance (Rec. 709 weights on the stored values);   4: RGBA, the same, alpha
//   ignored;   more: luminance of the first 3, the rest ignored.
// Values outside [0, 1] are clamped, with a warning.
Result<MapImage> loadMapImage(const std::filesystem::path& file);

// loadMapImage, then resampleMap to width × height if the file has another size, with a warning
// "<file>: resampled from 300×200 to 512×512". A size outside [1, 16384] is an error.
Result<MapImage> loadMapImageAt(const std::filesystem::path& file, int width, int height);

// How saved texels are stored. Auto: 16-bit for .png/.tif/.tiff (1/65535 steps, finer than any
// brush stroke), 32-bit float for .exr (lossless), 8-bit otherwise. Half (16-bit float, 11
// significant bits: relative error <= 2^-11) is for .exr only.
enum class MapSampleFormat { Auto, UInt8, UInt16, Half, Float };

// Writes a map (PNG 8/16 bit; TIFF 8/16 bit or float; EXR half or float, by extension)
// atomically. A format the extension cannot hold is refused, never silently changed.
Result<void> saveMapImage(const MapImage& map, const std::filesystem::path& file,
                          MapSampleFormat format = MapSampleFormat::Auto);

}  // namespace grass::core
