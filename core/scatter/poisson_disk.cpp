#include "scatter/poisson_disk.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace grass::core {

namespace {

// Cells of size minDistance: every point within minDistance of p lies in p's cell or one of
// its 26 neighbours, and only neighbours whose box comes within minDistance are visited. Cell
// coordinates are clamped to 21 bits each so they pack into one key; clamping is monotone and
// never moves neighbours more than one cell apart, so the check stays exact far out (only
// slower). The cells live in an open-addressing table: the dart loop is all lookups, most of
// them of empty cells (a surface crosses about a third of a 3 × 3 × 3 block), and a flat
// table answers those in one probe. Output never depends on the table's layout.
class SpatialHash {
public:
    explicit SpatialHash(float cellSize) : mInvCell(1.0f / cellSize) { rehash(1024); }

    bool anyWithin(glm::vec3 p, float distance, const std::vector<SurfaceSample>& points) const {
        const float d2 = distance * distance;
        const glm::ivec3 cell = cellOf(p);
        // The candidate's own cell first: at saturation that is where a conflict usually is.
        if (cellHasPointWithin(key(cell), p, d2, points))
            return true;
        // Distance from p to the faces of its cell, in cell units, per axis and side, less a
        // margin for the rounding that assigned stored points to cells (a few ulps of p·inv).
        // Outside the clamped range cells are unbounded: no pruning there.
        glm::vec3 low(0.0f), high(0.0f);
        for (int axis = 0; axis < 3; ++axis) {
            const double scaled = static_cast<double>(p[axis]) * static_cast<double>(mInvCell);
            const double f = scaled - static_cast<double>(cell[axis]);
            if (!(f >= 0.0 && f <= 1.0))
                continue;
            const double margin = 1e-4 + 5e-7 * std::abs(scaled);
            low[axis] = static_cast<float>(std::max(f - margin, 0.0));
            high[axis] = static_cast<float>(std::max(1.0 - f - margin, 0.0));
        }
        const auto gap = [&](int axis, int offset) {
            const float g = offset < 0 ? low[axis] : (offset > 0 ? high[axis] : 0.0f);
            return g * g;
        };
        for (int dz = -1; dz <= 1; ++dz) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    if (dx == 0 && dy == 0 && dz == 0)
                        continue;
                    if (gap(0, dx) + gap(1, dy) + gap(2, dz) >= 1.0f)
                        continue;
                    if (cellHasPointWithin(key(clampCell(cell + glm::ivec3(dx, dy, dz))), p, d2,
                                           points))
                        return true;
                }
            }
        }
        return false;
    }

    void insert(glm::vec3 p, std::uint32_t index) {
        if (2 * (mUsed + 1) > mSlots.size())
            rehash(2 * mSlots.size());
        const std::uint64_t k = key(cellOf(p));
        Slot& slot = mSlots[find(k)];
        if (slot.key == 0) {
            slot.key = k;
            slot.first = p;
            slot.rest = NONE;
            ++mUsed;
            mNext.push_back(NONE);
            return;
        }
        mNext.push_back(slot.rest);
        slot.rest = index;
    }

private:
    // The cell's first point is kept in the slot itself: most cells hold one point or none,
    // so most checks touch one cache line instead of a slot and then a point.
    struct Slot {
        std::uint64_t key = 0;  // 0 = empty: real keys have every 21-bit field ≥ 1
        glm::vec3 first{0.0f};
        std::uint32_t rest = NONE;  // further points of the cell, a list through mNext
    };
    static constexpr std::uint32_t NONE = 0xFFFFFFFFu;
    static constexpr int LIMIT = (1 << 20) - 1;

    static glm::ivec3 clampCell(glm::ivec3 c) {
        return glm::clamp(c, glm::ivec3(-LIMIT), glm::ivec3(LIMIT));
    }

    glm::ivec3 cellOf(glm::vec3 p) const {
        glm::ivec3 cell(0);
        for (int axis = 0; axis < 3; ++axis) {
            const float c = std::floor(p[axis] * mInvCell);
            // NaN (0 · ∞ for an absurdly small distance) goes to cell 0 instead of UB.
            if (c == c)
                cell[axis] = static_cast<int>(
                    std::clamp(c, static_cast<float>(-LIMIT), static_cast<float>(LIMIT)));
        }
        return cell;
    }

    static std::uint64_t key(glm::ivec3 c) {
        const auto bits = [](int v) {
            return static_cast<std::uint64_t>(v + LIMIT + 1) & 0x1FFFFFu;
        };
        return bits(c.x) | (bits(c.y) << 21u) | (bits(c.z) << 42u);
    }

    // The slot holding k, or the empty slot where it would go (linear probing). Runs of 4
    // cells along x share a hashed home, so a 3 × 3 × 3 neighbourhood touches ~9 cache lines,
    // not 27 random ones.
    std::size_t find(std::uint64_t k) const {
        const std::size_t mask = mSlots.size() - 1;
        const auto home = static_cast<std::size_t>(Rng::splitMix(k >> 2u) << 2u) | (k & 3u);
        for (std::size_t i = home & mask;; i = (i + 1) & mask) {
            if (mSlots[i].key == k || mSlots[i].key == 0)
                return i;
        }
    }

    void rehash(std::size_t size) {
        std::vector<Slot> old = std::move(mSlots);
        mSlots.assign(size, Slot{});
        for (const Slot& slot : old) {
            if (slot.key != 0)
                mSlots[find(slot.key)] = slot;
        }
    }

    bool cellHasPointWithin(std::uint64_t k, glm::vec3 p, float d2,
                            const std::vector<SurfaceSample>& points) const {
        const Slot& slot = mSlots[find(k)];
        if (slot.key == 0)
            return false;
        if (glm::dot(slot.first - p, slot.first - p) < d2)
            return true;
        for (std::uint32_t i = slot.rest; i != NONE; i = mNext[i]) {
            const glm::vec3 d = points[i].position - p;
            if (glm::dot(d, d) < d2)
                return true;
        }
        return false;
    }

    float mInvCell;
    std::vector<Slot> mSlots;  // size a power of two, at most half full
    std::size_t mUsed = 0;
    std::vector<std::uint32_t> mNext;  // per point: the next point in its cell
};

}  // namespace

double poissonDiskCapacity(double area, float minDistance) {
    if (!(area > 0.0) || !(minDistance > 0.0f))
        return 0.0;
    const double d = static_cast<double>(minDistance);
    return std::ceil(2.0 * area / (std::sqrt(3.0) * d * d));
}

PoissonDiskResult poissonDiskSample(const SurfaceSampler& sampler, const PoissonDiskParams& params,
                                    Rng& rng) {
    PoissonDiskResult result;
    if (sampler.empty() || !(params.minDistance > 0.0f) || !std::isfinite(params.minDistance) ||
        params.maxPoints == 0)
        return result;
    SpatialHash hash(params.minDistance);
    const std::size_t pointLimit = std::min<std::size_t>(params.maxPoints, 0xFFFFFFFEu);
    for (; result.attempts < params.maxAttempts; ++result.attempts) {
        const SurfaceSampler::Location dart = sampler.locate(rng);
        if (hash.anyWithin(dart.position, params.minDistance, result.points))
            continue;
        hash.insert(dart.position, static_cast<std::uint32_t>(result.points.size()));
        result.points.push_back(sampler.evaluate(dart.triangle, dart.b1, dart.b2));
        if (result.points.size() >= pointLimit) {
            result.reachedMaxPoints = true;
            ++result.attempts;
            break;
        }
    }
    return result;
}

}  // namespace grass::core
