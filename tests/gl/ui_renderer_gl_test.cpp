// The UI's GL backend (editor/gl/ui_renderer.h): a fixed panel of shapes tessellated by
// ui::tessellate and drawn into a 160×100 RGBA8 target without MSAA (the feathering does the
// anti-aliasing), compared with tests/data/golden/ui-shapes.png; text really lands where it was
// placed; the scissor follows the clip rects; a grown font atlas is re-uploaded.
//
// Golden metric (tests/support/image_compare.h): a pixel differs when a channel moved by more
// than PIXEL_THRESHOLD levels; the case fails when more than MAX_DIFFERING_SHARE of the pixels
// differ or the mean absolute difference exceeds MAX_MEAN_ABS.
// Why these numbers: the reference comes from Mesa llvmpipe, which is deterministic for one
// build; glyph coverage comes from stb_truetype on the CPU and is exact. What may vary between
// machines is llvmpipe's LLVM code (FMA contraction, vector width), which moves interpolated
// alpha inside a one-pixel feather band by a few levels and can flip which of two triangles
// owns an edge pixel; with no MSAA and feathered edges that changes a pixel by at most the
// step of the feather ramp over a pixel (~1/2 of the edge contrast on a diagonal, ~25 levels
// here). So a pixel differs only beyond 32 levels, and 0.5 % of the pixels (80) may do so; the
// mean stays under 1 level. A real regression (no premultiplication, wrong blend function,
// missing scissor, text at the wrong place) changes whole shapes: RegressionIsCaught checks the
// metric sees a one-pixel shift of everything.
// Refresh after an intended change: GRASS_UPDATE_GOLDEN=1 grass_gl_tests
// --gtest_filter='UiRenderer*' and look at the image before committing it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "gl/framebuffer.h"
#include "gl_context_fixture.h"
#include "support/image_compare.h"
#include "support/test_fonts.h"
#include "support/test_paths.h"
#include "ui/tessellator.h"
#include "gl/ui_renderer.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

constexpr int WIDTH = 160;
constexpr int HEIGHT = 100;
constexpr int PIXEL_THRESHOLD = 32;
constexpr double MAX_DIFFERING_SHARE = 0.005;
constexpr double MAX_MEAN_ABS = 1.0;

const ui::Color32 BACKGROUND = ui::Color32::rgb(20, 22, 26);
const ui::Color32 PANEL = ui::Color32::rgb(46, 50, 58);
const ui::Rect TITLE_AT = ui::Rect::fromMinSize({12.0f, 10.0f}, {0.0f, 0.0f});
const ui::Rect CLIP_PROBE = ui::Rect::fromMinSize({138.0f, 84.0f}, {10.0f, 8.0f});

using UiRendererTest = GlTest;

// The panel every case draws: what widgets paint most (rounded frames, text in two sizes, a
// circle, a polyline, a checkbox with its tick), plus a shape clipped to a small rect.
std::vector<ui::ClippedShape> panelShapes(ui::Vec2 shift = ui::Vec2(0.0f)) {
    const ui::Rect all{{0.0f, 0.0f}, {float(WIDTH), float(HEIGHT)}};
    const auto at = [shift](float x, float y) { return ui::Vec2(x, y) + shift; };
    const auto box = [&](float x, float y, float w, float h) {
        return ui::Rect::fromMinSize(at(x, y), {w, h});
    };
    const ui::Stroke frame{1.0f, ui::Color32::rgb(90, 96, 110)};
    ui::PathShape curve;
    curve.points = {at(12, 84), at(36, 62), at(62, 80), at(92, 60)};
    curve.stroke = {2.0f, ui::Color32::rgb(240, 196, 72)};
    ui::PathShape tick;
    tick.points = {at(113, 70), at(117, 74), at(124, 65)};
    tick.stroke = {2.0f, ui::Color32::rgb(235, 235, 235)};
    return {
        {all, ui::RectShape{box(4, 4, 152, 92), 6.0f, PANEL, frame}},
        {all,
         ui::TextShape{TITLE_AT.min + shift, "Grass UI", 16.0f, ui::Color32::rgb(235, 235, 235)}},
        {all, ui::TextShape{at(12, 32), "density 120/m\xC2\xB2", 11.0f,
                            ui::Color32::rgb(170, 176, 188)}},
        {all, ui::CircleShape{at(130, 28), 14.0f, ui::Color32::rgb(86, 168, 92),
                              ui::Stroke{1.5f, ui::Color32::rgb(200, 230, 200)}}},
        {all, curve},
        {all, ui::RectShape{box(110, 62, 16, 16), 3.0f, ui::Color32::rgb(64, 110, 200), frame}},
        {all, tick},
        // Half-transparent overlay: premultiplied blending shows in the mix.
        {all, ui::RectShape{box(100, 40, 50, 14), 2.0f, ui::Color32{255, 80, 80, 128}, {}}},
        // A large shape that only its clip rect keeps small: the scissor must cut it.
        {CLIP_PROBE, ui::CircleShape{at(143, 88), 40.0f, ui::Color32::rgb(255, 0, 255), {}}},
    };
}

gl::Rgba8Image render(const std::vector<ui::ClippedShape>& shapes, gl::UiRenderer& renderer,
                      const ui::FontAtlas& atlas = testFonts(), float ppp = 1.0f) {
    const int width = int(std::lround(float(WIDTH) * ppp));
    const int height = int(std::lround(float(HEIGHT) * ppp));
    gl::Framebuffer target(width, height, 1);
    target.bind();
    glClearColor(float(BACKGROUND.r) / 255.0f, float(BACKGROUND.g) / 255.0f,
                 float(BACKGROUND.b) / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const std::vector<ui::Mesh> meshes = ui::tessellate(shapes, atlas, ppp);
    renderer.draw(meshes, atlas, {width, height}, ppp);
    return target.readPixels();
}

gl::UiRenderer makeRenderer() {
    auto renderer = gl::UiRenderer::create();
    if (!renderer) {
        ADD_FAILURE() << renderer.error().str();
        std::abort();
    }
    return std::move(*renderer);
}

const std::uint8_t* pixel(const gl::Rgba8Image& image, int x, int y) {
    return &image.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
}

// Pixels in `rect` (points = pixels here) brighter than the panel by a clear margin.
int brightPixels(const gl::Rgba8Image& image, const ui::Rect& rect) {
    int count = 0;
    for (int y = int(rect.min.y); y < int(rect.max.y); ++y)
        for (int x = int(rect.min.x); x < int(rect.max.x); ++x)
            if (pixel(image, x, y)[0] > PANEL.r + 80)
                ++count;
    return count;
}

std::filesystem::path goldenFile() {
    return sourceDir() / "tests/data/golden/ui-shapes.png";
}

TEST_F(UiRendererTest, PanelMatchesGolden) {
    gl::UiRenderer renderer = makeRenderer();
    const gl::Rgba8Image image = render(panelShapes(), renderer);
    ASSERT_EQ(image.pixels.size(), std::size_t(WIDTH) * HEIGHT * 4);
    EXPECT_GE(renderer.drawCalls(), 2u);
    const char* update = std::getenv("GRASS_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        ASSERT_TRUE(writeRgba8Image(goldenFile(), WIDTH, HEIGHT, image.pixels).ok());
        return;
    }
    auto reference = readRgba8Image(goldenFile());
    ASSERT_TRUE(reference.ok()) << reference.error().str()
                                << " (GRASS_UPDATE_GOLDEN=1 writes the reference)";
    const ImageDifference diff = compareImages(image.pixels, reference->pixels, PIXEL_THRESHOLD);
    std::printf("[ golden ] ui-shapes differing %.4f, mean abs %.3f, max %d\n", diff.differingShare,
                diff.meanAbs, diff.maxChannel);
    if (diff.differingShare > MAX_DIFFERING_SHARE || diff.meanAbs > MAX_MEAN_ABS) {
        const auto actual = scratchDir("ui-golden") / "ui-shapes.actual.png";
        EXPECT_TRUE(writeRgba8Image(actual, WIDTH, HEIGHT, image.pixels).ok());
        ADD_FAILURE() << "differs from " << goldenFile() << ": share " << diff.differingShare
                      << ", mean " << diff.meanAbs << "; this render is in " << actual;
    }
}

// The metric notices the panel drawn one pixel off.
TEST_F(UiRendererTest, RegressionIsCaught) {
    gl::UiRenderer renderer = makeRenderer();
    auto reference = readRgba8Image(goldenFile());
    ASSERT_TRUE(reference.ok()) << reference.error().str();
    const gl::Rgba8Image shifted = render(panelShapes({1.0f, 1.0f}), renderer);
    const ImageDifference diff = compareImages(shifted.pixels, reference->pixels, PIXEL_THRESHOLD);
    std::printf("[ golden ] shifted panel vs ui-shapes: differing %.4f, mean abs %.3f\n",
                diff.differingShare, diff.meanAbs);
    EXPECT_TRUE(diff.differingShare > 2.0 * MAX_DIFFERING_SHARE ||
                diff.meanAbs > 2.0 * MAX_MEAN_ABS);
}

TEST_F(UiRendererTest, TextPixelsAppearWhereTextWasPlaced) {
    gl::UiRenderer renderer = makeRenderer();
    const gl::Rgba8Image image = render(panelShapes(), renderer);
    const ui::Vec2 size = testFonts().textSize("Grass UI", 16.0f);
    const ui::Rect title = ui::Rect::fromMinSize(TITLE_AT.min, size);
    const int inside = brightPixels(image, title);
    // Light glyph strokes cover roughly a tenth to a quarter of a line's box.
    EXPECT_GT(inside, int(0.08f * size.x * size.y)) << "title box " << size.x << "x" << size.y;
    // ... and far from all of it: a glyph quad drawn as a solid box (coverage not applied to
    // the colour) would light most of the box.
    EXPECT_LT(inside, int(0.4f * size.x * size.y));
    // Between the title and the small line, and right of the title: no text.
    EXPECT_EQ(
        brightPixels(image, ui::Rect::fromMinSize({title.max.x + 2.0f, 10.0f}, {10.0f, size.y})),
        0);
    const ui::Rect small =
        ui::Rect::fromMinSize({12.0f, 32.0f}, testFonts().textSize("density 120/m\xC2\xB2", 11.0f));
    EXPECT_GT(brightPixels(image, small), 0);
}

TEST_F(UiRendererTest, ScissorCutsShapesToTheirClip) {
    gl::UiRenderer renderer = makeRenderer();
    const gl::Rgba8Image image = render(panelShapes(), renderer);
    const auto isMagenta = [&](int x, int y) {
        const std::uint8_t* p = pixel(image, x, y);
        return p[0] > 240 && p[1] < 20 && p[2] > 240;
    };
    // Inside the clip: the circle; just outside (its radius reaches far beyond): not.
    EXPECT_TRUE(isMagenta(int(CLIP_PROBE.min.x) + 1, int(CLIP_PROBE.min.y) + 1));
    EXPECT_TRUE(isMagenta(int(CLIP_PROBE.max.x) - 1, int(CLIP_PROBE.max.y) - 1));
    EXPECT_FALSE(isMagenta(int(CLIP_PROBE.min.x) - 1, int(CLIP_PROBE.min.y) + 2));
    EXPECT_FALSE(isMagenta(int(CLIP_PROBE.max.x), int(CLIP_PROBE.min.y) + 2));
    EXPECT_FALSE(isMagenta(int(CLIP_PROBE.min.x) + 2, int(CLIP_PROBE.min.y) - 1));
    EXPECT_FALSE(isMagenta(int(CLIP_PROBE.min.x) + 2, int(CLIP_PROBE.max.y)));
}

// HiDPI: at 2 pixels per point everything doubles in pixels (the scissor too, with GL's
// bottom-left origin), and the text, rasterised at 2×, still lands in its doubled box.
TEST_F(UiRendererTest, TwoPixelsPerPointDoublesGeometryAndScissor) {
    gl::UiRenderer renderer = makeRenderer();
    std::string error;
    auto hiDpi = ui::FontAtlas::load(ui::FontAtlas::defaultFontPath(), &error);
    ASSERT_TRUE(hiDpi.has_value()) << error;
    hiDpi->setPixelsPerPoint(2.0f);
    const gl::Rgba8Image image = render(panelShapes(), renderer, *hiDpi, 2.0f);
    ASSERT_EQ(image.width, 2 * WIDTH);
    const auto isMagenta = [&](int x, int y) {
        const std::uint8_t* p = pixel(image, x, y);
        return p[0] > 240 && p[1] < 20 && p[2] > 240;
    };
    const ui::Rect probePx{2.0f * CLIP_PROBE.min, 2.0f * CLIP_PROBE.max};
    EXPECT_TRUE(isMagenta(int(probePx.min.x), int(probePx.min.y)));
    EXPECT_TRUE(isMagenta(int(probePx.max.x) - 1, int(probePx.max.y) - 1));
    EXPECT_FALSE(isMagenta(int(probePx.min.x) - 1, int(probePx.min.y) + 4));
    EXPECT_FALSE(isMagenta(int(probePx.min.x) + 4, int(probePx.max.y)));
    const ui::Vec2 size = hiDpi->textSize("Grass UI", 16.0f);
    const ui::Rect titlePx{2.0f * TITLE_AT.min, 2.0f * (TITLE_AT.min + size)};
    const int inside = brightPixels(image, titlePx);
    const float areaPx = titlePx.width() * titlePx.height();
    EXPECT_GT(inside, int(0.08f * areaPx));
    EXPECT_LT(inside, int(0.4f * areaPx));
}

// Glyphs first used after an upload grow the atlas version; the next draw must re-upload, or
// the new glyphs would sample empty texels.
TEST_F(UiRendererTest, NewGlyphsAreUploadedBeforeDrawing) {
    gl::UiRenderer renderer = makeRenderer();
    render({{{{0, 0}, {float(WIDTH), float(HEIGHT)}}, ui::TextShape{{4, 4}, "a", 12.0f}}},
           renderer);
    // A size never used before in this process: rasterised on this tessellation.
    const ui::Rect where = ui::Rect::fromMinSize({20.0f, 20.0f}, {60.0f, 60.0f});
    const gl::Rgba8Image image =
        render({{{{0, 0}, {float(WIDTH), float(HEIGHT)}}, ui::TextShape{where.min, "W", 47.25f}}},
               renderer);
    EXPECT_GT(brightPixels(image, where), 200);
}

// A user texture (a map image) shows through an ImageShape; unknown ids are skipped.
TEST_F(UiRendererTest, RegisteredImageIsDrawnAndUnknownSkipped) {
    gl::UiRenderer renderer = makeRenderer();
    gl::Rgba8Image checker{
        2, 2, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}};
    renderer.registerTexture(ui::TextureId{3}, checker);
    const ui::Rect all{{0, 0}, {float(WIDTH), float(HEIGHT)}};
    const gl::Rgba8Image image =
        render({{all, ui::ImageShape{ui::Rect::fromMinSize({0, 0}, {80, 80}), ui::TextureId{3}}},
                {all, ui::ImageShape{ui::Rect::fromMinSize({80, 0}, {80, 80}), ui::TextureId{9}}}},
               renderer);
    EXPECT_EQ(renderer.skippedMeshes(), 1u);
    // Top-left texel red, top-right green (row 0 of the image is the top).
    EXPECT_GT(pixel(image, 5, 5)[0], 200);
    EXPECT_GT(pixel(image, 75, 5)[1], 200);
    EXPECT_GT(pixel(image, 5, 75)[2], 200);
    EXPECT_EQ(pixel(image, 120, 40)[0], BACKGROUND.r);
}

}  // namespace
}  // namespace grass::test
