// How long the window at rest waits for input: the soonest change on screen, bounded.
#include "app/idle_wait.h"

#include <gtest/gtest.h>

#include <limits>

namespace grass::editor {
namespace {

TEST(IdleWait, NothingDueWaitsTheLongestWait) {
    RestingFrame frame;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), LONGEST_IDLE_WAIT_S);
    // Changes further off than the bound: the bound.
    frame.panelsChangeInS = 5.0;
    frame.autosaveInS = 30.0;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), LONGEST_IDLE_WAIT_S);
}

TEST(IdleWait, TheSoonestChangeSetsTheWait) {
    RestingFrame frame;
    frame.panelsChangeInS = 0.35;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), 0.35);
    frame.fullPictureInS = 0.2;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), 0.2);
    frame.autosaveInS = 0.05;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), 0.05);
    frame = {};
    frame.autosaveInS = 0.5;
    frame.statusUpdateInS = 0.4;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), 0.4);
}

TEST(IdleWait, ShownProgressKeepsFramesComing) {
    RestingFrame frame;
    frame.progressShown = true;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), PROGRESS_IDLE_WAIT_S);
    frame.panelsChangeInS = 0.02;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), 0.02);
    // Playing a field whose picture stands still: frames keep coming for the physics' steps.
    frame = {};
    frame.playing = true;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), PLAYING_IDLE_WAIT_S);
}

TEST(IdleWait, OverdueChangesAndNaNNeverMakeAWaitOutsideItsBounds) {
    RestingFrame frame;
    frame.fullPictureInS = -0.1;
    EXPECT_DOUBLE_EQ(idleWaitS(frame), 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    frame = {};
    frame.panelsChangeInS = nan;
    frame.statusUpdateInS = nan;
    const double waitS = idleWaitS(frame);
    EXPECT_GE(waitS, 0.0);
    EXPECT_LE(waitS, LONGEST_IDLE_WAIT_S);
}

}  // namespace
}  // namespace grass::editor
