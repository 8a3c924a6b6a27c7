#include "scene/blade_shading.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "scatter/patches.h"
#include "util/rng.h"

namespace grass::core {
namespace {

constexpr float PI = std::numbers::pi_v<float>;

Blade bladeAt(glm::vec3 v0, glm::vec3 up = {0.0f, 1.0f, 0.0f}, float h = 0.4f) {
    return makeRestBlade(v0, glm::normalize(up), h, 0.015f, 60.0f, 0.0f);
}

// `count` blades uniform over the square [cx ± side/2] × [cz ± side/2] of the plane y = 0.
void addUniformSquare(std::vector<Blade>& blades, glm::vec2 centre, float side, std::size_t count,
                      Rng& rng) {
    for (std::size_t i = 0; i < count; ++i) {
        const float x = centre.x + rng.uniform(-0.5f, 0.5f) * side;
        const float z = centre.y + rng.uniform(-0.5f, 0.5f) * side;
        blades.push_back(bladeAt({x, 0.0f, z}));
    }
}

std::vector<Blade> uniformSquare(float side, float densityPerM2, std::uint64_t seed) {
    std::vector<Blade> blades;
    Rng rng(seed);
    addUniformSquare(blades, glm::vec2(0.0f), side,
                     static_cast<std::size_t>(std::lround(densityPerM2 * side * side)), rng);
    return blades;
}

std::vector<BladeShading> bake(const std::vector<Blade>& blades, const BladeShadingParams& params,
                               std::uint64_t seed = 1, unsigned threads = 0) {
    Result<std::vector<BladeShading>> r = bakeBladeShading(blades, params, seed, threads);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().str());
    return r.ok() ? std::move(r).value() : std::vector<BladeShading>{};
}

// Mean AO of the blades whose root lies within `radius` (x, z) of `centre`.
float meanAo(const std::vector<Blade>& blades, const std::vector<BladeShading>& shading,
             glm::vec2 centre, float radius) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < blades.size(); ++i) {
        if (glm::length(glm::vec2(blades[i].v0().x, blades[i].v0().z) - centre) <= radius) {
            sum += shading[i].ao();
            ++n;
        }
    }
    EXPECT_GT(n, 0);
    return n > 0 ? static_cast<float>(sum / n) : 0.0f;
}

float angleDeg(glm::vec3 a, glm::vec3 b) {
    const float c = std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f);
    return std::acos(c) * 180.0f / PI;
}

// The exact sums of the header's definition, O(n²): the reference the cell approximation is
// measured against.
std::vector<BladeShading> bruteForce(const std::vector<Blade>& blades,
                                     const BladeShadingParams& p) {
    const auto kernel = [](float d2, float sigma) {
        const float cut = 3.0f * sigma;
        return d2 < cut * cut ? std::exp(-d2 / (2.0f * sigma * sigma)) - std::exp(-4.5f) : 0.0f;
    };
    const double mass = 2.0 * std::numbers::pi * double(p.aoRadiusM) * double(p.aoRadiusM) *
                        (1.0 - std::exp(-4.5) * 5.5);
    std::vector<BladeShading> out(blades.size());
    for (std::size_t i = 0; i < blades.size(); ++i) {
        double weight = 0.0;
        glm::dvec3 up(0.0);
        for (std::size_t j = 0; j < blades.size(); ++j) {
            const float c = glm::dot(blades[j].up(), blades[i].up());
            const float t = std::clamp(2.0f * c + 1.0f, 0.0f, 1.0f);
            const float f = t * t * (3.0f - 2.0f * t);
            const glm::vec3 d = blades[j].v0() - blades[i].v0();
            const float d2 = glm::dot(d, d);
            if (j != i)
                weight += f * kernel(d2, p.aoRadiusM);
            up += double(f * kernel(d2, p.normalBlurRadiusM)) * glm::dvec3(blades[j].up());
        }
        const double ao = p.aoFloor + (1.0 - p.aoFloor) * std::exp(-weight / mass * p.aoStrength);
        out[i].blurredNormalAo = glm::vec4(glm::vec3(glm::normalize(up)), float(ao));
    }
    return out;
}

TEST(BladeShading, IsolatedBladeIsOpen) {
    const std::vector<Blade> blades = {bladeAt({0, 0, 0}), bladeAt({5, 0, 0}, {0.3f, 1, 0})};
    const std::vector<BladeShading> s = bake(blades, BladeShadingParams{});
    ASSERT_EQ(s.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_FLOAT_EQ(s[i].ao(), 1.0f) << "blade " << i;
        EXPECT_LT(angleDeg(s[i].blurredNormal(), blades[i].up()), 1e-3f) << "blade " << i;
    }
}

TEST(BladeShading, MeadowOf144PerSquareMetreIsHalfShaded) {
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
        const std::vector<Blade> blades = uniformSquare(6.0f, 144.0f, seed);
        const std::vector<BladeShading> s = bake(blades, BladeShadingParams{});
        // Away from the edges by more than the 3σ kernel reach.
        const float ao = meanAo(blades, s, glm::vec2(0.0f), 2.0f);
        std::printf("[ seed %llu ] 144 blades/m²: mean AO %.3f\n",
                    static_cast<unsigned long long>(seed), static_cast<double>(ao));
        EXPECT_GT(ao, 0.5f) << "seed " << seed;
        EXPECT_LT(ao, 0.7f) << "seed " << seed;
    }
}

TEST(BladeShading, DenseCentreIsDarkerThanItsEdgeAndThanASparsePatch) {
    std::vector<Blade> blades;
    Rng rng(7);
    addUniformSquare(blades, {0.0f, 0.0f}, 3.0f, 2700, rng);  // 300 blades/m²
    addUniformSquare(blades, {10.0f, 0.0f}, 3.0f, 360, rng);  // 40 blades/m²
    const std::vector<BladeShading> s = bake(blades, BladeShadingParams{});
    const float centre = meanAo(blades, s, {0.0f, 0.0f}, 0.5f);
    float edge = 0.0f;
    int edgeCount = 0;
    for (std::size_t i = 0; i < 2700; ++i) {
        const glm::vec3 p = blades[i].v0();
        if (std::max(std::abs(p.x), std::abs(p.z)) > 1.45f) {
            edge += s[i].ao();
            ++edgeCount;
        }
    }
    ASSERT_GT(edgeCount, 0);
    edge /= static_cast<float>(edgeCount);
    const float sparse = meanAo(blades, s, {10.0f, 0.0f}, 0.5f);
    EXPECT_LT(centre + 0.05f, edge);
    EXPECT_LT(centre + 0.2f, sparse);
}

TEST(BladeShading, AoFallsMonotonicallyWithDensity) {
    const float densities[] = {5.0f, 20.0f, 60.0f, 144.0f, 300.0f, 1000.0f, 4000.0f};
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
        float previous = 1.01f;
        for (float density : densities) {
            const std::vector<Blade> blades = uniformSquare(3.0f, density, seed);
            const float ao = meanAo(blades, bake(blades, BladeShadingParams{}), {0.0f, 0.0f}, 0.9f);
            EXPECT_LT(ao, previous) << "density " << density << " seed " << seed;
            previous = ao;
        }
    }
}

TEST(BladeShading, AoStaysWithinFloorAndOne) {
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        Rng rng(seed, 3);
        BladeShadingParams p;
        p.aoFloor = rng.uniform();
        p.aoStrength = rng.uniform(0.0f, 0.1f);
        p.aoRadiusM = rng.uniform(0.01f, 0.5f);
        std::vector<Blade> blades;
        // Clumps of every density, coincident roots included.
        for (int clump = 0; clump < 10; ++clump) {
            const glm::vec2 c(rng.uniform(-3.0f, 3.0f), rng.uniform(-3.0f, 3.0f));
            addUniformSquare(blades, c, rng.uniform(0.0f, 1.0f), rng.below(800), rng);
        }
        for (const BladeShading& s : bake(blades, p, seed)) {
            EXPECT_GE(s.ao(), p.aoFloor) << "seed " << seed;
            EXPECT_LE(s.ao(), 1.0f) << "seed " << seed;
        }
    }
}

TEST(BladeShading, FlatPlaneKeepsUp) {
    // A tilted plane, so no axis of the grid lines up with it.
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 1.0f, -0.5f));
    const glm::vec3 t = glm::normalize(glm::cross(n, glm::vec3(1, 0, 0)));
    const glm::vec3 b = glm::cross(n, t);
    Rng rng(11);
    std::vector<Blade> blades;
    for (int i = 0; i < 20000; ++i)
        blades.push_back(bladeAt(t * rng.uniform(-4.0f, 4.0f) + b * rng.uniform(-4.0f, 4.0f), n));
    const std::vector<BladeShading> s = bake(blades, BladeShadingParams{});
    for (std::size_t i = 0; i < blades.size(); ++i)
        ASSERT_LT(angleDeg(s[i].blurredNormal(), n), 0.05f) << "blade " << i;
}

// Fibonacci points on a sphere: nearly uniform, so the blur of radial normals is radial.
std::vector<Blade> sphereBlades(float radius, int count, glm::vec3 centre) {
    std::vector<Blade> blades;
    const float golden = PI * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < count; ++i) {
        const float y = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / static_cast<float>(count);
        const float r = std::sqrt(1.0f - y * y);
        const float a = golden * static_cast<float>(i);
        const glm::vec3 dir(r * std::cos(a), y, r * std::sin(a));
        blades.push_back(bladeAt(centre + radius * dir, dir));
    }
    return blades;
}

TEST(BladeShading, SphereBlurStaysNearTheRadialNormal) {
    const BladeShadingParams p;
    const glm::vec3 centre(2.0f, -1.0f, 0.5f);
    for (float radius : {0.4f, 1.0f, 3.0f}) {
        const int count = static_cast<int>(4.0f * PI * radius * radius * 300.0f);
        const std::vector<Blade> blades = sphereBlades(radius, count, centre);
        const std::vector<BladeShading> s = bake(blades, p);
        // Every summed up lies within the angle a chord of 3σ spans, so their mean does too:
        // the worst case for any sampling. Fibonacci sampling is nearly
        // symmetric about each point, so the mean is close to radial: 1° is ~1/50 of the bound
        // at radius 3.
        const float bound =
            std::min(120.0f, 2.0f * std::asin(std::min(1.0f, 1.5f * p.normalBlurRadiusM / radius)) *
                                 180.0f / PI);
        float worst = 0.0f;
        for (std::size_t i = 0; i < blades.size(); ++i)
            worst = std::max(worst, angleDeg(s[i].blurredNormal(), blades[i].up()));
        std::printf("[ radius %.1f ] worst angle to radial %.4f° (bound %.1f°)\n",
                    static_cast<double>(radius), static_cast<double>(worst),
                    static_cast<double>(bound));
        EXPECT_LT(worst, bound) << "radius " << radius;
        EXPECT_LT(worst, 1.0f) << "radius " << radius;
    }
}

TEST(BladeShading, CreaseNormalLiesBetweenTheFaces) {
    // A floor (y = 0, x < 0) meeting a wall (x = 0, y > 0) at a 90° concave crease along z.
    const glm::vec3 floorN(0, 1, 0), wallN(-1, 0, 0);
    std::vector<Blade> blades;
    for (int i = 0; i < 60; ++i) {
        for (int k = 0; k < 60; ++k) {
            const float u = (static_cast<float>(i) + 0.5f) * 0.05f;
            const float z = (static_cast<float>(k) - 30.0f) * 0.05f;
            blades.push_back(bladeAt({-u, 0, z}, floorN));
            blades.push_back(bladeAt({0, u, z}, wallN));
        }
    }
    const BladeShadingParams p;
    const std::vector<BladeShading> s = bake(blades, p);
    float previousTilt = 90.0f;
    for (std::size_t i = 0; i < blades.size(); ++i) {
        const glm::vec3 n = s[i].blurredNormal();
        const glm::vec3 v0 = blades[i].v0();
        if (std::abs(v0.z) > 0.5f)
            continue;
        // On the arc from one face normal to the other: no z part, both parts non-negative.
        EXPECT_NEAR(n.z, 0.0f, 0.02f) << "blade " << i;
        EXPECT_NEAR(angleDeg(n, floorN) + angleDeg(n, wallN), 90.0f, 0.1f) << "blade " << i;
        const float distance = std::max(-v0.x, v0.y);
        const glm::vec3 own = blades[i].up();
        // Bent well towards the other face next to the crease, untouched out of its reach.
        if (distance < 0.1f) {
            EXPECT_GT(angleDeg(n, own), 20.0f) << "blade " << i;
        }
        if (distance > 3.0f * p.normalBlurRadiusM) {
            EXPECT_LT(angleDeg(n, own), 1e-3f) << "blade " << i;
        }
    }
    // Along one line of the floor, the tilt towards the wall shrinks with distance.
    for (int i = 0; i < 60; ++i) {
        const std::size_t index = static_cast<std::size_t>(i * 60 + 30) * 2;
        const float tilt = angleDeg(s[index].blurredNormal(), floorN);
        EXPECT_LE(tilt, previousTilt + 1e-3f) << "step " << i;
        previousTilt = tilt;
    }
}

TEST(BladeShading, OppositeSidesOfAThinSheetDoNotMix) {
    // Grass on both faces of a 1 cm sheet, as across a Möbius seam: neither face darkens or
    // bends the other.
    Rng rng(5);
    std::vector<Blade> top, both;
    for (int i = 0; i < 1500; ++i) {
        const glm::vec3 p(rng.uniform(-1.5f, 1.5f), 0.0f, rng.uniform(-1.5f, 1.5f));
        top.push_back(bladeAt(p, {0, 1, 0}));
        both.push_back(bladeAt(p, {0, 1, 0}));
        both.push_back(bladeAt(p - glm::vec3(0, 0.01f, 0), {0, -1, 0}));
    }
    const BladeShadingParams params;
    const std::vector<BladeShading> single = bake(top, params);
    const std::vector<BladeShading> sheet = bake(both, params);
    for (std::size_t i = 0; i < top.size(); ++i) {
        EXPECT_NEAR(sheet[2 * i].ao(), single[i].ao(), 2e-3f) << "blade " << i;
        EXPECT_LT(angleDeg(sheet[2 * i].blurredNormal(), {0, 1, 0}), 1e-3f) << "blade " << i;
        EXPECT_LT(angleDeg(sheet[2 * i + 1].blurredNormal(), {0, -1, 0}), 1e-3f) << "blade " << i;
    }
}

TEST(BladeShading, CellSumsMatchTheExactSums) {
    // Clumps of every density on a plane plus a small sphere: the cell-centroid approximation
    // against the O(n²) definition. The thresholds are ~3× the errors measured when written
    // (AO 0.003; normal 0.75°, all of it on the sphere, whose radius is below the blur's 3σ).
    BladeShadingParams p;
    for (std::uint64_t seed = 0; seed < 3; ++seed) {
        Rng rng(seed, 9);
        std::vector<Blade> blades;
        for (int clump = 0; clump < 8; ++clump) {
            const glm::vec2 c(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f));
            addUniformSquare(blades, c, rng.uniform(0.2f, 1.5f), rng.below(600), rng);
        }
        for (const Blade& b : sphereBlades(0.5f, 800, {0.0f, 1.0f, 0.0f}))
            blades.push_back(b);
        const std::vector<BladeShading> fast = bake(blades, p, seed);
        const std::vector<BladeShading> exact = bruteForce(blades, p);
        float aoError = 0.0f, angleError = 0.0f;
        for (std::size_t i = 0; i < blades.size(); ++i) {
            aoError = std::max(aoError, std::abs(fast[i].ao() - exact[i].ao()));
            angleError =
                std::max(angleError, angleDeg(fast[i].blurredNormal(), exact[i].blurredNormal()));
        }
        std::printf("[ seed %llu ] %zu blades: max AO error %.4f, max normal error %.3f°\n",
                    static_cast<unsigned long long>(seed), blades.size(),
                    static_cast<double>(aoError), static_cast<double>(angleError));
        EXPECT_LT(aoError, 0.01f) << "seed " << seed;
        EXPECT_LT(angleError, 2.0f) << "seed " << seed;
    }
}

// The bake's speed/accuracy knob (issue 10): cells of 0 σ are the exact sums, and the error
// shrinks as the cells do.
TEST(BladeShading, CellSizeIsTheAccuracyKnobAndZeroIsExact) {
    Rng rng(4, 9);
    std::vector<Blade> blades;
    for (int clump = 0; clump < 6; ++clump) {
        const glm::vec2 c(rng.uniform(-1.5f, 1.5f), rng.uniform(-1.5f, 1.5f));
        addUniformSquare(blades, c, rng.uniform(0.2f, 1.0f), 200 + rng.below(400), rng);
    }
    BladeShadingParams p;
    const std::vector<BladeShading> exact = bruteForce(blades, p);
    float previous = INFINITY;
    for (const float cell : {2.0f, 0.5f, 0.0f}) {
        p.cellSigmas = cell;
        const std::vector<BladeShading> baked = bake(blades, p, 4);
        float aoError = 0.0f;
        for (std::size_t i = 0; i < blades.size(); ++i)
            aoError = std::max(aoError, std::abs(baked[i].ao() - exact[i].ao()));
        std::printf("[ cells %.1f σ ] max AO error %.5f\n", static_cast<double>(cell),
                    static_cast<double>(aoError));
        if (cell == 0.0f)
            EXPECT_LT(aoError, 1e-4f);  // float summation order only
        else
            EXPECT_LT(aoError, previous) << cell;
        previous = aoError;
    }
}

TEST(BladeShading, WaterIsWithinRangeAndFollowsAge) {
    const std::vector<Blade> blades = uniformSquare(4.0f, 200.0f, 3);
    BladeShadingParams p;
    p.waterRange = {0.2f, 0.9f};
    const std::vector<BladeShading> a = bake(blades, p, 42);
    const std::vector<BladeShading> again = bake(blades, p, 42);
    const std::vector<BladeShading> other = bake(blades, p, 43);
    EXPECT_EQ(a, again);
    std::size_t differing = 0;
    double ageSum = 0.0;
    for (std::size_t i = 0; i < blades.size(); ++i) {
        EXPECT_GE(a[i].age(), 0.0f);
        EXPECT_LE(a[i].age(), 1.0f);
        EXPECT_GE(a[i].water(), 0.2f);
        EXPECT_LE(a[i].water(), 0.9f);
        // Young is wet: water = mix(youngest, oldest, age).
        EXPECT_NEAR(a[i].water(), 0.9f + (0.2f - 0.9f) * a[i].age(), 1e-6f);
        EXPECT_EQ(a[i].waterAge.z, 0.0f);
        EXPECT_EQ(a[i].waterAge.w, 0.0f);
        differing += a[i].age() != other[i].age() ? 1 : 0;
        ageSum += a[i].age();
    }
    EXPECT_GT(differing, blades.size() * 9 / 10);
    EXPECT_NEAR(ageSum / static_cast<double>(blades.size()), 0.5, 0.02);
}

TEST(BladeShading, PaddingBladesKeepTheDefault) {
    const std::vector<Blade> blades = uniformSquare(3.0f, 150.0f, 8);
    const PatchedBlades patched = buildPatches(blades, 256);
    ASSERT_GT(patched.blades.size(), blades.size());
    const std::vector<BladeShading> s = bake(patched.blades, BladeShadingParams{});
    ASSERT_EQ(s.size(), patched.blades.size());
    // Padding is nobody's neighbour: the live blades shade as without it.
    const std::vector<BladeShading> unpadded = bake(blades, BladeShadingParams{});
    std::size_t padding = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::uint32_t source = patched.sourceIndex[i];
        if (source == UINT32_MAX) {
            EXPECT_EQ(s[i], BladeShading{}) << "slot " << i;
            ++padding;
            continue;
        }
        EXPECT_NEAR(s[i].ao(), unpadded[source].ao(), 1e-3f) << "slot " << i;
        EXPECT_LT(angleDeg(s[i].blurredNormal(), unpadded[source].blurredNormal()), 0.05f);
    }
    EXPECT_EQ(padding, patched.blades.size() - blades.size());
}

TEST(BladeShading, UnusableBladesKeepTheDefault) {
    std::vector<Blade> blades = {bladeAt({0, 0, 0}), bladeAt({0.01f, 0, 0}), bladeAt({0.02f, 0, 0}),
                                 bladeAt({0.03f, 0, 0})};
    blades[1].v1H.w = -0.2f;
    blades[2].v0Theta.x = std::nanf("");
    blades[3].upS = glm::vec4(0.0f, 0.0f, 0.0f, 60.0f);
    const std::vector<BladeShading> s = bake(blades, BladeShadingParams{});
    EXPECT_FLOAT_EQ(s[0].ao(), 1.0f);
    for (std::size_t i = 1; i < 4; ++i)
        EXPECT_EQ(s[i], BladeShading{}) << "blade " << i;
}

TEST(BladeShading, EmptyInputGivesNothing) {
    EXPECT_TRUE(bake({}, BladeShadingParams{}).empty());
}

TEST(BladeShading, ResultIsTheSameForAnyThreadCount) {
    std::vector<Blade> blades = uniformSquare(12.0f, 300.0f, 2);
    for (const Blade& b : sphereBlades(1.0f, 3000, {0.0f, 1.5f, 0.0f}))
        blades.push_back(b);
    const std::vector<BladeShading> one = bake(blades, BladeShadingParams{}, 5, 1);
    for (unsigned threads : {2u, 4u, 7u})
        EXPECT_TRUE(bake(blades, BladeShadingParams{}, 5, threads) == one) << threads << " threads";
}

TEST(BladeShading, ZeroRadiiTurnTheTermsOff) {
    const std::vector<Blade> blades = uniformSquare(2.0f, 500.0f, 4);
    BladeShadingParams p;
    p.aoRadiusM = 0.0f;
    p.normalBlurRadiusM = 0.0f;
    const std::vector<BladeShading> s = bake(blades, p);
    for (std::size_t i = 0; i < blades.size(); ++i) {
        EXPECT_EQ(s[i].ao(), 1.0f);
        EXPECT_EQ(s[i].blurredNormal(), blades[i].up());
    }
}

TEST(BladeShading, RejectsBadParameters) {
    const std::vector<Blade> blades = {bladeAt({0, 0, 0})};
    const auto failsOn = [&](const BladeShadingParams& p, const std::string& field) {
        const Result<std::vector<BladeShading>> r = bakeBladeShading(blades, p, 1);
        ASSERT_FALSE(r.ok()) << field;
        EXPECT_EQ(r.error().path, field);
    };
    const float nan = std::nanf("");
    BladeShadingParams p;
    p.aoRadiusM = nan;
    failsOn(p, "/lighting/ao_radius");
    p = {};
    p.aoRadiusM = -0.1f;
    failsOn(p, "/lighting/ao_radius");
    p = {};
    p.normalBlurRadiusM = INFINITY;
    failsOn(p, "/lighting/normal_blur_radius");
    p = {};
    p.normalBlurRadiusM = 1e-9f;
    failsOn(p, "/lighting/normal_blur_radius");
    p = {};
    p.aoStrength = nan;
    failsOn(p, "/lighting/ao_strength");
    p = {};
    p.cellSigmas = 0.01f;  // between exact and the smallest cells
    failsOn(p, "/lighting/ao_cell");
    p.cellSigmas = nan;
    failsOn(p, "/lighting/ao_cell");
    p = {};
    p.aoStrength = -1.0f;
    failsOn(p, "/lighting/ao_strength");
    p = {};
    p.aoFloor = 1.5f;
    failsOn(p, "/lighting/ao_floor");
    p = {};
    p.waterRange.x = -0.1f;
    failsOn(p, "/lighting/water/0");
    p = {};
    p.waterRange.y = nan;
    failsOn(p, "/lighting/water/1");
}

}  // namespace
}  // namespace grass::core
