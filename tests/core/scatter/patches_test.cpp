#include "scatter/patches.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "mesh/procedural.h"
#include "scatter/scatter.h"

namespace grass::core {
namespace {

std::vector<Blade> bladesOnPlane(float side, float density, std::uint64_t seed) {
    ProceduralMeshParams p;
    p.size = side;
    p.resolution = 4;
    ScatterParams s;
    s.density = density;
    return scatterBlades(makeProceduralMesh(p), s, nullptr, seed).blades;
}

std::vector<Blade> bladesOnSphere(std::uint64_t seed) {
    ProceduralMeshParams p;
    p.shape = ProceduralShape::Sphere;
    p.size = 2.0f;
    p.resolution = 24;
    ScatterParams s;
    s.density = 60.0f;
    s.clumpSpacing = 0.5f;
    return scatterBlades(makeProceduralMesh(p), s, nullptr, seed).blades;
}

bool contains(const Bounds& box, glm::vec3 p) {
    return glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max));
}

void expectWellFormed(const std::vector<Blade>& input, const PatchedBlades& out,
                      std::uint32_t patchSize, std::uint64_t seed) {
    const std::size_t patchCount = (input.size() + patchSize - 1) / patchSize;
    ASSERT_EQ(out.patchSize, patchSize);
    ASSERT_EQ(out.patches.size(), patchCount) << "seed " << seed;
    ASSERT_EQ(out.blades.size(), patchCount * patchSize);
    ASSERT_EQ(out.sourceIndex.size(), out.blades.size());
    std::vector<int> seen(input.size(), 0);
    for (std::size_t p = 0; p < out.patches.size(); ++p) {
        const Patch& patch = out.patches[p];
        EXPECT_EQ(patch.firstBlade, p * patchSize);
        // Only the last patch may be short; every other is full.
        if (p + 1 < out.patches.size()) {
            EXPECT_EQ(patch.bladeCount, patchSize) << "seed " << seed;
        }
        EXPECT_GT(patch.bladeCount, 0u);
        std::uint64_t previousCode = 0;
        for (std::uint32_t i = 0; i < patchSize; ++i) {
            const std::size_t k = patch.firstBlade + i;
            const Blade& b = out.blades[k];
            if (i >= patch.bladeCount) {
                EXPECT_EQ(out.sourceIndex[k], UINT32_MAX);
                EXPECT_EQ(b.h(), 0.0f);
                EXPECT_EQ(b.w(), 0.0f);
                continue;
            }
            ASSERT_LT(out.sourceIndex[k], input.size());
            ++seen[out.sourceIndex[k]];
            EXPECT_EQ(b, input[out.sourceIndex[k]]);
            // The box holds the blade's whole reach.
            EXPECT_TRUE(contains(patch.bounds, b.v0() + glm::vec3(b.h())));
            EXPECT_TRUE(contains(patch.bounds, b.v0() - glm::vec3(b.h())));
            const std::uint64_t code = mortonCode(b.v0(), patch.bounds);
            EXPECT_GE(code, previousCode) << "patch " << p << " blade " << i;
            previousCode = code;
        }
    }
    // sourceIndex restricted to live blades is a permutation of the input.
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }))
        << "seed " << seed;
}

TEST(Patches, EveryBladeOnceInFullPatches) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        const std::vector<Blade> onPlane = bladesOnPlane(6.0f, 37.0f, seed);  // 1332 blades
        expectWellFormed(onPlane, buildPatches(onPlane, 64), 64, seed);
        const std::vector<Blade> onSphere = bladesOnSphere(seed);
        expectWellFormed(onSphere, buildPatches(onSphere, 32), 32, seed);
    }
}

TEST(Patches, SizesAtTheEdges) {
    const std::vector<Blade> blades = bladesOnPlane(2.0f, 64.0f, 4);  // 256 blades
    expectWellFormed(blades, buildPatches(blades, 256), 256, 4);
    expectWellFormed(blades, buildPatches(blades, 1000), 1000, 4);
    expectWellFormed(blades, buildPatches(blades, 1), 1, 4);
    const std::vector<Blade> one(blades.begin(), blades.begin() + 1);
    expectWellFormed(one, buildPatches(one, 32), 32, 4);
    const PatchedBlades none = buildPatches({}, 32);
    EXPECT_TRUE(none.patches.empty());
    EXPECT_TRUE(none.blades.empty());
    EXPECT_TRUE(none.sourceIndex.empty());
}

// Median bisection tiles the plane with disjoint cells, one patch each, so the boxes around
// the roots (without the ±h reach) cover the plane without overlap: their areas sum to at most
// the plane's, and at least 80 % of it (root boxes fall short of their cells by about the mean
// spacing between blades). Longest-axis splits keep cells near-square: aspect at most 4.
TEST(Patches, PatchesAreCompactOnAPlane) {
    for (const std::uint64_t seed : {5u, 6u}) {
        const std::vector<Blade> blades = bladesOnPlane(20.0f, 100.0f, seed);  // 40 000
        const PatchedBlades out = buildPatches(blades, 256);
        double areaSum = 0.0;
        float worstAspect = 1.0f;
        for (const Patch& patch : out.patches) {
            glm::vec3 lo(1e30f), hi(-1e30f);
            for (std::uint32_t i = 0; i < patch.bladeCount; ++i) {
                lo = glm::min(lo, out.blades[patch.firstBlade + i].v0());
                hi = glm::max(hi, out.blades[patch.firstBlade + i].v0());
            }
            const glm::vec3 size = hi - lo;
            areaSum += static_cast<double>(size.x) * static_cast<double>(size.z);
            if (patch.bladeCount == out.patchSize)
                worstAspect =
                    std::max(worstAspect, std::max(size.x, size.z) / std::min(size.x, size.z));
        }
        EXPECT_LE(areaSum, 400.0 * 1.0001) << "seed " << seed;
        EXPECT_GE(areaSum, 400.0 * 0.8) << "seed " << seed;
        EXPECT_LE(worstAspect, 4.0f) << "seed " << seed;
    }
}

TEST(Patches, DeterministicForEqualInput) {
    const std::vector<Blade> blades = bladesOnSphere(9);
    const PatchedBlades a = buildPatches(blades, 64), b = buildPatches(blades, 64);
    EXPECT_EQ(a.blades, b.blades);
    EXPECT_EQ(a.sourceIndex, b.sourceIndex);
}

}  // namespace
}  // namespace grass::core
