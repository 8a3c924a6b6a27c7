// HSV conversion and the colour edit widget.
#include "ui/color_edit.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "tests/ui/ui_harness.h"

namespace grass::ui {
namespace {

using test::UiHarness;

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(UiColor, KnownHsvValues) {
    expectNear(rgbToHsv({1.0f, 0.0f, 0.0f}), {0.0f, 1.0f, 1.0f}, 1e-6f);
    expectNear(rgbToHsv({0.0f, 1.0f, 0.0f}), {1.0f / 3.0f, 1.0f, 1.0f}, 1e-6f);
    expectNear(rgbToHsv({0.0f, 0.0f, 1.0f}), {2.0f / 3.0f, 1.0f, 1.0f}, 1e-6f);
    expectNear(rgbToHsv({1.0f, 1.0f, 0.0f}), {1.0f / 6.0f, 1.0f, 1.0f}, 1e-6f);
    expectNear(rgbToHsv({1.0f, 0.0f, 1.0f}), {5.0f / 6.0f, 1.0f, 1.0f}, 1e-6f);
    expectNear(rgbToHsv({0.5f, 0.5f, 0.5f}), {0.0f, 0.0f, 0.5f}, 1e-6f);
    expectNear(rgbToHsv({0.0f, 0.0f, 0.0f}), {0.0f, 0.0f, 0.0f}, 1e-6f);
    expectNear(rgbToHsv({0.5f, 0.25f, 0.25f}), {0.0f, 0.5f, 0.5f}, 1e-6f);
    expectNear(hsvToRgb({0.0f, 1.0f, 1.0f}), {1.0f, 0.0f, 0.0f}, 1e-6f);
    expectNear(hsvToRgb({0.5f, 0.5f, 1.0f}), {0.5f, 1.0f, 1.0f}, 1e-6f);
    expectNear(hsvToRgb({2.0f / 3.0f, 1.0f, 0.5f}), {0.0f, 0.0f, 0.5f}, 1e-6f);
    expectNear(hsvToRgb({0.25f, 0.0f, 0.75f}), {0.75f, 0.75f, 0.75f}, 1e-6f);
    // Hue wraps.
    expectNear(hsvToRgb({1.25f, 1.0f, 1.0f}), hsvToRgb({0.25f, 1.0f, 1.0f}), 1e-6f);
}

TEST(UiColor, RgbHsvRoundTripWithin1em5) {
    const std::uint32_t seed = 1234;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int i = 0; i < 10000; ++i) {
        const glm::vec3 rgb{unit(rng), unit(rng), unit(rng)};
        const glm::vec3 hsv = rgbToHsv(rgb);
        ASSERT_GE(hsv.x, 0.0f);
        ASSERT_LT(hsv.x, 1.0f);
        const glm::vec3 back = hsvToRgb(hsv);
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(back[c], rgb[c], 1e-5f) << "seed " << seed << " sample " << i;
        }
        // And the other way, where the hue is defined (saturated, not black).
        const glm::vec3 hsv2{unit(rng), 0.05f + 0.95f * unit(rng), 0.05f + 0.95f * unit(rng)};
        const glm::vec3 again = rgbToHsv(hsvToRgb(hsv2));
        const float dh = std::abs(again.x - hsv2.x);
        ASSERT_LT(std::min(dh, 1.0f - dh), 1e-5f) << "seed " << seed << " sample " << i;
        ASSERT_NEAR(again.y, hsv2.y, 1e-5f);
        ASSERT_NEAR(again.z, hsv2.z, 1e-5f);
    }
}

TEST(UiColor, DraggingTheSquareSetsSaturationAndValueAtTheHue) {
    UiHarness h;
    glm::vec3 rgb{0.2f, 0.2f, 0.8f};  // hue 2/3 (blue)
    Response r;
    const auto build = [&](Ui& ui) { r = colorPicker(ui, "pick", rgb); };
    h.frame(build);
    const Vec2 topLeft = h.panel.min;
    // Top-right corner: full saturation and value.
    h.moveTo(topLeft + Vec2(COLOR_PICKER_SIZE * 0.5f));
    h.frame(build);
    h.press();
    h.frame(build);
    h.moveTo(topLeft + Vec2(COLOR_PICKER_SIZE + 30.0f, -30.0f));
    h.frame(build);
    EXPECT_TRUE(r.changed());
    expectNear(rgb, {0.0f, 0.0f, 1.0f}, 1e-5f);
    // Through black (bottom edge) and back: the hue is remembered.
    h.moveTo(topLeft + Vec2(COLOR_PICKER_SIZE, COLOR_PICKER_SIZE + 20.0f));
    h.frame(build);
    expectNear(rgb, {0.0f, 0.0f, 0.0f}, 1e-5f);
    h.moveTo(topLeft + Vec2(COLOR_PICKER_SIZE, 0.0f));
    h.frame(build);
    expectNear(rgb, {0.0f, 0.0f, 1.0f}, 1e-5f);
    h.release();
    h.frame(build);

    // The hue bar: its middle is hue 0.5 (cyan).
    const Vec2 bar =
        topLeft + Vec2(COLOR_PICKER_SIZE + h.ctx.style().itemSpacing.x + 0.5f * COLOR_HUE_BAR_WIDTH,
                       0.5f * COLOR_PICKER_SIZE);
    h.clickAt(bar, build);
    expectNear(rgb, {0.0f, 1.0f, 1.0f}, 1e-5f);
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
}

TEST(UiColor, SwatchOpensAndEscapeClosesThePicker) {
    UiHarness h;
    glm::vec3 rgb{0.5f, 0.1f, 0.1f};
    Response r;
    const auto build = [&](Ui& ui) { r = colorEdit(ui, "Tip colour", rgb); };
    h.frame(build);
    EXPECT_FALSE(test::findText(h.ctx.output(), "R").has_value());
    h.clickAt(r.rect().centre(), build);
    h.frame(build);
    EXPECT_TRUE(test::findText(h.ctx.output(), "R").has_value()) << "popup open";
    EXPECT_TRUE(test::findText(h.ctx.output(), "V").has_value());
    EXPECT_EQ(h.ctx.duplicateIdCount(), 0);
    h.input.keys.push_back({Key::Escape, {}});
    h.frame(build);
    h.frame(build);
    EXPECT_FALSE(test::findText(h.ctx.output(), "R").has_value()) << "closed";
    EXPECT_FALSE(r.changed());
}

}  // namespace
}  // namespace grass::ui
