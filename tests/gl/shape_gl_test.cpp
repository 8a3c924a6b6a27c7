// Blade shapes (SPEC §7) on the GPU: each shape draws a measurably different outline, both
// geometry paths draw the same outline for every shape, and the width correction keeps far
// blades covering pixels.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>

#include "gl_context_fixture.h"
#include "render/offscreen_render.h"
#include "support/image_compare.h"
#include "support/plane_project.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using ShapeRenderTest = GlTest;

constexpr int SIDE = 128;

// 64 wide, short blades on a 1 m plane: sparse enough that blades seldom overlap, so the
// covered area follows each blade's outline.
core::Scene shapeScene() {
    core::LoadedProject loaded = planeFieldProject({1.0f, 2, 64.0f, 0.25f, 0.35f}, sourceDir());
    core::GrassLayer& layer = loaded.project.layers.front();
    layer.scatter.blade.widthMin = 0.015f;
    layer.scatter.blade.widthMax = 0.02f;
    auto scene = core::buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return std::move(*scene);
}

// Low and from the side, so blades show their faces rather than their tips.
core::OrbitCamera sideCamera() {
    core::OrbitCamera camera;
    camera.target = glm::vec3(0.0f, 0.12f, 0.0f);
    camera.distance = 1.5f;
    camera.pitchRad = 0.3f;
    camera.nearPlane = 0.05f;
    camera.farPlane = 50.0f;
    return camera;
}

gl::Rgba8Image renderWith(const core::Scene& scene, const core::OrbitCamera& camera,
                          render::GeometryPath path, bool widthCorrection = true,
                          int msaaSamples = 4) {
    render::OffscreenRequest request;
    request.width = request.height = SIDE;
    request.msaaSamples = msaaSamples;
    request.frames = 1;
    request.options.geometry = path;
    request.options.tessLevel = 8;
    request.options.stripSegments = 8;
    request.options.widthCorrection = widthCorrection;
    request.options.cull.frustum = request.options.cull.orientation = false;
    request.options.cull.distance = request.options.cull.occlusion = false;
    auto result = render::renderOffscreen(scene, camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    return result.ok() ? std::move(result->image) : gl::Rgba8Image{};
}

// A pixel is covered by grass when it differs from the empty scene (sky and soil only).
std::vector<bool> coverage(const gl::Rgba8Image& image, const gl::Rgba8Image& empty) {
    std::vector<bool> covered(image.pixels.size() / 4, false);
    for (std::size_t p = 0; p < covered.size(); ++p)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(int(image.pixels[4 * p + c]) - int(empty.pixels[4 * p + c])) > 8)
                covered[p] = true;
    return covered;
}

double share(const std::vector<bool>& covered) {
    std::size_t n = 0;
    for (const bool c : covered)
        n += c ? 1 : 0;
    return static_cast<double>(n) / static_cast<double>(std::max<std::size_t>(covered.size(), 1));
}

TEST_F(ShapeRenderTest, ShapesCoverTheAreaTheirOutlinesPredict) {
    core::Scene scene = shapeScene();
    ASSERT_GT(scene.totalBlades(), 40u);
    ASSERT_LT(scene.totalBlades(), 100u);
    const core::OrbitCamera camera = sideCamera();
    core::Scene empty = scene;
    empty.layers.clear();
    // One sample per pixel: a pixel counts as covered when its centre is, so thin outlines are
    // not inflated by the partly covered edge pixels multisampling would add.
    const gl::Rgba8Image background =
        renderWith(empty, camera, render::GeometryPath::Strips, true, 1);

    std::array<double, core::BLADE_SHAPE_COUNT> shares{};
    std::array<std::vector<bool>, core::BLADE_SHAPE_COUNT> covered;
    for (std::size_t i = 0; i < core::BLADE_SHAPE_COUNT; ++i) {
        scene.layers.front().shape = static_cast<core::BladeShape>(i);
        covered[i] =
            coverage(renderWith(scene, camera, render::GeometryPath::Strips, true, 1), background);
        shares[i] = share(covered[i]);
        RecordProperty(std::string(core::bladeShapeName(scene.layers.front().shape)),
                       std::to_string(shares[i]));
    }
    const auto at = [&](core::BladeShape s) { return shares[static_cast<std::size_t>(s)]; };
    using S = core::BladeShape;
    // Outline areas relative to the quad: quad 1, triangle-tip (τ = 0.5) 3/4, quadratic 2/3,
    // triangle 1/2, dandelion about 0.45. Overlapping and edge-on blades compress the ratios
    // (measured on llvmpipe: 0.203, 0.190, 0.176, 0.151, 0.118 of the image, steps of 7 %,
    // 8 % and 17 %), so the test asks for the order with steps of 3 %, 3 % and 8 %.
    EXPECT_GT(at(S::Quad), 0.05) << "the view must show the blades";
    EXPECT_GT(at(S::Quad), 1.03 * at(S::TriangleTip));
    EXPECT_GT(at(S::TriangleTip), 1.03 * at(S::Quadratic));
    EXPECT_GT(at(S::Quadratic), 1.08 * at(S::Triangle));
    // The dandelion leaf covers less than the triangle (measured 0.78 of it; asked < 0.9) and
    // other pixels: the triangle is widest at the root, the leaf narrow there, widest past the
    // middle and notched. Of the pixels either covers, at least 25 % are covered by only one
    // (measured 37 %; identical outlines give 0 %).
    EXPECT_LT(at(S::Dandelion), 0.9 * at(S::Triangle));
    const auto& tri = covered[static_cast<std::size_t>(S::Triangle)];
    const auto& dan = covered[static_cast<std::size_t>(S::Dandelion)];
    std::size_t either = 0, onlyOne = 0;
    for (std::size_t p = 0; p < tri.size(); ++p) {
        either += (tri[p] || dan[p]) ? 1 : 0;
        onlyOne += (tri[p] != dan[p]) ? 1 : 0;
    }
    ASSERT_GT(either, 0u);
    const double differing = static_cast<double>(onlyOne) / static_cast<double>(either);
    RecordProperty("dandelion_vs_triangle", std::to_string(differing));
    EXPECT_GT(differing, 0.25) << "dandelion and triangle differ on " << differing * 100
                               << " % of covered pixels";
}

TEST_F(ShapeRenderTest, StripsAndTessellationAgreeForEveryShape) {
    core::Scene scene = shapeScene();
    const core::OrbitCamera camera = sideCamera();
    for (std::size_t i = 0; i < core::BLADE_SHAPE_COUNT; ++i) {
        scene.layers.front().shape = static_cast<core::BladeShape>(i);
        const std::string name(core::bladeShapeName(scene.layers.front().shape));
        const gl::Rgba8Image strips = renderWith(scene, camera, render::GeometryPath::Strips);
        const gl::Rgba8Image tess = renderWith(scene, camera, render::GeometryPath::Tessellation);
        ASSERT_EQ(strips.pixels.size(), tess.pixels.size()) << name;
        // The tolerance of SceneRender.TessellationAndStripsDrawTheSameField: the same vertices
        // (v = i/8, u ∈ {0, 1}) on both paths, so only quad diagonals and rasterizer ties
        // differ; mean absolute difference under 2/255 and 97 % of pixels within 16/255.
        double sum = 0.0;
        std::size_t close = 0;
        for (std::size_t p = 0; p < strips.pixels.size(); p += 4) {
            int worst = 0;
            for (std::size_t c = 0; c < 3; ++c) {
                const int d = std::abs(int(strips.pixels[p + c]) - int(tess.pixels[p + c]));
                sum += d;
                worst = std::max(worst, d);
            }
            if (worst <= 16)
                ++close;
        }
        const double pixels = static_cast<double>(strips.pixels.size() / 4);
        EXPECT_LT(sum / (pixels * 3.0), 2.0) << name;
        EXPECT_GT(static_cast<double>(close) / pixels, 0.97) << name;
    }
}

TEST_F(ShapeRenderTest, RenderOptionShapeOverridesTheLayers) {
    core::Scene scene = shapeScene();
    const core::OrbitCamera camera = sideCamera();
    scene.layers.front().shape = core::BladeShape::Quad;
    const gl::Rgba8Image quad = renderWith(scene, camera, render::GeometryPath::Strips);
    scene.layers.front().shape = core::BladeShape::Triangle;
    render::OffscreenRequest request;
    request.width = request.height = SIDE;
    request.frames = 1;
    request.options.shape = core::BladeShape::Quad;
    request.options.cull.frustum = request.options.cull.orientation = false;
    request.options.cull.distance = request.options.cull.occlusion = false;
    auto overridden = render::renderOffscreen(scene, camera, request);
    ASSERT_TRUE(overridden.ok()) << overridden.error().str();
    EXPECT_EQ(overridden->image.pixels, quad.pixels);
}

TEST_F(ShapeRenderTest, WidthCorrectionKeepsSubPixelBladesCovering) {
    // Hair-thin blades (4 mm wide, 0.12 of the 3–4 cm) seen close stand in for far blades: at 1.5 m
    // with the 45° lens (154 px per metre at 1 m) they are ~0.4 px wide, below w_min = 1 px, so the
    // triangle blends fully towards the quad (Φ = 1) while the field still spans the image
    // and blades seldom overlap. A sub-pixel line covers about the same pixels whatever its
    // width, so the gain is far below the 3/2 of the areas: measured 1.2, asked 1.1.
    core::Scene scene = shapeScene();
    for (core::Blade& blade : scene.layers.front().patched.blades)
        blade.v2W.w *= 0.12f;
    core::Scene empty = scene;
    empty.layers.clear();
    const core::OrbitCamera camera = sideCamera();
    const gl::Rgba8Image background = renderWith(empty, camera, render::GeometryPath::Strips);
    const double off =
        share(coverage(renderWith(scene, camera, render::GeometryPath::Strips, false), background));
    const double on =
        share(coverage(renderWith(scene, camera, render::GeometryPath::Strips, true), background));
    RecordProperty("thin_off", std::to_string(off));
    RecordProperty("thin_on", std::to_string(on));
    EXPECT_GT(on, 1.1 * off) << "with correction " << on << ", without " << off;
}

// Below w_min every shape blends fully into the quad (Φ = 1), on both edges: hair-thin blades
// (0.05 of their width, ~0.15 px) drawn as triangles give exactly the picture of the same blades
// drawn as quads. 8× MSAA resolves the sub-pixel area, so the trapezoid SPEC's max(t, Φ·u)
// made (¾ of the quad, one edge moved) shows as paler pixels; that version measured a mean
// difference of 0.20 levels here, up to 54 levels in a pixel (this one: 0, the same picture).
TEST_F(ShapeRenderTest, FullyCorrectedShapesAreTheQuad) {
    core::Scene scene = shapeScene();
    for (core::Blade& blade : scene.layers.front().patched.blades)
        blade.v2W.w *= 0.05f;
    const core::OrbitCamera camera = sideCamera();
    const auto drawnAs = [&](core::BladeShape shape) {
        render::OffscreenRequest request;
        request.width = request.height = SIDE;
        request.msaaSamples = 8;
        request.frames = 1;
        request.options.shape = shape;
        request.options.cull.frustum = request.options.cull.orientation = false;
        request.options.cull.distance = request.options.cull.occlusion = false;
        auto result = render::renderOffscreen(scene, camera, request);
        EXPECT_TRUE(result.ok()) << result.error().str();
        return result.ok() ? std::move(result->image) : gl::Rgba8Image{};
    };
    const gl::Rgba8Image quad = drawnAs(core::BladeShape::Quad);
    const gl::Rgba8Image triangle = drawnAs(core::BladeShape::Triangle);
    ASSERT_EQ(quad.pixels.size(), triangle.pixels.size());
    const ImageDifference diff = compareImages(quad.pixels, triangle.pixels, 48);
    std::printf("[ shape ] hair-thin triangle against quad: mean %.3f, max %d levels\n",
                diff.meanAbs, diff.maxChannel);
    EXPECT_LT(diff.meanAbs, 0.05);
}

}  // namespace
}  // namespace grass::test
