// Snow accumulation, CPU reference (SPEC §11, paper 004, issue 9): the exposure Fe against a depth
// map, the incline Fi, the coverage Fp and colour, the noise sum, the displacement and its smooth
// boundary, snow on grass, and the amount over time. The pinned values at the end are what the
// GLSL port must reproduce.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "snow/snow.h"
#include "support/snow_triangles.h"
#include "util/rng.h"

namespace grass::core {
namespace {

using Triangle = test::SnowTriangle;
using test::addRect;

// Snow falling straight down on a 10 m ground with a 2 × 2 m roof 2 m up over the origin. The view
// is laid out by hand so texels are 1/32 m and the roof edges (x, z = ±1) fall on texel borders:
// the analytic disc coverage below is then exact up to sampling.
constexpr int RES = 512;
constexpr float TEXEL_M = 1.0f / 32.0f;

OrthoSnowView roofView() {
    OrthoSnowView view;
    view.origin = {-8.0f, 3.0f, -8.0f};
    view.sizeM = 16.0f;
    view.depthRangeM = 4.0f;
    return view;
}

SnowDepthMap roofMap() {
    std::vector<Triangle> triangles;
    addRect(triangles, -5.0f, 5.0f, -5.0f, 5.0f, 0.0f);
    addRect(triangles, -1.0f, 1.0f, -1.0f, 1.0f, 2.0f);
    return renderSnowDepthMap(triangles, roofView(), RES);
}

constexpr glm::vec3 UP{0.0f, 1.0f, 0.0f};
constexpr float BIAS_M = 0.02f;

// The exposed share of a disc of radius r whose centre lies d outside a straight shelter edge.
float discExposure(float d, float r) {
    if (d >= r)
        return 1.0f;
    if (d <= -r)
        return 0.0f;
    const float t = d / r;
    return 1.0f - (std::acos(t) - t * std::sqrt(1.0f - t * t)) / std::numbers::pi_v<float>;
}

TEST(SnowMap, ViewCoordinatesRoundTrip) {
    const OrthoSnowView down = makeOrthoSnowView({0, -1, 0}, {{-5, 0, -5}, {5, 2, 5}}, 0.5f);
    EXPECT_EQ(down.right, glm::vec3(1, 0, 0));
    EXPECT_EQ(down.up, glm::vec3(0, 0, 1));
    const glm::vec3 top = snowMapCoords(down, {0, 2, 0}), bottom = snowMapCoords(down, {0, 0, 0});
    EXPECT_NEAR(top.z, 0.5f, 1e-5f);  // the near plane sits a margin above the highest point
    EXPECT_GT(bottom.z, top.z);       // depth grows along the fall
    const OrthoSnowView slanted = makeOrthoSnowView({0.3f, -1, 0.5f}, {{-5, 0, -5}, {5, 2, 5}}, 0);
    Rng rng(7);
    for (int i = 0; i < 100; ++i) {
        const glm::vec3 p{rng.uniform(-5, 5), rng.uniform(0, 2), rng.uniform(-5, 5)};
        const glm::vec3 c = snowMapCoords(slanted, p);
        EXPECT_GE(c.x, -1e-5f);
        EXPECT_LE(c.y, 1.0f + 1e-5f);
        const glm::vec3 back = snowMapToWorld(slanted, c);
        EXPECT_NEAR(glm::length(back - p), 0.0f, 1e-4f) << "point " << i;
    }
}

TEST(SnowMap, RasteriserKeepsTheSurfaceNearestTheSky) {
    const SnowDepthMap map = roofMap();
    const auto texelOf = [&](glm::vec3 p) {
        const glm::vec3 c = snowMapCoords(map.view, p);
        return glm::ivec2(glm::floor(glm::vec2(c) * float(RES)));
    };
    const glm::ivec2 roof = texelOf({0.5f, 0, 0.5f}), ground = texelOf({3, 0, 3});
    EXPECT_FLOAT_EQ(map.at(roof.x, roof.y), 1.0f);      // 3 − 2 m
    EXPECT_FLOAT_EQ(map.at(ground.x, ground.y), 3.0f);  // 3 − 0 m
    const glm::ivec2 outside = texelOf({7, 0, 7});
    EXPECT_EQ(map.at(outside.x, outside.y), SNOW_MAP_EMPTY);
    EXPECT_EQ(map.at(-1, 0), SNOW_MAP_EMPTY);
}

TEST(SnowExposure, OpenGroundIsFullyExposed) {
    const SnowDepthMap map = roofMap();
    Rng rng(1);
    for (int samples : {1, 4, 18, 32}) {
        for (int i = 0; i < 50; ++i) {
            const glm::vec3 p{rng.uniform(2, 4.5f), 0.0f, rng.uniform(-4.5f, 4.5f)};
            EXPECT_EQ(exposureCoefficient(map, p, UP, samples, 4.0f, BIAS_M), 1.0f)
                << samples << " samples at x " << p.x << " z " << p.z;
        }
    }
}

TEST(SnowExposure, GroundUnderTheRoofIsSheltered) {
    const SnowDepthMap map = roofMap();
    Rng rng(2);
    for (int samples : {1, 18, 32}) {
        for (int i = 0; i < 50; ++i) {
            const glm::vec3 p{rng.uniform(-0.8f, 0.8f), 0.0f, rng.uniform(-0.8f, 0.8f)};
            EXPECT_EQ(exposureCoefficient(map, p, UP, samples, 4.0f, BIAS_M), 0.0f);
        }
        // The roof itself is the nearest surface: exposed.
        EXPECT_EQ(exposureCoefficient(map, {0.2f, 2.0f, 0.1f}, UP, samples, 4.0f, BIAS_M), 1.0f);
    }
}

// Mean |Fe − exact disc coverage| over points crossing the roof edge x = 1.
float edgeError(const SnowDepthMap& map, int samples, float radiusTexels, int& fractional) {
    double error = 0.0;
    int count = 0;
    fractional = 0;
    for (int zi = 0; zi < 24; ++zi) {
        const float z = -0.75f + 0.0625f * float(zi);
        for (float d = -6.0f; d <= 6.0f; d += 0.25f) {
            const glm::vec3 p{1.0f + d * TEXEL_M, 0.0f, z};
            const float fe = exposureCoefficient(map, p, UP, samples, radiusTexels, BIAS_M);
            EXPECT_GE(fe, 0.0f);
            EXPECT_LE(fe, 1.0f);
            if (fe > 0.0f && fe < 1.0f)
                ++fractional;
            error += std::abs(fe - discExposure(d, radiusTexels));
            ++count;
        }
    }
    return float(error / count);
}

TEST(SnowExposure, EdgeIsFractionalAndConvergesWithSamples) {
    const SnowDepthMap map = roofMap();
    int fractional1 = 0, fractional4 = 0, fractional32 = 0;
    const float error1 = edgeError(map, 1, 4.0f, fractional1);
    const float error4 = edgeError(map, 4, 4.0f, fractional4);
    const float error32 = edgeError(map, 32, 4.0f, fractional32);
    // One sample is Ohlsson's hard test: never fractional.
    EXPECT_EQ(fractional1, 0);
    EXPECT_GT(fractional32, fractional4);
    EXPECT_LT(error4, error1);
    EXPECT_LT(error32, error4);
    // 32 stratified samples in 4-texel discs: the residual is the texel grid, not the jitter.
    EXPECT_LT(error32, 0.03f) << "errors 1/4/32: " << error1 << " " << error4 << " " << error32;
}

TEST(SnowExposure, IsDeterministicPerPoint) {
    const SnowDepthMap map = roofMap();
    const glm::vec3 p{1.01f, 0.0f, 0.3f};
    EXPECT_EQ(exposureCoefficient(map, p, UP, 18, 4.0f, BIAS_M),
              exposureCoefficient(map, p, UP, 18, 4.0f, BIAS_M));
    // Radius 0 is the single-texel test of Ohlsson: a hard step at the edge.
    EXPECT_EQ(exposureCoefficient(map, {0.99f, 0, 0.3f}, UP, 18, 0.0f, BIAS_M), 0.0f);
    EXPECT_EQ(exposureCoefficient(map, {1.01f, 0, 0.3f}, UP, 18, 0.0f, BIAS_M), 1.0f);
}

// A slope's own depth changes across the sample disc; the slope term of the bias keeps it lit.
TEST(SnowExposure, OpenSlopeDoesNotShadowItself) {
    for (float slopeDeg : {30.0f, 45.0f, 70.0f}) {
        const float t = std::tan(glm::radians(slopeDeg));
        const std::vector<Triangle> slope{
            {glm::vec3(-4, -4 * t, -4), glm::vec3(4, 4 * t, -4), glm::vec3(4, 4 * t, 4)},
            {glm::vec3(-4, -4 * t, -4), glm::vec3(4, 4 * t, 4), glm::vec3(-4, -4 * t, 4)}};
        const Bounds bounds{{-4, -4 * t, -4}, {4, 4 * t, 4}};
        const SnowDepthMap map =
            renderSnowDepthMap(slope, makeOrthoSnowView({0, -1, 0}, bounds, 0.5f), 512);
        const glm::vec3 normal = glm::normalize(glm::vec3(-t, 1, 0));
        Rng rng(3);
        for (int i = 0; i < 40; ++i) {
            const float x = rng.uniform(-3, 3);
            const glm::vec3 p{x, x * t, rng.uniform(-3, 3)};
            EXPECT_EQ(exposureCoefficient(map, p, normal, 32, 4.0f, BIAS_M), 1.0f)
                << slopeDeg << "° at x " << x;
        }
    }
}

// The displacement's exposure has no cliff: its step between neighbouring texels across the
// edge stays small where the plain test jumps from 0 to 1.
TEST(SnowBoundary, DisplacementRisesSmoothlyAcrossTheEdge) {
    const SnowDepthMap map = roofMap();
    SnowParams params;
    params.samples = 32;
    params.boundaryFalloffM = 0.25f;  // 8 texels
    float previous = snowBoundaryExposure(map, {1.0f - 12 * TEXEL_M, 0, 0.2f}, UP, params);
    EXPECT_EQ(previous, 0.0f);
    float largestStep = 0.0f;
    for (int i = -11; i <= 12; ++i) {
        const float fe =
            snowBoundaryExposure(map, {1.0f + float(i) * TEXEL_M, 0, 0.2f}, UP, params);
        largestStep = std::max(largestStep, std::abs(fe - previous));
        previous = fe;
    }
    EXPECT_EQ(previous, 1.0f);
    EXPECT_LT(largestStep, 0.3f);
}

TEST(SnowIncline, FollowsCosineAndNoiseUpToNinetyDegrees) {
    // φ = 0°: 1 + n, clamped.
    EXPECT_EQ(inclineCoefficient(UP, UP, 1.0f, 0.2f), 1.0f);
    EXPECT_FLOAT_EQ(inclineCoefficient(UP, UP, -1.0f, 0.2f), 0.8f);
    EXPECT_EQ(inclineCoefficient(3.0f * UP, UP, 0.0f, 0.2f), 1.0f);  // normals need not be unit
    // φ = 60°: cos φ + n.
    const glm::vec3 n60{std::sin(glm::radians(60.0f)), 0.5f, 0.0f};
    EXPECT_NEAR(inclineCoefficient(n60, UP, 0.5f, 0.2f), 0.6f, 1e-6f);
    // φ = 90° and beyond: exactly 0, whatever the noise.
    for (float noise : {-1.0f, 0.0f, 1.0f}) {
        EXPECT_EQ(inclineCoefficient({1, 0, 0}, UP, noise, 1.0f), 0.0f);
        EXPECT_EQ(inclineCoefficient({1, -1, 0}, UP, noise, 1.0f), 0.0f);
        EXPECT_EQ(inclineCoefficient(-UP, UP, noise, 1.0f), 0.0f);
    }
}

TEST(SnowIncline, CoverageAndColourStayInRange) {
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        Rng rng(seed);
        const glm::vec3 normal{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        if (glm::length(normal) < 1e-3f)
            continue;
        const float fi = inclineCoefficient(normal, UP, rng.uniform(-1, 1), rng.uniform(0, 1));
        const float fp = snowCoverage(rng.uniform(), fi);
        ASSERT_GE(fi, 0.0f) << "seed " << seed;
        ASSERT_LE(fi, 1.0f) << "seed " << seed;
        ASSERT_GE(fp, 0.0f) << "seed " << seed;
        ASSERT_LE(fp, fi) << "seed " << seed;
    }
    const glm::vec3 cn{0.1f, 0.3f, 0.05f}, cs{0.9f, 0.95f, 1.0f};
    EXPECT_EQ(snowColor(cn, cs, 0.0f), cn);
    EXPECT_EQ(snowColor(cn, cs, 1.0f), cs);
    EXPECT_NEAR(snowColor(cn, cs, 0.5f).x, 0.5f, 1e-6f);
}

TEST(SnowNoise, SumStaysInRangeAndIsDeterministic) {
    Rng rng(11);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p{rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
        const int octaves = 1 + int(rng.below(8));
        const float a = rng.uniform(0.05f, 1.0f), b = rng.uniform(1.1f, 4.0f);
        const float n = perlinNoise3(p), f = fractalNoise(p, octaves, a, b);
        ASSERT_GE(n, -1.0f);
        ASSERT_LE(n, 1.0f);
        ASSERT_GE(f, -1.0f) << "point " << i;
        ASSERT_LE(f, 1.0f) << "point " << i;
        ASSERT_EQ(f, fractalNoise(p, octaves, a, b));
    }
    // One octave is the noise itself (divided by A⁰ = 1); lattice points are zeros.
    EXPECT_EQ(fractalNoise({0.3f, 1.7f, -2.2f}, 1, 0.5f, 2.0f), perlinNoise3({0.3f, 1.7f, -2.2f}));
    EXPECT_EQ(perlinNoise3({3.0f, -2.0f, 7.0f}), 0.0f);
    // Continuous: a millimetre moves the value by little.
    EXPECT_NEAR(perlinNoise3({0.3f, 1.7f, -2.2f}), perlinNoise3({0.301f, 1.7f, -2.2f}), 0.01f);
}

// Values the GLSL port must reproduce (uint maths exactly, floats within rounding).
TEST(SnowNoise, PinnedValuesForTheShaderPort) {
    EXPECT_EQ(pcg3d({1u, 2u, 3u}), glm::uvec3(4204755366u, 1223881804u, 1500469937u));
    EXPECT_NEAR(perlinNoise3({0.3f, 1.7f, -2.2f}), 0.0771121979f, 1e-5f);
    EXPECT_NEAR(perlinNoise3({-10.25f, 4.5f, 7.125f}), -0.28656894f, 1e-5f);
    EXPECT_NEAR(fractalNoise({0.3f, 1.7f, -2.2f}, 4, 0.5f, 2.0f), -0.0736584738f, 1e-5f);
}

TEST(SnowSurface, ZeroAmountOrDisabledIsExactlySnowFree) {
    const glm::vec3 cn{0.12f, 0.34f, 0.056f};
    SnowParams zero;
    zero.enabled = 1;
    zero.amountM = 0.0f;
    SnowParams off;  // disabled by default
    for (const SnowParams& params : {zero, off}) {
        const SnowShade shade = shadeSnow(params, {0.3f, 0, 0.2f}, UP, 1.0f, 1.0f, cn);
        EXPECT_EQ(shade.color, cn);
        EXPECT_EQ(shade.displacement, glm::vec3(0.0f));
        EXPECT_EQ(snowDisplacement({0.3f, 0, 0.2f}, UP, 1.0f, params), glm::vec3(0.0f));
        EXPECT_EQ(snowDepthAt({0.3f, 0, 0.2f}, 1.0f, params), 0.0f);
        EXPECT_EQ(bladeTipSnow(1.0f, params), 0.0f);
    }
    EXPECT_EQ(snowLoadGravity(off, 0.5f, 1.0f), 0.0f);
}

TEST(SnowSurface, DisplacementIsAmountTimesExposureTimesNoiseAgainstTheFall) {
    SnowParams params;
    params.enabled = 1;
    params.amountM = 0.4f;
    params.fallDirection = {0.3f, -1.0f, 0.2f};
    const glm::vec3 up = snowUp(params);
    Rng rng(5);
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 p{rng.uniform(-9, 9), rng.uniform(-1, 1), rng.uniform(-9, 9)};
        const glm::vec3 normal = glm::normalize(glm::vec3(rng.uniform(-1, 1), 1, 0));
        const float fe = rng.uniform();
        const glm::vec3 d = snowDisplacement(p, 2.0f * normal, fe, params);
        const float depth = snowDepthAt(p, fe, params);
        EXPECT_NEAR(glm::length(d), depth, 1e-6f);
        EXPECT_NEAR(glm::dot(d, up), depth, 1e-6f);  // against the fall, whatever N
        EXPECT_NEAR(glm::length(glm::cross(d, up)), 0.0f, 1e-6f);
        EXPECT_GE(depth, 0.0f);                          // Zn ≥ 0
        EXPECT_LE(depth, params.amountM * fe + 1e-7f);
    }
    // The shaded point agrees with the separate functions.
    const SnowShade shade = shadeSnow(params, {1, 0, 2}, UP, 0.5f, 0.75f, glm::vec3(0.2f));
    EXPECT_EQ(shade.displacement, snowDisplacement({1, 0, 2}, UP, 0.75f, params));
    EXPECT_FLOAT_EQ(shade.Fp, 0.5f * shade.Fi);
}

TEST(SnowGrass, BuriedTipsAndLoad) {
    EXPECT_TRUE(bladeBuriedBySnow(0.1f, 0.2f));
    EXPECT_FALSE(bladeBuriedBySnow(0.3f, 0.2f));
    EXPECT_FALSE(bladeBuriedBySnow(0.2f, 0.2f));
    SnowParams params;
    params.enabled = 1;
    EXPECT_EQ(bladeTipSnow(0.7f, params), 0.7f);
    EXPECT_EQ(bladeSnowWhiteness(1.0f, 1.0f), 1.0f);
    EXPECT_EQ(bladeSnowWhiteness(1.0f, 0.5f), 0.0f);  // below the tip fraction
    EXPECT_GT(bladeSnowWhiteness(1.0f, 0.85f), 0.0f);
    params.loadGravity = 20.0f;
    EXPECT_FLOAT_EQ(snowLoadGravity(params, 0.1f, 1.0f), 2.0f);
    EXPECT_EQ(snowLoadGravity(params, 0.1f, 0.0f), 0.0f);  // sheltered blades carry nothing
}

TEST(SnowTime, AmountAccumulatesAndMeltsWithinItsBounds) {
    SnowParams params;
    params.amountM = 0.1f;
    params.maxAmountM = 0.3f;
    params.accumulationRate = 0.01f;
    EXPECT_EQ(snowAmountAt(params, 0.0f), 0.1f);
    EXPECT_EQ(snowAmountAt(params, -5.0f), 0.1f);
    EXPECT_NEAR(snowAmountAt(params, 5.0f), 0.15f, 1e-6f);
    EXPECT_EQ(snowAmountAt(params, 1000.0f), 0.3f);
    params.meltRate = 0.03f;
    EXPECT_NEAR(snowAmountAt(params, 2.0f), 0.06f, 1e-6f);
    EXPECT_EQ(snowAmountAt(params, 1000.0f), 0.0f);
}

}  // namespace
}  // namespace grass::core
