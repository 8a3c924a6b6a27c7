// A whole UI panel through the whole pipeline (issue 7): widgets laid out by ui::Context and
// ui::Ui, tessellated, drawn by gl::UiRenderer into 320×300 and compared with
// tests/data/golden/ui-panel.png. It catches what the shapes-only golden (ui_renderer_gl_test)
// cannot: layout, widget visuals, the theme.
// Metric and tolerances are those of ui_renderer_gl_test.cpp (a pixel differs beyond 32 levels;
// 0.5 % of the pixels may, mean ≤ 1 level), for the same reasons: stb_truetype's coverage is
// exact, only llvmpipe's code for another CPU may move alpha inside one-pixel feather bands.
// Refresh: GRASS_UPDATE_GOLDEN=1 grass_gl_tests --gtest_filter='UiPanel*', then look at it.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <string>

#include "gl/framebuffer.h"
#include "gl_context_fixture.h"
#include "support/golden_file.h"
#include "support/image_compare.h"
#include "support/test_fonts.h"
#include "support/test_paths.h"
#include "ui/color_edit.h"
#include "ui/context.h"
#include "ui/curve_edit.h"
#include "ui/tessellator.h"
#include "ui/text_edit.h"
#include "ui/ui.h"
#include "gl/ui_renderer.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

constexpr int WIDTH = 320;
constexpr int HEIGHT = 300;
constexpr int PIXEL_THRESHOLD = 32;
constexpr double MAX_DIFFERING_SHARE = 0.005;
constexpr double MAX_MEAN_ABS = 1.0;

using UiPanelTest = GlTest;

// A layer's settings as the editor's side panel shows them (fixed values, no input).
struct PanelValues {
    std::string name = "meadow grass";
    bool growth = true;
    float density = 144.0f;
    float height = 0.45f;
    int shape = 1;
    glm::vec3 tip{0.5f, 0.72f, 0.22f};
    std::array<float, 3> soil{0.1f, 0.6f, 1.0f};
};

std::vector<ui::Mesh> buildPanel(ui::Context& ctx, PanelValues& values) {
    ui::Input input;
    input.screenRect = {{0.0f, 0.0f}, {float(WIDTH), float(HEIGHT)}};
    input.pixelsPerPoint = 1.0f;
    input.hasPointer = false;
    // Two frames: grids and collapsing headers settle their sizes from the previous frame.
    for (int frame = 0; frame < 2; ++frame) {
        ctx.beginFrame(input);
        ui::Painter background = ctx.painter(ui::Layer::Background, input.screenRect);
        background.rect(input.screenRect, 0.0f, ctx.style().panelFill);
        ui::Ui ui(ctx, input.screenRect.expand(-8.0f));
        ui.label("Layer");
        ui::textEdit(ui, "name", values.name, 180.0f);
        ui.checkbox(values.growth, "growth from soil and light");
        ui.slider("density", values.density, 0.0f, 500.0f);
        ui.dragValue("height", values.height, 0.01f, 0.01f, 2.0f, 2);
        ui.comboBox("shape", values.shape,
                    std::vector<std::string>{"quad", "triangle", "quadratic"});
        ui::colorEdit(ui, "tip colour", values.tip);
        ui::bezierCurveEdit(ui, "soil curve", values.soil, {180.0f, 50.0f});
        ui.progressBar(0.6f, "re-growing 60 %");
        ctx.endFrame();
    }
    return ui::tessellate(ctx.output().shapes, testFonts(), 1.0f);
}

gl::Rgba8Image render(const std::vector<ui::Mesh>& meshes) {
    auto renderer = gl::UiRenderer::create();
    EXPECT_TRUE(renderer.ok()) << renderer.error().str();
    gl::Framebuffer framebuffer(WIDTH, HEIGHT, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, WIDTH, HEIGHT);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (renderer.ok())
        renderer->draw(meshes, testFonts(), {WIDTH, HEIGHT}, 1.0f);
    return framebuffer.readPixels();
}

TEST_F(UiPanelTest, LayerPanelMatchesGolden) {
    ui::Context ctx(testFonts());
    PanelValues values;
    const std::vector<ui::Mesh> meshes = buildPanel(ctx, values);
    ASSERT_FALSE(meshes.empty());
    const gl::Rgba8Image image = render(meshes);
    ASSERT_EQ(image.pixels.size(), std::size_t(WIDTH) * HEIGHT * 4);
    expectMatchesGolden("ui-panel", image, {PIXEL_THRESHOLD, MAX_DIFFERING_SHARE, MAX_MEAN_ABS});
}

// The metric sees a change a user would see: the same panel with the checkbox off and another
// density fails it.
TEST_F(UiPanelTest, ChangedValuesFailTheGolden) {
    ui::Context ctx(testFonts());
    PanelValues values;
    values.growth = false;
    values.density = 400.0f;
    const gl::Rgba8Image image = render(buildPanel(ctx, values));
    auto reference = readRgba8Image(sourceDir() / "tests/data/golden/ui-panel.png");
    ASSERT_TRUE(reference.ok()) << reference.error().str();
    const ImageDifference diff = compareImages(image.pixels, reference->pixels, PIXEL_THRESHOLD);
    EXPECT_GT(diff.differingShare, MAX_DIFFERING_SHARE);
}

}  // namespace
}  // namespace grass::test
