#include "billboard/grass_texture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "util/assert.h"
#include "util/image_header.h"
#include "util/image_layout.h"
#include "util/image_open.h"
#include "util/rng.h"
#include "util/tga_palette.h"

namespace grass::core {

namespace {

// One blade in pixel units, y measured upwards from the bottom edge: the centre line is
// x(t) = rootX + bendX·t² (t ∈ [0, 1] from root to tip, a quadratic curve leaning one way) and
// the half width halfWidth·(1 − t) tapers to a point at the tip.
struct TextureBlade {
    float rootX = 0.0f;
    float bendX = 0.0f;
    float heightPx = 1.0f;
    float halfWidth = 1.0f;
    float shade = 1.0f;
};

std::uint8_t toByte(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// Pixel coverage of a blade at pixel centre (x, y): 0.5 minus the signed horizontal distance to
// the outline, scaled by the outline's slope so the ramp is one pixel wide across the edge.
float bladeCoverage(const TextureBlade& blade, float x, float y) {
    const float t = y / blade.heightPx;
    if (t < 0.0f || t > 1.0f)
        return 0.0f;
    const float centreX = blade.rootX + blade.bendX * t * t;
    const float halfWidth = blade.halfWidth * (1.0f - t);
    // d(centre ± halfWidth)/dy: the steeper edge's slope bounds the distance correction.
    const float slope = (2.0f * blade.bendX * t + blade.halfWidth) / blade.heightPx;
    const float distance = (std::abs(x - centreX) - halfWidth) / std::sqrt(1.0f + slope * slope);
    return std::clamp(0.5f - distance, 0.0f, 1.0f);
}

}  // namespace

Rgba8Pixels generateGrassTexture(int width, int height, int bladeCount, std::uint64_t seed,
                                 glm::vec3 rootColor, glm::vec3 tipColor) {
    GRASS_ASSERT(width >= 1 && height >= 1 && bladeCount >= 0);
    const auto w = static_cast<float>(width);
    const auto h = static_cast<float>(height);
    Rng rng(seed);
    std::vector<TextureBlade> blades(static_cast<std::size_t>(bladeCount));
    for (std::size_t i = 0; i < blades.size(); ++i) {
        TextureBlade& blade = blades[i];
        // Roots stratified along the bottom (jittered within equal slots) so tufts spread over
        // the whole width instead of piling up by chance; kept off the side edges.
        const float slot = (static_cast<float>(i) + rng.uniform()) / static_cast<float>(bladeCount);
        blade.rootX = w * (0.12f + 0.76f * slot);
        blade.heightPx = h * rng.uniform(0.55f, 1.0f);
        blade.halfWidth = w * rng.uniform(0.022f, 0.045f);
        // Lean outwards from the middle (a tuft opens up), plus some randomness.
        const float outwards = (blade.rootX / w - 0.5f) * 0.5f;
        blade.bendX = w * std::clamp(outwards + rng.uniform(-0.15f, 0.15f), -0.35f, 0.35f);
        // Keep tips inside the image (when it is wide enough to have an inside).
        const float lo = 1.0f - blade.rootX, hi = w - 1.0f - blade.rootX;
        blade.bendX = lo <= hi ? std::clamp(blade.bendX, lo, hi) : 0.0f;
        blade.shade = rng.uniform(0.8f, 1.1f);
    }

    Rgba8Pixels image;
    image.width = width;
    image.height = height;
    image.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    for (int row = 0; row < height; ++row) {
        // Row 0 is the top: y up from the bottom edge, at the pixel centre.
        const float y = h - (static_cast<float>(row) + 0.5f);
        const glm::vec3 rowColor = glm::mix(rootColor, tipColor, std::clamp(y / h, 0.0f, 1.0f));
        for (int col = 0; col < width; ++col) {
            const float x = static_cast<float>(col) + 0.5f;
            // Union of the blades: the most covering one also gives its shade.
            float alpha = 0.0f;
            float shade = 1.0f;
            for (const TextureBlade& blade : blades) {
                const float coverage = bladeCoverage(blade, x, y);
                if (coverage > alpha) {
                    alpha = coverage;
                    shade = blade.shade;
                }
            }
            const glm::vec3 color = rowColor * (1.0f + (shade - 1.0f) * alpha);
            std::uint8_t* p = image.pixels.data() +
                              4 * (static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                                   static_cast<std::size_t>(col));
            p[0] = toByte(color.r);
            p[1] = toByte(color.g);
            p[2] = toByte(color.b);
            p[3] = toByte(alpha);
        }
    }
    return image;
}

namespace {

// Transparent texels of files often hold black (PNG writers drop their colour), which bilinear
// filtering and mipmaps would bleed into the blade edges as a dark fringe. Give each one the
// mean colour of the row's mostly opaque texels (or of the nearest row that has some).
void fillTransparentColour(Rgba8Pixels& image) {
    const auto width = static_cast<std::size_t>(image.width);
    const auto height = static_cast<std::size_t>(image.height);
    std::vector<glm::vec3> rowMean(height, glm::vec3(-1.0f));
    for (std::size_t row = 0; row < height; ++row) {
        glm::vec3 sum(0.0f);
        float n = 0.0f;
        for (std::size_t col = 0; col < width; ++col) {
            const std::uint8_t* p = &image.pixels[4 * (row * width + col)];
            if (p[3] >= 128) {
                sum += glm::vec3(p[0], p[1], p[2]);
                n += 1.0f;
            }
        }
        if (n > 0.0f)
            rowMean[row] = sum / n;
    }
    for (std::size_t row = 0; row < height; ++row) {
        glm::vec3 mean = rowMean[row];
        for (std::size_t d = 1; mean.x < 0.0f && d < height; ++d) {
            if (row >= d && rowMean[row - d].x >= 0.0f)
                mean = rowMean[row - d];
            else if (row + d < height && rowMean[row + d].x >= 0.0f)
                mean = rowMean[row + d];
        }
        if (mean.x < 0.0f)
            return;  // no opaque texel anywhere: nothing to borrow
        for (std::size_t col = 0; col < width; ++col) {
            std::uint8_t* p = &image.pixels[4 * (row * width + col)];
            if (p[3] == 0)
                for (std::size_t c = 0; c < 3; ++c)
                    p[c] = static_cast<std::uint8_t>(std::lround(mean[static_cast<int>(c)]));
        }
    }
}

Error noAlpha(const std::filesystem::path& file, const std::string& what) {
    return makeError(file.string(), "grass texture has no alpha channel (" + what +
                                        "); billboards need RGBA with transparent gaps between "
                                        "the blades");
}

// The texture once read: refused when nothing is transparent, its gaps given the blades' colour.
Result<Rgba8Pixels> withGaps(const std::filesystem::path& file, Rgba8Pixels image,
                             bool anyTransparent) {
    if (!anyTransparent)
        return makeError(file.string(),
                         "grass texture's alpha is opaque everywhere; billboards need "
                         "transparent gaps between the blades");
    fillTransparentColour(image);
    return image;
}

}  // namespace

Result<Rgba8Pixels> loadGrassTexture(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
        return makeError(file.string(), "grass texture not found");
    if (auto header = checkImageHeader(file, MAX_IMAGE_SIDE); !header)
        return header.error();
    if (isColourMappedTga(file)) {
        // Decoded here (util/tga_palette.h): OpenImageIO 2.4 reads such palettes unchecked.
        auto decoded = readColourMappedTga(file, MAX_IMAGE_SIDE);
        if (!decoded)
            return makeError(file.string(), "grass texture: " + decoded.error().message);
        if (!decoded->alpha)
            return noAlpha(file, "a colour-mapped TGA whose palette has none");
        bool anyTransparent = false;
        for (std::size_t i = 3; i < decoded->pixels.pixels.size(); i += 4)
            anyTransparent = anyTransparent || decoded->pixels.pixels[i] < 255;
        return withGaps(file, std::move(decoded->pixels), anyTransparent);
    }
    // Read through OpenImageIO directly rather than readRgba8Image: we need to know whether the
    // file has an alpha channel at all (readRgba8Image fills a missing one with 255), and the
    // colours as stored (unassociated, as PNG defines them), not premultiplied by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto opened = openImageInput(file.string(), &config);
    if (!opened)
        return makeError(file.string(), "grass texture: " + opened.error().message);
    auto& in = *opened;
    const OIIO::ImageSpec& spec = in->spec();
    if (auto fits = checkImageSize(file.string(), spec.width, spec.height, MAX_IMAGE_SIDE); !fits)
        return fits.error();
    const int channels = spec.nchannels;
    const bool hasAlpha = alphaChannelOf(spec) >= 0 || channels == 4 || channels == 2;
    if (!hasAlpha)
        return noAlpha(file, std::to_string(channels) + " channels");
    const int alphaChannel = alphaChannelOf(spec) >= 0 ? alphaChannelOf(spec) : channels - 1;
    const auto count = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    std::vector<std::uint8_t> raw(count * static_cast<std::size_t>(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data()))
        return makeError(file.string(), "cannot read grass texture: " + oneLine(in->geterror()));
    // As a viewer shows it: turned by its orientation tag, its data window in its display window.
    const ImageLayout layout = imageLayout(spec, in->format_name());
    Rgba8Pixels image;
    image.width = spec.width;
    image.height = spec.height;
    if (layout.windowed() || layout.orientation != 1) {
        if (auto fits = checkImageSize(file.string(), layout.shownWidth(), layout.shownHeight(),
                                       MAX_IMAGE_SIDE);
            !fits)
            return fits.error();
        raw = showImage(raw, static_cast<std::size_t>(channels), layout);
        image.width = layout.shownWidth();
        image.height = layout.shownHeight();
    }
    const auto shown =
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    image.pixels.resize(shown * 4);
    // OpenImageIO 2.4's WebP reader hands out colour multiplied by alpha whatever
    // oiio:UnassociatedAlpha says: divided back out, as the colours are stored.
    const bool premultiplied = std::string(in->format_name()) == "webp";
    bool anyTransparent = false;
    for (std::size_t i = 0; i < shown; ++i) {
        const std::uint8_t* p = raw.data() + i * static_cast<std::size_t>(channels);
        const bool grey = channels < 3;
        const std::uint8_t alpha = p[alphaChannel];
        const auto stored = [&](std::uint8_t value) {
            if (!premultiplied || alpha == 0 || alpha == 255)
                return value;
            return static_cast<std::uint8_t>(std::min(255L, std::lround(value * 255.0 / alpha)));
        };
        image.pixels[4 * i + 0] = stored(p[0]);
        image.pixels[4 * i + 1] = stored(grey ? p[0] : p[1]);
        image.pixels[4 * i + 2] = stored(grey ? p[0] : p[2]);
        image.pixels[4 * i + 3] = alpha;
        anyTransparent = anyTransparent || alpha < 255;
    }
    return withGaps(file, std::move(image), anyTransparent);
}

glm::vec3 meanGrassColour(const Rgba8Pixels& texture) {
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (std::size_t p = 0; p + 3 < texture.pixels.size(); p += 4) {
        const double alpha = texture.pixels[p + 3];
        sum += alpha * glm::dvec3(texture.pixels[p], texture.pixels[p + 1], texture.pixels[p + 2]);
        weight += alpha;
    }
    return weight > 0.0 ? glm::vec3(sum / (weight * 255.0)) : glm::vec3(0.0f);
}

}  // namespace grass::core
