// The roof scene of issue 9 (SPEC §11): a ground plane with a roof slab over half of it and snow
// falling straight down. Snow lies outside, none under the roof, and the edge between is soft:
// a golden image of the shaded result, and the width of the edge measured on the coverage view
// (Fp), which shrinks as the sample count and the map resolution grow.
//
// Edge width: the visible edge is where Fp crosses ½. In each image row, from the sheltered
// side, `left` is the first pixel at or above ½ and `right` the last one below it; the width is
// P95(right) − P5(left) over the rows, in pixels. With one sample a pixel is either covered or
// not, at random within the sample disc, so the edge wanders over the whole disc (ragged); more
// stratified samples average the disc and the crossing settles on one line. The disc's radius
// is in texels, so a finer map narrows it in metres. Both show as a narrower band.
//
// Golden tolerance: the image holds no geometric edges (the roof is above the camera), only the
// snow's shading; llvmpipe is deterministic for one build, and another CPU's LLVM code (FMA
// contraction) may move the noise or a sample's texel by one float rounding, which flips single
// samples of the edge disc: at most a few levels on a few edge pixels. A pixel counts as
// different beyond 24 levels, and 0.5 % of pixels may differ; a wrong shelter or a missing soft
// edge changes whole columns (several percent).
// Refresh after an intended change: GRASS_UPDATE_GOLDEN=1 grass_gl_tests --gtest_filter='SnowRoof*'
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gl_context_fixture.h"
#include "mesh/procedural.h"
#include "render/offscreen_render.h"
#include "support/golden_file.h"
#include "support/plane_project.h"

namespace grass::test {
namespace {

using SnowRoofGlTest = GlTest;

constexpr int SIDE = 160;
constexpr int PIXEL_THRESHOLD = 24;
constexpr double MAX_DIFFERING_SHARE = 0.005;
constexpr double MAX_MEAN_ABS = 1.0;

// An 8 m ground plane (no grass: the ground's snow is what is measured) and a 4 × 4 m roof at
// 3 m over x ∈ [−4, 0].
const core::Scene& roofScene() {
    static const core::Scene scene = [] {
        const core::LoadedProject loaded = planeFieldProject({8.0f, 4, 1.0f, 0.3f, 0.4f});
        auto built = core::buildScene(loaded);
        EXPECT_TRUE(built.ok()) << built.error().str();
        core::Scene out = built.ok() ? std::move(*built) : core::Scene{};
        out.layers.clear();
        core::ProceduralMeshParams slab;
        slab.size = 1.0f;
        slab.resolution = 1;
        core::SceneProp roof;
        roof.name = "roof";
        roof.mesh = core::makeProceduralMesh(slab);
        roof.position = {-2.0f, 3.0f, 0.0f};
        roof.scale = 4.0f;
        out.props.push_back(std::move(roof));
        return out;
    }();
    return scene;
}

core::SnowParams roofSnow(int resolution, int samples) {
    core::SnowParams snow;
    snow.enabled = 1u;
    snow.amountM = 0.05f;
    snow.fallDirection = {0.0f, -1.0f, 0.0f};
    snow.inclineNoise = 0.0f;  // flat ground: Fp is the exposure alone
    snow.mapResolution = resolution;
    snow.samples = samples;
    snow.sampleRadiusTexels = 4.0f;  // a disc wide enough to measure at every resolution
    return snow;
}

// Under the roof's edge from 2 m up, looking almost straight down: the view spans about ±0.4 m
// around x = 0 (the roof itself is above the camera, out of view).
gl::Rgba8Image renderRoof(const core::SnowParams& snow, bool coverage) {
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt({0.0f, 2.0f, 0.2f}, {0.0f, 0.0f, 0.0f}, 0.4f);
    render::OffscreenRequest request;
    request.width = request.height = SIDE;
    request.msaaSamples = 0;  // one sample: pixels are not blended across the edge
    request.frames = 1;
    request.options.snow = snow;
    request.options.snowCoverageView = coverage;
    auto result = render::renderOffscreen(roofScene(), camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    return result.ok() ? std::move(result->image) : gl::Rgba8Image{};
}

float coverageAt(const gl::Rgba8Image& image, int x, int y) {
    return float(image.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4]) /
           255.0f;
}

struct Edge {
    float widthPx = 0.0f;
    float softPx = 0.0f;        // median count per row of pixels with 0.05 < Fp < 0.95
    float shelteredMax = 1.0f;  // largest Fp in the outer eighth on the roof's side
    float openMin = 0.0f;       // smallest Fp in the outer eighth on the open side
};

Edge measureEdge(const gl::Rgba8Image& image) {
    std::vector<int> lefts, rights, soft;
    Edge edge;
    edge.shelteredMax = 0.0f;
    edge.openMin = 1.0f;
    for (int y = 0; y < image.height; ++y) {
        int left = image.width, right = -1, between = 0;
        for (int x = 0; x < image.width; ++x) {
            const float fp = coverageAt(image, x, y);
            between += fp > 0.05f && fp < 0.95f;
            if (fp >= 0.5f)
                left = std::min(left, x);
            else
                right = x;
            if (x < image.width / 8)
                edge.shelteredMax = std::max(edge.shelteredMax, fp);
            if (x >= image.width - image.width / 8)
                edge.openMin = std::min(edge.openMin, fp);
        }
        soft.push_back(between);
        lefts.push_back(left);
        rights.push_back(right + 1);
    }
    std::sort(soft.begin(), soft.end());
    std::sort(lefts.begin(), lefts.end());
    std::sort(rights.begin(), rights.end());
    const auto percentile = [](const std::vector<int>& v, double p) {
        return float(v[std::size_t(p * double(v.size() - 1))]);
    };
    edge.widthPx = percentile(rights, 0.95) - percentile(lefts, 0.05);
    edge.softPx = percentile(soft, 0.5);
    return edge;
}

TEST_F(SnowRoofGlTest, SnowOutsideNoneUnderTheRoofAndTheEdgeNarrowsWithQuality) {
    std::vector<std::pair<std::string, Edge>> edges;
    const auto measure = [&](int resolution, int samples) {
        const gl::Rgba8Image image = renderRoof(roofSnow(resolution, samples), true);
        EXPECT_EQ(image.pixels.size(), std::size_t(SIDE) * SIDE * 4);
        const Edge edge = image.pixels.empty() ? Edge{} : measureEdge(image);
        std::printf("[ roof ] %4d² %2d samples: edge %.1f px, soft %.0f px\n", resolution, samples,
                    double(edge.widthPx), double(edge.softPx));
        EXPECT_EQ(edge.shelteredMax, 0.0f) << "no snow under the roof";
        EXPECT_EQ(edge.openMin, 1.0f) << "full snow in the open";
        return edge;
    };
    const Edge ragged = measure(1024, 1);
    const Edge few = measure(1024, 4);
    const Edge many = measure(1024, 32);
    EXPECT_GT(ragged.widthPx, few.widthPx);
    EXPECT_GT(few.widthPx, many.widthPx);
    const Edge coarse = measure(512, 8);
    const Edge medium = measure(1024, 8);
    const Edge fine = measure(2048, 8);
    EXPECT_GT(coarse.widthPx, medium.widthPx);
    EXPECT_GT(medium.widthPx, fine.widthPx);
    // Soft, not a hard aliased step: with many samples Fp ramps over the disc (8 texels of
    // 8.5 m / 1024 ≈ 6.6 cm, about 13 px here); a single sample gives only 0 or 1.
    EXPECT_GE(many.softPx, 6.0f);
    EXPECT_EQ(ragged.softPx, 0.0f);
}

TEST_F(SnowRoofGlTest, ShadedImageMatchesItsReference) {
    const gl::Rgba8Image image = renderRoof(roofSnow(1024, 8), false);
    ASSERT_EQ(image.pixels.size(), std::size_t(SIDE) * SIDE * 4);
    expectMatchesGolden("snow-roof", image, {PIXEL_THRESHOLD, MAX_DIFFERING_SHARE, MAX_MEAN_ABS});
    // The golden must show both sides: bright snow on the right, darker bare ground on the left.
    const auto brightness = [&](int x) {
        const std::size_t i = (std::size_t(SIDE / 2) * SIDE + std::size_t(x)) * 4;
        return int(image.pixels[i]) + image.pixels[i + 1] + image.pixels[i + 2];
    };
    EXPECT_GT(brightness(SIDE - 5), brightness(4) + 150);
}

}  // namespace
}  // namespace grass::test
