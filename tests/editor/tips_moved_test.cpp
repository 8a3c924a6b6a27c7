// While the timeline plays, the CPU physics' blades go up to the renderer (and the picture is
// drawn again) only when a tip moved by more than STILL_TIP_SHARE of its blade's height since the
// last upload (app/live_scene.h tipsMoved): a field that nothing moves stands still on screen.
#include "app/live_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "blade/blade.h"

namespace grass::editor {
namespace {

std::vector<core::Blade> twoBlades() {
    return {core::makeRestBlade({0, 0, 0}, {0, 1, 0}, 0.5f, 0.01f, 40.0f, 0.0f),
            core::makeRestBlade({1, 0, 0}, {0, 1, 0}, 2.0f, 0.01f, 40.0f, 0.0f)};
}

TEST(TipsMoved, TheFirstLookAndAChangedCountAreMoves) {
    std::vector<core::Blade> blades = twoBlades();
    std::vector<glm::vec3> shown;
    EXPECT_TRUE(tipsMoved(blades, shown));
    ASSERT_EQ(shown.size(), 2u);
    EXPECT_EQ(shown[1], blades[1].v2());
    EXPECT_FALSE(tipsMoved(blades, shown));
    blades.pop_back();
    EXPECT_TRUE(tipsMoved(blades, shown));
    EXPECT_EQ(shown.size(), 1u);
}

TEST(TipsMoved, AMoveIsMeasuredAgainstTheBladesHeightAndTheLastUpload) {
    std::vector<core::Blade> blades = twoBlades();
    std::vector<glm::vec3> shown;
    tipsMoved(blades, shown);
    // The 2 m blade's tip moves by 0.9 of the share of its height: still. Again by the same:
    // 1.8 of the share from the upload, which is what is on screen: moved.
    const float step = 0.9f * STILL_TIP_SHARE * 2.0f;
    blades[1].v2W.x += step;
    EXPECT_FALSE(tipsMoved(blades, shown));
    blades[1].v2W.x += step;
    EXPECT_TRUE(tipsMoved(blades, shown));
    EXPECT_FLOAT_EQ(shown[1].x, blades[1].v2W.x);
    // The same move on the 0.5 m blade is more than its share.
    blades[0].v2W.z += step;
    EXPECT_TRUE(tipsMoved(blades, shown));
}

TEST(TipsMoved, ANaNTipIsAMove) {
    std::vector<core::Blade> blades = twoBlades();
    std::vector<glm::vec3> shown;
    tipsMoved(blades, shown);
    blades[0].v2W.y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(tipsMoved(blades, shown));
}

}  // namespace
}  // namespace grass::editor

namespace grass::editor {
namespace {

// A crushed blade a collider keeps pressing (η rising, or falling by less than half the frame's
// decay) lets the field rest; one whose η fell by the decay (nothing presses it: it will rise)
// does not; η 0 is no crush at all; a NaN η or nothing to compare with counts as recovering.
TEST(AnyRecovering, OnlyABladeWhoseCrushDecaysUnpressedKeepsTheFieldAwake) {
    const float decay = 0.5f / 60.0f;  // one step of the default decay
    const std::vector<float> before{0.0f, 3.0f, 40.0f};
    EXPECT_FALSE(anyRecovering(std::vector<float>{0.0f, 3.2f, 40.0f}, before, decay)) << "pressed";
    EXPECT_FALSE(anyRecovering(std::vector<float>{0.0f, 3.0f - 0.4f * decay, 40.0f}, before, decay))
        << "pressed a little less than it decays";
    EXPECT_TRUE(anyRecovering(std::vector<float>{0.0f, 3.0f - decay, 40.0f}, before, decay))
        << "decaying freely";
    EXPECT_FALSE(anyRecovering(std::vector<float>{0.0f, 0.0f, 40.0f}, before, decay))
        << "recovered: η 0";
    EXPECT_TRUE(anyRecovering(std::vector<float>{0.0f, 3.0f, std::nanf("")}, before, decay));
    EXPECT_TRUE(anyRecovering(std::vector<float>{3.0f}, {}, decay)) << "nothing to compare with";
    EXPECT_FALSE(anyRecovering(std::vector<float>{0.0f}, {}, decay)) << "nothing crushed";
}

}  // namespace
}  // namespace grass::editor
