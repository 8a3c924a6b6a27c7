#include "scatter/patches.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/assert.h"

namespace grass::core {

namespace {

constexpr std::uint32_t PADDING = std::numeric_limits<std::uint32_t>::max();
// 21 bits per axis: a 63-bit Morton code.
constexpr float MORTON_MAX = 2097151.0f;

// Spreads the low 21 bits of v so there are two zero bits between each.
std::uint64_t spreadBits(std::uint64_t v) {
    v &= 0x1FFFFFu;
    v = (v | (v << 32u)) & 0x1F00000000FFFFULL;
    v = (v | (v << 16u)) & 0x1F0000FF0000FFULL;
    v = (v | (v << 8u)) & 0x100F00F00F00F00FULL;
    v = (v | (v << 4u)) & 0x10C30C30C30C30C3ULL;
    v = (v | (v << 2u)) & 0x1249249249249249ULL;
    return v;
}

std::uint64_t quantise(float value, float lo, float extent) {
    if (!(extent > 0.0f))
        return 0;
    const float t = std::clamp((value - lo) / extent, 0.0f, 1.0f);
    return static_cast<std::uint64_t>(t * MORTON_MAX);
}

// A root and where it came from: the splits sort these 16-byte entries in place instead of
// chasing indices into 64-byte blades (3× faster on a million blades, cache misses).
struct Root {
    glm::vec3 v0;
    std::uint32_t index;
};

// Splits roots[first, first + count) until each range is one patch. `first` is always a
// multiple of patchSize and the left part gets a whole number of patches, so every leaf starts
// on a patch boundary and only the rightmost leaf can be short.
void split(std::vector<Root>& roots, std::size_t first, std::size_t count, std::size_t patchSize) {
    if (count <= patchSize)
        return;
    const std::size_t patches = (count + patchSize - 1) / patchSize;
    const std::size_t leftCount = (patches / 2) * patchSize;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (std::size_t i = first; i < first + count; ++i) {
        lo = glm::min(lo, roots[i].v0);
        hi = glm::max(hi, roots[i].v0);
    }
    const glm::vec3 extent = hi - lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto begin = roots.begin() + static_cast<std::ptrdiff_t>(first);
    // Ties broken by input index: a total order, so the partition is the same on every
    // standard library.
    std::nth_element(
        begin, begin + static_cast<std::ptrdiff_t>(leftCount),
        begin + static_cast<std::ptrdiff_t>(count), [axis](const Root& l, const Root& r) {
            return l.v0[axis] < r.v0[axis] || (l.v0[axis] == r.v0[axis] && l.index < r.index);
        });
    split(roots, first, leftCount, patchSize);
    split(roots, first + leftCount, count - leftCount, patchSize);
}

// The patch's box (v0 ± h of each blade), then its roots in Morton order within that box,
// ties by input index.
Patch makePatch(const std::vector<Blade>& blades, std::vector<Root>& roots, std::size_t first,
                std::size_t count) {
    Patch patch;
    patch.firstBlade = static_cast<std::uint32_t>(first);
    patch.bladeCount = static_cast<std::uint32_t>(count);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (std::size_t i = first; i < first + count; ++i) {
        const float reach = std::abs(blades[roots[i].index].h());
        lo = glm::min(lo, roots[i].v0 - glm::vec3(reach));
        hi = glm::max(hi, roots[i].v0 + glm::vec3(reach));
    }
    patch.bounds = Bounds{lo, hi};
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    keyed.reserve(count);
    for (std::size_t i = first; i < first + count; ++i)
        keyed.emplace_back(mortonCode(roots[i].v0, patch.bounds), roots[i].index);
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t i = 0; i < count; ++i)
        roots[first + i] = {blades[keyed[i].second].v0(), keyed[i].second};
    return patch;
}

}  // namespace

std::uint64_t mortonCode(glm::vec3 p, const Bounds& box) {
    const glm::vec3 extent = box.max - box.min;
    return spreadBits(quantise(p.x, box.min.x, extent.x)) |
           (spreadBits(quantise(p.y, box.min.y, extent.y)) << 1u) |
           (spreadBits(quantise(p.z, box.min.z, extent.z)) << 2u);
}

PatchedBlades buildPatches(const std::vector<Blade>& blades, std::uint32_t patchSize) {
    GRASS_ASSERT(patchSize > 0);
    GRASS_ASSERT(blades.size() < PADDING);
    PatchedBlades result;
    result.patchSize = patchSize;
    if (blades.empty())
        return result;

    std::vector<Root> roots(blades.size());
    for (std::size_t i = 0; i < roots.size(); ++i)
        roots[i] = {blades[i].v0(), static_cast<std::uint32_t>(i)};
    split(roots, 0, roots.size(), patchSize);

    const std::size_t patchCount = (blades.size() + patchSize - 1) / patchSize;
    result.patches.reserve(patchCount);
    result.blades.reserve(patchCount * patchSize);
    result.sourceIndex.reserve(patchCount * patchSize);
    for (std::size_t p = 0; p < patchCount; ++p) {
        const std::size_t first = p * patchSize;
        const std::size_t count = std::min<std::size_t>(patchSize, blades.size() - first);
        result.patches.push_back(makePatch(blades, roots, first, count));
        for (std::size_t i = first; i < first + count; ++i) {
            result.blades.push_back(blades[roots[i].index]);
            result.sourceIndex.push_back(roots[i].index);
        }
    }
    // Padding: null blades (h = 0, w = 0) at the last live root, inside the last patch's box,
    // so a shader that forgot to skip them still draws nothing outside the patch.
    const Blade& last = result.blades.back();
    const Blade padding = makeRestBlade(last.v0(), last.up(), 0.0f, 0.0f, last.s(), 0.0f);
    while (result.blades.size() < patchCount * patchSize) {
        result.blades.push_back(padding);
        result.sourceIndex.push_back(PADDING);
    }
    return result;
}

}  // namespace grass::core
