#include "maps/brush.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "util/assert.h"

namespace grass::core {

namespace {

constexpr std::uint32_t NO_ENTRY = 0xFFFFFFFFu;
constexpr float DEFAULT_DAB_SPACING = 0.25f;
// Below 1/20 of the radius dabs only cost time; above 2 radii a stroke becomes a dotted line,
// which someone may want, but not more.
constexpr float MIN_DAB_SPACING = 0.05f, MAX_DAB_SPACING = 2.0f;
// A tiny brush dragged across a huge gap would otherwise place millions of dabs in one frame;
// past this the spacing on that segment widens instead.
constexpr float MAX_DABS_PER_SEGMENT = 65536.0f;
// Smooth, at chart borders and seams, averages the texels within this many of the texel's longer
// side in 3D: at least its 3 × 3 neighbourhood (diagonals at √2 ≈ 1.41 on a square layout), a
// little more along the short side of a stretched one.
constexpr float SMOOTH_KERNEL_TEXELS = 1.5f;
// A UV neighbour farther than this many texel sizes in 3D lies across a seam or in another chart
// of an atlas, so the texel counts as being on a border.
constexpr float SEAM_JUMP_TEXELS = 3.0f;
// MapImage::sample blends texels less than one texel away per axis, up to √2 in a diagonal:
// the touched bounds grow by this many texel sizes so grass sampling there is re-grown too.
constexpr float BOUNDS_PAD_TEXELS = 1.5f;

float clamp01(float v) {
    return std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
}

bool isFinite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

BrushSettings sanitizedBrush(const BrushSettings& settings) {
    BrushSettings s = settings;
    if (!std::isfinite(s.radiusM) || s.radiusM < 0.0f)
        s.radiusM = 0.0f;
    s.strength = clamp01(s.strength);
    s.setValue = clamp01(s.setValue);
    if (std::isnan(s.dabSpacing) || s.dabSpacing <= 0.0f)
        s.dabSpacing = DEFAULT_DAB_SPACING;
    s.dabSpacing = std::clamp(s.dabSpacing, MIN_DAB_SPACING, MAX_DAB_SPACING);
    return s;
}

float brushFalloff(BrushFalloff falloff, float distanceOverRadius) {
    const float x = distanceOverRadius;
    if (std::isnan(x) || x >= 1.0f)
        return 0.0f;
    if (x <= 0.0f)
        return 1.0f;
    switch (falloff) {
        case BrushFalloff::Smooth:
            return 1.0f - x * x * (3.0f - 2.0f * x);
        case BrushFalloff::Linear:
            return 1.0f - x;
        case BrushFalloff::Constant:
            return 1.0f;
    }
    return 0.0f;
}

PaintStroke::PaintStroke(MapImage& map, const TexelSurface& surface, const BrushSettings& settings)
    : mMap(&map), mSurface(&surface), mSettings(sanitizedBrush(settings)) {
    GRASS_ASSERT(map.width == surface.width() && map.height == surface.height());
    GRASS_ASSERT(map.texels.size() == surface.texelCount());
}

void PaintStroke::addHits(std::span<const glm::vec3> hits) {
    if (mSettings.radiusM <= 0.0f)
        return;
    const float step = mSettings.dabSpacing * mSettings.radiusM;
    for (const glm::vec3 hit : hits) {
        if (!isFinite(hit))
            continue;
        if (!mStarted) {
            mStarted = true;
            mLastHit = hit;
            mToNextDabM = step;
            dab(hit);
            continue;
        }
        const glm::vec3 segment = hit - mLastHit;
        const float length = glm::length(segment);
        if (length > 0.0f) {
            const float segmentStep = std::max(step, length / MAX_DABS_PER_SEGMENT);
            while (mToNextDabM <= length) {
                dab(mLastHit + segment * (mToNextDabM / length));
                mToNextDabM += segmentStep;
            }
            mToNextDabM -= length;
        }
        mLastHit = hit;
    }
}

void PaintStroke::dab(glm::vec3 centre) {
    ++mDabs;
    const float radius = mSettings.radiusM;
    std::vector<float>& texels = mMap->texels;
    mSurface->texelsWithin(centre, radius, mDabTexels);
    // All new values first, then the writes: Smooth must read the map as it was before this dab,
    // whatever order the texels come in.
    mNewValues.resize(mDabTexels.size());
    for (std::size_t k = 0; k < mDabTexels.size(); ++k) {
        const std::uint32_t texel = mDabTexels[k];
        const float v = texels[texel];
        const float distance = glm::length(mSurface->position(texel) - centre);
        const float w =
            mSettings.strength * mPressure * brushFalloff(mSettings.falloff, distance / radius);
        mNewValues[k] = v;
        if (!(w > 0.0f))
            continue;
        switch (mSettings.mode) {
            case BrushMode::Add:
                mNewValues[k] = clamp01(v + w);
                break;
            case BrushMode::Subtract:
                mNewValues[k] = clamp01(v - w);
                break;
            case BrushMode::Set:
                // This form gives setValue exactly at w = 1 (v + w·(s − v) may miss by an ulp).
                mNewValues[k] = clamp01((1.0f - w) * v + w * mSettings.setValue);
                break;
            case BrushMode::Smooth:
                mNewValues[k] = clamp01(v + w * meanNeighbourDifference(texel));
                break;
        }
    }
    for (std::size_t k = 0; k < mDabTexels.size(); ++k) {
        const std::uint32_t texel = mDabTexels[k];
        if (mNewValues[k] == texels[texel])
            continue;
        if (mEntry.empty())
            mEntry.assign(texels.size(), NO_ENTRY);
        if (mEntry[texel] == NO_ENTRY) {
            mEntry[texel] = static_cast<std::uint32_t>(mTouched.size());
            mTouched.push_back(texel);
            mBefore.push_back(texels[texel]);
        }
        texels[texel] = mNewValues[k];
        const glm::vec3 p = mSurface->position(texel);
        const float size = mSurface->texelSizeM(texel);
        const float pad = BOUNDS_PAD_TEXELS * size;
        if (!mChanged)
            mChanged = ChangedRegion{Bounds{p - pad, p + pad}, size};
        mChanged->bounds.min = glm::min(mChanged->bounds.min, p - pad);
        mChanged->bounds.max = glm::max(mChanged->bounds.max, p + pad);
        mChanged->texelMarginM = std::max(mChanged->texelMarginM, size);
    }
}

void PaintStroke::setPressure(float pressure) {
    mPressure = pressure >= 0.0f ? std::min(pressure, 1.0f) : 0.0f;  // NaN fails >= 0
}

std::optional<PaintStroke::ChangedRegion> PaintStroke::takeChangedRegion() {
    return std::exchange(mChanged, std::nullopt);
}

// Mean of (neighbour − v), not of the values: on a constant map it is exactly 0, so Smooth leaves
// such a map bit-identical. Away from borders the kernel is the 3 × 3 UV neighbourhood, read
// directly (a 3D query per texel costs about ten times more); at a border it is the texels
// within SMOOTH_KERNEL_TEXELS in 3D, so the blur crosses seams. Reads the map as it was before
// the current dab (dab writes afterwards).
float PaintStroke::meanNeighbourDifference(std::uint32_t texel) {
    const std::vector<float>& texels = mMap->texels;
    const float v = texels[texel];
    const auto width = static_cast<std::uint32_t>(mMap->width);
    const std::uint32_t x = texel % width, y = texel / width;
    const glm::vec3 p = mSurface->position(texel);
    const float size = mSurface->texelSizeM(texel);
    const float maxJump2 = (SEAM_JUMP_TEXELS * size) * (SEAM_JUMP_TEXELS * size);
    bool intact = x > 0 && y > 0 && x + 1 < width && static_cast<int>(y) + 1 < mMap->height;
    float sum = 0.0f;
    for (std::uint32_t row = y - 1; intact && row <= y + 1; ++row) {
        for (std::uint32_t n = row * width + x - 1; intact && n <= row * width + x + 1; ++n) {
            const glm::vec3 d = mSurface->position(n) - p;
            intact = mSurface->isCovered(n) && glm::dot(d, d) <= maxJump2;
            sum += texels[n] - v;
        }
    }
    if (intact)
        return sum / 9.0f;
    mSurface->texelsWithin(p, SMOOTH_KERNEL_TEXELS * size, mNeighbours);
    sum = 0.0f;
    for (const std::uint32_t n : mNeighbours)
        sum += texels[n] - v;
    return sum / static_cast<float>(std::max<std::size_t>(mNeighbours.size(), 1));
}

PaintRecord PaintStroke::record() const {
    std::vector<std::uint32_t> order(mTouched.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [this](std::uint32_t a, std::uint32_t b) { return mTouched[a] < mTouched[b]; });
    PaintRecord record;
    record.texelIndex.reserve(order.size());
    record.before.reserve(order.size());
    record.after.reserve(order.size());
    glm::vec3 lo(0.0f), hi(0.0f);
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::uint32_t texel = mTouched[order[k]];
        record.texelIndex.push_back(texel);
        record.before.push_back(mBefore[order[k]]);
        record.after.push_back(mMap->texels[texel]);
        const glm::vec3 p = mSurface->position(texel);
        const float pad = BOUNDS_PAD_TEXELS * mSurface->texelSizeM(texel);
        lo = k == 0 ? p - pad : glm::min(lo, p - pad);
        hi = k == 0 ? p + pad : glm::max(hi, p + pad);
    }
    record.touchedBounds = Bounds{lo, hi};
    return record;
}

PaintRecord paintStroke(MapImage& map, const TexelSurface& surface, const BrushSettings& settings,
                        std::span<const glm::vec3> hits) {
    PaintStroke stroke(map, surface, settings);
    stroke.addHits(hits);
    return stroke.record();
}

namespace {

void writeBack(MapImage& map, const std::vector<std::uint32_t>& index,
               const std::vector<float>& values) {
    GRASS_ASSERT(index.size() == values.size());
    for (std::size_t k = 0; k < index.size(); ++k) {
        GRASS_ASSERT(index[k] < map.texels.size());
        map.texels[index[k]] = values[k];
    }
}

}  // namespace

void undoPaint(MapImage& map, const PaintRecord& record) {
    writeBack(map, record.texelIndex, record.before);
}

void redoPaint(MapImage& map, const PaintRecord& record) {
    writeBack(map, record.texelIndex, record.after);
}

}  // namespace grass::core
