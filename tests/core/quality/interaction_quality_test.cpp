// The viewport's adaptive quality (issue 24): reduce while the user interacts and a frame is over
// budget, refine once input stops, and never reduce when the budget is met.
#include "quality/interaction_quality.h"

#include <gtest/gtest.h>

namespace grass::core {
namespace {

TEST(InteractionQuality, AGenerousBudgetLowersNothing) {
    InteractionQuality quality({.enabled = true, .budgetMs = 5000.0, .settleS = 0.3});
    for (int frame = 0; frame < 50; ++frame)
        EXPECT_EQ(quality.update(900.0, true, 0.1 * frame), 0) << "frame " << frame;
}

TEST(InteractionQuality, ASlowFrameClimbsToTheBudgetInOneStep) {
    InteractionQuality quality({.enabled = true, .budgetMs = 80.0, .settleS = 0.3});
    // A full frame of 944 ms: each rung is expected to halve it, 944 / 2^4 = 59 ms fits.
    EXPECT_EQ(quality.update(944.0, true, 0.0), 4);
    EXPECT_EQ(quality.reduction().keepEvery, 8);
    EXPECT_TRUE(quality.reduction().msaaOff);
    // Measured within the budget: stays.
    EXPECT_EQ(quality.update(60.0, true, 0.1), 4);
    // Measured far under it: the rung above is expected at twice as much, 2 × 40 = 80: fits.
    EXPECT_EQ(quality.update(20.0, true, 0.2), 3);
    // That rung turns out far over budget: back to the one measured within it, not beyond.
    EXPECT_EQ(quality.update(500.0, true, 0.3), 4);
    EXPECT_EQ(quality.update(60.0, true, 0.4), 4) << "no oscillation: rung 3 is known too slow";
    // Every rung over budget: the last one.
    InteractionQuality slow({.enabled = true, .budgetMs = 80.0, .settleS = 0.3});
    EXPECT_EQ(slow.update(1e6, true, 0.0), int(REDUCTION_LADDER.size()) - 1);
}

TEST(InteractionQuality, InputThatStopsGivesTheFullPictureAfterTheSettleTime) {
    InteractionQuality quality({.enabled = true, .budgetMs = 80.0, .settleS = 0.3});
    quality.update(700.0, true, 10.0);
    ASSERT_GT(quality.level(), 0);
    // A window at rest wakes for the full picture when it is due.
    ASSERT_TRUE(quality.fullPictureAtS().has_value());
    EXPECT_DOUBLE_EQ(*quality.fullPictureAtS(), 10.3);
    EXPECT_GT(quality.update(50.0, false, 10.2), 0) << "0.2 s after the last input: still moving";
    EXPECT_DOUBLE_EQ(*quality.fullPictureAtS(), 10.3);
    EXPECT_EQ(quality.update(50.0, false, 10.31), 0);
    EXPECT_FALSE(quality.fullPictureAtS().has_value()) << "at full quality nothing is due";
    EXPECT_EQ(quality.reduction().label, REDUCTION_LADDER[0].label);
    // A frame at full quality is the project's own: nothing reduced.
    EXPECT_FALSE(REDUCTION_LADDER[0].msaaOff);
    EXPECT_EQ(REDUCTION_LADDER[0].keepEvery, 1);
    EXPECT_EQ(REDUCTION_LADDER[0].lodDistanceScale, 1.0f);
    EXPECT_EQ(REDUCTION_LADDER[0].resolutionScale, 1.0f);
}

// A frame that showed the last picture again (the editor at rest, editor/app/view_redraw.h)
// took a few milliseconds: that is not what the full picture costs. Its measurement stays as it
// was and trusted however long the rest lasts, so the first move after it reduces at once, as
// it would after frames that drew; without such frames a measurement is forgotten after 3 s.
TEST(InteractionQuality, FramesThatDrewNothingKeepTheMeasuredCost) {
    InteractionQuality quality({.enabled = true, .budgetMs = 80.0, .settleS = 0.3});
    EXPECT_EQ(quality.update(400.0, false, 0.0), 0);  // a full frame of 400 ms
    for (int frame = 1; frame <= 100; ++frame)
        EXPECT_EQ(quality.update(5.0, false, 0.1 * frame, false), 0);
    EXPECT_GT(quality.update(5.0, true, 10.1, false), 0)
        << "the full picture still costs 400 ms: the first orbit frame is reduced";
    // The same frames counted as drawn: the cheap frames would say the full picture fits.
    InteractionQuality counted({.enabled = true, .budgetMs = 80.0, .settleS = 0.3});
    counted.update(400.0, false, 0.0);
    for (int frame = 1; frame <= 100; ++frame)
        counted.update(5.0, false, 0.1 * frame);
    EXPECT_EQ(counted.update(5.0, true, 10.1), 0);
    // A measurement already forgotten (3 s without frames) is not brought back by them.
    InteractionQuality forgotten({.enabled = true, .budgetMs = 80.0, .settleS = 0.3});
    forgotten.update(400.0, false, 0.0);
    forgotten.update(5.0, false, 3.5, false);
    EXPECT_EQ(forgotten.update(5.0, true, 3.6, false), 0) << "nothing known: assumed to fit";
}

TEST(InteractionQuality, TurnedOffItNeverReduces) {
    InteractionQuality quality({.enabled = false, .budgetMs = 80.0, .settleS = 0.3});
    EXPECT_EQ(quality.update(5000.0, true, 0.0), 0);
}

// Each rung costs no more than the one before: a higher level never draws more.
TEST(InteractionQuality, EveryRungReducesAtLeastAsMuchAsTheOneBefore) {
    for (std::size_t i = 1; i < REDUCTION_LADDER.size(); ++i) {
        const Reduction& a = REDUCTION_LADDER[i - 1];
        const Reduction& b = REDUCTION_LADDER[i];
        EXPECT_TRUE(b.msaaOff || !a.msaaOff);
        EXPECT_GE(b.keepEvery, a.keepEvery);
        EXPECT_LE(b.lodDistanceScale, a.lodDistanceScale);
        EXPECT_LE(b.resolutionScale, a.resolutionScale);
    }
}

}  // namespace
}  // namespace grass::core
