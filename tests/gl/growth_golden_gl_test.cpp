// The growth model seen (issue 6): a plane whose soil map is a left-to-right ramp (poor soil on
// the left, good on the right), grown with growth on, drawn by both techniques — the Jahrmann
// blades and Kim & Cho's stem sets. Two checks per technique:
//   - what a user must see: grass covers more of the image and reaches higher on the right,
//     and it is greener there (poor grass turns to straw), measured against a render of the
//     bare plane so the ground and the sky never count as grass;
//   - a golden image (tests/data/golden/growth-ramp-*.png) under the metric and tolerances of
//     golden_gl_test.cpp (see there why 48 levels, 0.5 % of the pixels, mean 1.0).
// Refresh: GRASS_UPDATE_GOLDEN=1 grass_gl_tests --gtest_filter='GrowthGolden*', then look.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "gl_context_fixture.h"
#include "maps/map_image.h"
#include "render/offscreen_render.h"
#include "support/image_compare.h"
#include "support/plane_project.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

constexpr int WIDTH = 128;
constexpr int HEIGHT = 80;
constexpr int PIXEL_THRESHOLD = 48;
constexpr double MAX_DIFFERING_SHARE = 0.005;
constexpr double MAX_MEAN_ABS = 1.0;
// A pixel is grass when it moved this far from the bare-plane render: grass against sky or
// soil differs by far more, antialiased blade edges by less.
constexpr int GRASS_THRESHOLD = 30;

using GrowthGoldenTest = GlTest;

// 1.6 m plane, 1000 blades 0.2–0.3 m at full growth, soil 0 at u = 0 to 1 at u = 1 (x grows
// with u on the procedural plane), no light map (l = 1). density 0 gives the bare plane.
core::Scene rampScene(float density) {
    // A folder of this test's own: CTest runs the cases side by side, and scratchDir empties
    // the folder it returns.
    const std::filesystem::path folder =
        scratchDir("growth-golden-" +
                   std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                   "-" + std::to_string(int(density)));
    core::MapImage ramp = core::makeConstantMap(64, 4, 0.0f);
    for (int y = 0; y < ramp.height; ++y)
        for (int x = 0; x < ramp.width; ++x)
            ramp.texels[static_cast<std::size_t>(y * ramp.width + x)] =
                (static_cast<float>(x) + 0.5f) / static_cast<float>(ramp.width);
    EXPECT_TRUE(core::saveMapImage(ramp, folder / "soil-ramp.png").ok());
    core::LoadedProject loaded = planeFieldProject({1.6f, 2, density, 0.2f, 0.3f}, folder);
    core::GrassLayer& layer = loaded.project.layers.front();
    layer.soilMap = "soil-ramp.png";
    layer.mapResolution = {64, 4};
    layer.growth.enabled = true;
    layer.scatter.blade.widthMin = 0.012f;
    layer.scatter.blade.widthMax = 0.018f;
    auto built = core::buildScene(loaded);
    EXPECT_TRUE(built.ok()) << built.error().str();
    return built.ok() ? std::move(*built) : core::Scene{};
}

const core::Scene& grassScene() {
    static const core::Scene scene = rampScene(390.0f);
    return scene;
}

const core::Scene& bareScene() {
    static const core::Scene scene = rampScene(0.0f);
    return scene;
}

gl::Rgba8Image render(const core::Scene& scene, core::GrassTechnique technique) {
    core::OrbitCamera camera;
    camera.target = glm::vec3(0.0f, 0.1f, 0.15f);
    camera.yawRad = 0.0f;  // looking along −z: x (and the ramp) runs left to right
    camera.distance = 1.45f;
    camera.pitchRad = 0.22f;
    camera.nearPlane = 0.05f;
    camera.farPlane = 20.0f;
    render::OffscreenRequest request;
    request.width = WIDTH;
    request.height = HEIGHT;
    request.msaaSamples = 4;
    request.frames = 1;
    request.options.geometry = render::GeometryPath::Strips;
    request.options.technique = technique;
    request.options.sun.direction = glm::vec3(0.3f, -0.8f, -0.4f);
    auto result = render::renderOffscreen(scene, camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    return result.ok() ? std::move(result->image) : gl::Rgba8Image{};
}

struct BandStats {
    std::size_t grassPixels = 0;
    double topRow = 0.0;     // mean over the columns of their highest grass row (0 = top)
    double greenness = 0.0;  // mean (G − R)/(G + R) over grass pixels: hue, not brightness
};

// Grass statistics of the columns [x0, x1): pixels that differ from the bare plane.
BandStats band(const gl::Rgba8Image& grass, const gl::Rgba8Image& bare, int x0, int x1) {
    BandStats stats;
    double greenSum = 0.0;
    std::vector<int> columnTop(static_cast<std::size_t>(x1 - x0), HEIGHT);
    for (int y = 0; y < HEIGHT; ++y)
        for (int x = x0; x < x1; ++x) {
            // Rows come top first (the image as saved).
            const std::size_t i = 4 * static_cast<std::size_t>(y * WIDTH + x);
            int moved = 0;
            for (int c = 0; c < 3; ++c)
                moved = std::max(moved, std::abs(int(grass.pixels[i + c]) - int(bare.pixels[i + c])));
            if (moved <= GRASS_THRESHOLD)
                continue;
            ++stats.grassPixels;
            const double r = grass.pixels[i], g = grass.pixels[i + 1];
            greenSum += (g - r) / (g + r + 1.0);
            int& top = columnTop[static_cast<std::size_t>(x - x0)];
            top = std::min(top, y);
        }
    stats.greenness = stats.grassPixels > 0 ? greenSum / double(stats.grassPixels) : 0.0;
    for (int top : columnTop)
        stats.topRow += top / double(columnTop.size());
    return stats;
}

std::filesystem::path goldenFile(const std::string& name) {
    return sourceDir() / "tests/data/golden" / (name + ".png");
}

bool updating() {
    const char* update = std::getenv("GRASS_UPDATE_GOLDEN");
    return update != nullptr && std::string(update) == "1";
}

void checkTechnique(core::GrassTechnique technique, const std::string& name) {
    SCOPED_TRACE(name);
    const gl::Rgba8Image grass = render(grassScene(), technique);
    const gl::Rgba8Image bare = render(bareScene(), technique);
    ASSERT_EQ(grass.pixels.size(), std::size_t(WIDTH) * HEIGHT * 4);
    ASSERT_EQ(bare.pixels.size(), grass.pixels.size());

    // The middle of the plane, away from its corners: poor third against good third.
    const BandStats poor = band(grass, bare, WIDTH / 6, WIDTH / 6 + WIDTH / 4);
    const BandStats good = band(grass, bare, WIDTH - WIDTH / 6 - WIDTH / 4, WIDTH - WIDTH / 6);
    std::printf("[ growth ] %-8s poor: %zu px, top row %.1f, green %.3f | good: %zu px, top row "
                "%.1f, green %.3f\n",
                name.c_str(), poor.grassPixels, poor.topRow, poor.greenness, good.grassPixels,
                good.topRow, good.greenness);
    ASSERT_GT(poor.grassPixels, 0u);
    EXPECT_GT(double(good.grassPixels), 1.3 * double(poor.grassPixels)) << "taller, wider grass";
    EXPECT_LT(good.topRow, poor.topRow - 2.0) << "good soil reaches higher in the image";
    EXPECT_GT(good.greenness, poor.greenness + 0.05) << "good soil is greener";

    if (updating()) {
        ASSERT_TRUE(writeRgba8Image(goldenFile(name), WIDTH, HEIGHT, grass.pixels).ok());
        return;
    }
    auto reference = readRgba8Image(goldenFile(name));
    ASSERT_TRUE(reference.ok()) << reference.error().str()
                                << " (GRASS_UPDATE_GOLDEN=1 writes the references)";
    const ImageDifference diff = compareImages(grass.pixels, reference->pixels, PIXEL_THRESHOLD);
    std::printf("[ golden ] %-22s differing %.4f, mean abs %.3f, max %d\n", name.c_str(),
                diff.differingShare, diff.meanAbs, diff.maxChannel);
    if (diff.differingShare > MAX_DIFFERING_SHARE || diff.meanAbs > MAX_MEAN_ABS) {
        const auto actual = scratchDir("growth-golden") / (name + ".actual.png");
        EXPECT_TRUE(writeRgba8Image(actual, WIDTH, HEIGHT, grass.pixels).ok());
        ADD_FAILURE() << name << " differs from " << goldenFile(name) << ": share "
                      << diff.differingShare << ", mean " << diff.meanAbs
                      << "; this render is in " << actual;
    }
}

TEST_F(GrowthGoldenTest, SoilRampGrowsTallerGreenerBladesToTheRight) {
    checkTechnique(core::GrassTechnique::Blades, "growth-ramp-blades");
}

TEST_F(GrowthGoldenTest, SoilRampGrowsTallerGreenerStemSetsToTheRight) {
    checkTechnique(core::GrassTechnique::Growth, "growth-ramp-stems");
}

}  // namespace
}  // namespace grass::test
