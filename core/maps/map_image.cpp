#include "maps/map_image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "maps/map_file_read.h"
#include "util/assert.h"
#include "util/atomic_file.h"
#include "util/file_extension.h"
#include "util/image_file.h"
#include "util/image_header.h"

namespace grass::core {

namespace fs = std::filesystem;

namespace {

Result<void> writeMap(const MapImage& map, const fs::path& file, MapSampleFormat format) {
    const std::string name = file.string();
    if (map.width <= 0 || map.height <= 0)
        return makeError(name, "the map is empty (" + std::to_string(map.width) + "×" +
                                   std::to_string(map.height) + "); nothing to write");
    if (map.texels.size() !=
        static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height))
        return makeError(name, "internal: the map's size does not match its texels");
    const std::string ext = lowerExtension(file);
    const bool png = ext == ".png", exr = ext == ".exr", tiff = ext == ".tif" || ext == ".tiff";
    if (format == MapSampleFormat::Auto)
        format = exr ? MapSampleFormat::Float
                     : (png || tiff ? MapSampleFormat::UInt16 : MapSampleFormat::UInt8);
    if (png && format == MapSampleFormat::Float)
        return makeError(name, "PNG holds 8 or 16 bits per texel, not float; use .exr or .tif");
    if (exr && format != MapSampleFormat::Float && format != MapSampleFormat::Half)
        return makeError(name, "EXR holds half or float texels; use .png or .tif for 8 or 16 bits");
    // Half is refused elsewhere because the other writers would quietly store something else.
    if (!exr && format == MapSampleFormat::Half)
        return makeError(name, "half-float texels need .exr; use Float for .tif");
    const OIIO::TypeDesc type = format == MapSampleFormat::Float    ? OIIO::TypeDesc::FLOAT
                                : format == MapSampleFormat::Half   ? OIIO::TypeDesc::HALF
                                : format == MapSampleFormat::UInt16 ? OIIO::TypeDesc::UINT16
                                                                    : OIIO::TypeDesc::UINT8;
    std::error_code ec;
    if (file.has_parent_path() && !fs::is_directory(file.parent_path(), ec))
        return makeError(name, "the folder " + file.parent_path().string() + " does not exist");

    const fs::path temporary = temporaryPathFor(file);
    auto out = OIIO::ImageOutput::create(name);
    if (!out)
        return makeError(name, "cannot write this image format (use .png, .tif or .exr): " +
                                   oneLine(OIIO::geterror()));
    OIIO::ImageSpec spec(map.width, map.height, 1, type);
    // The texels are data (density, soil, light), not colour: no transfer curve.
    spec.attribute("oiio:ColorSpace", "Linear");
    if (exr)
        spec.attribute("compression", "zip");
    if (!out->open(temporary.string(), spec)) {
        fs::remove(temporary, ec);
        return makeError(name, "cannot write: " + oneLine(out->geterror()));
    }
    // Clamp on the way out so the integer formats never wrap or saturate unexpectedly.
    std::vector<float> clamped(map.texels.size());
    for (std::size_t i = 0; i < clamped.size(); ++i) {
        const float t = map.texels[i];
        clamped[i] = t == t ? std::clamp(t, 0.0f, 1.0f) : 0.0f;
    }
    const bool written = out->write_image(OIIO::TypeDesc::FLOAT, clamped.data());
    const bool closed = out->close();
    if (!written || !closed) {
        const std::string reason = oneLine(out->geterror());
        out.reset();
        fs::remove(temporary, ec);
        return makeError(name, "write failed: " + reason);
    }
    out.reset();
    if (auto whole = verifyWrittenImage(temporary, name, map.width, map.height); !whole) {
        fs::remove(temporary, ec);
        return whole;
    }
    return commitTemporaryFile(temporary, file);
}

// Resampling weights along one axis of `from` texels to `to` texels: output texel i reads
// source texels first[i] + k with weights[begin[i] + k], for begin[i] + k < begin[i + 1].
struct AxisFilter {
    std::vector<int> first;
    std::vector<std::size_t> begin;
    std::vector<float> weights;
};

AxisFilter makeAxisFilter(int from, int to) {
    AxisFilter filter;
    filter.first.reserve(static_cast<std::size_t>(to));
    filter.begin.reserve(static_cast<std::size_t>(to) + 1);
    // Doubles so that integer ratios give exact footprints and weights (a 2^k box is exact).
    const double scale = static_cast<double>(from) / static_cast<double>(to);
    for (int i = 0; i < to; ++i) {
        filter.begin.push_back(filter.weights.size());
        if (scale <= 2.0) {
            // Bilinear at the new texel centre, in the source's texel-centre coordinates, clamped
            // to the edge exactly as MapImage::sample does. Up to 2× down every source texel
            // still reaches some output texel, so nothing is skipped.
            const double x = std::clamp((static_cast<double>(i) + 0.5) * scale - 0.5, 0.0,
                                        static_cast<double>(from - 1));
            const int x0 = static_cast<int>(x);
            const double t = x - static_cast<double>(x0);
            filter.first.push_back(x0);
            filter.weights.push_back(static_cast<float>(1.0 - t));
            if (x0 + 1 < from)
                filter.weights.push_back(static_cast<float>(t));
        } else {
            // The output texel covers source edges [lo, hi); each source texel weighs the length
            // of its overlap. Bilinear here would read 2 of the more than 2 texels and alias.
            const double lo = static_cast<double>(i) * static_cast<double>(from) / to;
            const double hi = static_cast<double>(i + 1) * static_cast<double>(from) / to;
            const int k0 = static_cast<int>(lo);
            const int k1 = std::min(from, static_cast<int>(std::ceil(hi)));
            filter.first.push_back(k0);
            for (int k = k0; k < k1; ++k) {
                const double overlap = std::min(hi, static_cast<double>(k) + 1.0) -
                                       std::max(lo, static_cast<double>(k));
                filter.weights.push_back(static_cast<float>(overlap / (hi - lo)));
            }
        }
    }
    filter.begin.push_back(filter.weights.size());
    return filter;
}

}  // namespace

float MapImage::sample(glm::vec2 uv) const {
    if (width <= 0 || height <= 0 || texels.empty())
        return 0.0f;
    // Texel centres sit at (i + 0.5) / width; NaN coordinates read texel 0.
    const auto coordinate = [](float t, int size) {
        const float x = t * static_cast<float>(size) - 0.5f;
        return std::clamp(x == x ? x : 0.0f, 0.0f, static_cast<float>(size - 1));
    };
    const float x = coordinate(uv.x, width), y = coordinate(uv.y, height);
    const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
    const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    const float top = at(x0, y0) + fx * (at(x1, y0) - at(x0, y0));
    const float bottom = at(x0, y1) + fx * (at(x1, y1) - at(x0, y1));
    return top + fy * (bottom - top);
}

float MapImage::maxValue() const {
    float best = 0.0f;
    for (const float t : texels)
        best = std::max(best, t);
    return best;
}

MapImage makeConstantMap(int width, int height, float value) {
    MapImage map;
    map.width = std::max(width, 0);
    map.height = std::max(height, 0);
    const float v = value == value ? std::clamp(value, 0.0f, 1.0f) : 0.0f;
    map.texels.assign(static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height),
                      v);
    return map;
}

MapImage resampleMap(const MapImage& map, int width, int height) {
    GRASS_ASSERT(width >= 1 && height >= 1);
    GRASS_ASSERT(map.width >= 1 && map.height >= 1 &&
                 map.texels.size() ==
                     static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height));
    if (width == map.width && height == map.height)
        return map;
    const auto size = [](int n) { return static_cast<std::size_t>(n); };

    // Separable: rows first (map.width -> width), then columns (map.height -> height). Both
    // bilinear and box filters are products of their 1D filters, so this equals the 2D filter.
    std::vector<float> rows(size(width) * size(map.height));
    if (width == map.width) {
        rows = map.texels;
    } else {
        const AxisFilter fx = makeAxisFilter(map.width, width);
        for (std::size_t y = 0; y < size(map.height); ++y) {
            const float* in = &map.texels[y * size(map.width)];
            for (std::size_t x = 0; x < size(width); ++x) {
                float sum = 0.0f;
                for (std::size_t k = fx.begin[x]; k < fx.begin[x + 1]; ++k)
                    sum += fx.weights[k] * in[size(fx.first[x]) + (k - fx.begin[x])];
                rows[y * size(width) + x] = sum;
            }
        }
    }

    MapImage out;
    out.width = width;
    out.height = height;
    out.warnings = map.warnings;
    if (height == map.height) {
        out.texels = std::move(rows);
    } else {
        out.texels.assign(size(width) * size(height), 0.0f);
        const AxisFilter fy = makeAxisFilter(map.height, height);
        // Whole rows at a time: each output row is a weighted sum of source rows.
        for (std::size_t y = 0; y < size(height); ++y) {
            float* dst = &out.texels[y * size(width)];
            for (std::size_t k = fy.begin[y]; k < fy.begin[y + 1]; ++k) {
                const float w = fy.weights[k];
                const float* src = &rows[(size(fy.first[y]) + (k - fy.begin[y])) * size(width)];
                for (std::size_t x = 0; x < size(width); ++x)
                    dst[x] += w * src[x];
            }
        }
    }
    // The weights are convex, but their float rounding can land a hair outside [0, 1].
    for (float& t : out.texels)
        t = std::clamp(t, 0.0f, 1.0f);
    return out;
}

Result<MapImage> loadMapImage(const fs::path& file) {
    // OIIO and the standard library may throw (bad_alloc, filesystem errors); nothing escapes.
    try {
        return readMapFile(file);
    } catch (const std::exception& e) {
        return makeError(file.string(), std::string("cannot read the map: ") + e.what());
    }
}

Result<MapImage> loadMapImageAt(const fs::path& file, int width, int height) {
    const auto sizeText = [](int w, int h) { return std::to_string(w) + "×" + std::to_string(h); };
    if (width < 1 || height < 1 || width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE)
        return makeError(file.string(), "cannot load the map at " + sizeText(width, height) +
                                            "; the size must be 1 to " +
                                            std::to_string(MAX_IMAGE_SIDE) + " texels a side");
    Result<MapImage> loaded = loadMapImage(file);
    if (!loaded || (loaded->width == width && loaded->height == height))
        return loaded;
    try {
        MapImage map = resampleMap(*loaded, width, height);
        map.warnings.push_back(file.string() + ": resampled from " +
                               sizeText(loaded->width, loaded->height) + " to " +
                               sizeText(width, height));
        return map;
    } catch (const std::exception& e) {
        return makeError(file.string(), std::string("cannot resample the map: ") + e.what());
    }
}

Result<void> saveMapImage(const MapImage& map, const fs::path& file, MapSampleFormat format) {
    try {
        return writeMap(map, file, format);
    } catch (const std::exception& e) {
        return makeError(file.string(), std::string("cannot write the map: ") + e.what());
    }
}

}  // namespace grass::core
