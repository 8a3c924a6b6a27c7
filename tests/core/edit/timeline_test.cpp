#include "edit/timeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "util/rng.h"

namespace grass::core {
namespace {

constexpr double NAN_S = std::numeric_limits<double>::quiet_NaN();
constexpr double INF_S = std::numeric_limits<double>::infinity();

TEST(Timeline, DefaultsArePausedAtZeroOverTenSeconds) {
    const Timeline timeline;
    EXPECT_EQ(timeline.startS(), 0.0);
    EXPECT_EQ(timeline.endS(), 10.0);
    EXPECT_EQ(timeline.timeS(), 0.0);
    EXPECT_EQ(timeline.speed(), 1.0);
    EXPECT_FALSE(timeline.playing());
    EXPECT_FALSE(timeline.looping());
}

TEST(Timeline, PausedTimeDoesNotMove) {
    Timeline timeline(0.0, 10.0, 0.02);
    EXPECT_EQ(timeline.advance(0.5).change, TimeChange::None);
    EXPECT_EQ(timeline.timeS(), 0.0);
}

TEST(Timeline, PlayingAdvancesByElapsedTimesSpeedContinuously) {
    Timeline timeline(0.0, 10.0, 0.02);
    timeline.play();
    TimeUpdate update = timeline.advance(0.5);
    EXPECT_EQ(update, (TimeUpdate{TimeChange::Continuous, 0.0, 0.5}));
    EXPECT_FALSE(update.needsReset());
    ASSERT_TRUE(timeline.setSpeed(4.0));
    update = timeline.advance(0.25);
    EXPECT_EQ(update.change, TimeChange::Continuous);
    EXPECT_DOUBLE_EQ(timeline.timeS(), 1.5);
    timeline.pause();
    EXPECT_EQ(timeline.advance(1.0).change, TimeChange::None);
    EXPECT_DOUBLE_EQ(timeline.timeS(), 1.5);
}

TEST(Timeline, ToggleSwitchesBetweenPlayAndPause) {
    Timeline timeline;
    timeline.toggle();
    EXPECT_TRUE(timeline.playing());
    timeline.toggle();
    EXPECT_FALSE(timeline.playing());
}

TEST(Timeline, WithoutLoopItStopsAndPausesAtTheEnd) {
    Timeline timeline(0.0, 2.0, 0.02);
    timeline.play();
    const TimeUpdate update = timeline.advance(5.0);
    EXPECT_EQ(update, (TimeUpdate{TimeChange::Continuous, 0.0, 2.0}));
    EXPECT_EQ(timeline.timeS(), 2.0);
    EXPECT_FALSE(timeline.playing());
}

TEST(Timeline, PlayAtTheEndStartsOverFromTheStart) {
    Timeline timeline(1.0, 2.0, 0.02);
    timeline.scrub(2.0);
    const TimeUpdate update = timeline.play();
    EXPECT_TRUE(update.needsReset());
    EXPECT_EQ(timeline.timeS(), 1.0);
    EXPECT_TRUE(timeline.playing());
}

TEST(Timeline, LoopWrapsToTheStartAndAsksForAReset) {
    Timeline timeline(1.0, 3.0, 0.02);
    timeline.setLoop(true);
    timeline.play();
    timeline.advance(1.5);  // at 2.5
    const TimeUpdate update = timeline.advance(1.0);
    EXPECT_EQ(update.change, TimeChange::JumpBack);
    EXPECT_TRUE(update.needsReset());
    EXPECT_NEAR(timeline.timeS(), 1.5, 1e-12);
    EXPECT_TRUE(timeline.playing());
}

// More than a lap at once can land later in the range than it started: still a new lap, so
// the simulated state is not the past of the new time.
TEST(Timeline, AWrapLandingAheadStillAsksForAReset) {
    Timeline timeline(0.0, 3.0, 0.02);
    timeline.setLoop(true);
    timeline.play();
    timeline.advance(1.0);
    const TimeUpdate update = timeline.advance(4.5);
    EXPECT_NEAR(timeline.timeS(), 2.5, 1e-12);
    EXPECT_TRUE(update.needsReset());
}

TEST(Timeline, ReachingTheEndExactlyDoesNotWrap) {
    Timeline timeline(0.0, 2.0, 0.5);
    timeline.setLoop(true);
    timeline.play();
    EXPECT_EQ(timeline.advance(2.0).change, TimeChange::Continuous);
    EXPECT_EQ(timeline.timeS(), 2.0);
}

// A laptop woken after a day: the phase must be right without looping once per lap.
TEST(Timeline, HugeElapsedTimeWithLoopWrapsByFmod) {
    Timeline timeline(2.0, 5.0, 0.02);
    timeline.setLoop(true);
    timeline.play();
    timeline.advance(1.0);  // at 3.0
    timeline.advance(86400.0 + 0.25);
    // 3 + 86400.25 − 2 = 86401.25 s into a 3 s loop: 86401.25 mod 3 = 1.25.
    EXPECT_NEAR(timeline.timeS(), 2.0 + 1.25, 1e-9);
    timeline.advance(1e15);
    EXPECT_GE(timeline.timeS(), 2.0);
    EXPECT_LT(timeline.timeS(), 5.0);
}

TEST(Timeline, LoopedTimeStaysInRangeForRandomElapsedTimes) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        Rng rng(seed);
        const double start = rng.uniform(-5.0f, 5.0f);
        const double end = start + rng.uniform(0.01f, 20.0f);
        Timeline timeline(start, end, 0.02);
        timeline.setLoop(true);
        timeline.setSpeed(rng.uniform(0.1f, 8.0f));
        timeline.play();
        for (int frame = 0; frame < 50; ++frame) {
            timeline.advance(std::pow(10.0, rng.uniform(-4.0f, 6.0f)));
            ASSERT_GE(timeline.timeS(), start) << "seed " << seed;
            ASSERT_LE(timeline.timeS(), end) << "seed " << seed;
        }
    }
}

TEST(Timeline, NanInfiniteAndNegativeElapsedTimesAreIgnored) {
    Timeline timeline(0.0, 10.0, 0.02);
    timeline.setLoop(true);
    timeline.play();
    timeline.advance(1.0);
    for (const double elapsed : {NAN_S, INF_S, -INF_S, -1.0, 0.0})
        EXPECT_EQ(timeline.advance(elapsed).change, TimeChange::None) << elapsed;
    EXPECT_EQ(timeline.timeS(), 1.0);
    EXPECT_TRUE(timeline.playing());
}

TEST(Timeline, ZeroLengthRangeHoldsItsOneTime) {
    Timeline timeline(3.0, 3.0, 0.02);
    timeline.setLoop(true);
    timeline.play();
    EXPECT_EQ(timeline.advance(1.0).change, TimeChange::None);
    EXPECT_EQ(timeline.timeS(), 3.0);
    EXPECT_EQ(timeline.stepForward().change, TimeChange::None);
    EXPECT_EQ(timeline.stepBack().change, TimeChange::None);
    EXPECT_EQ(timeline.scrub(7.0).change, TimeChange::None);
    EXPECT_EQ(timeline.timeS(), 3.0);
    // An end before the start also collapses to the start.
    const Timeline reversed(4.0, 1.0, 0.02);
    EXPECT_EQ(reversed.endS(), 4.0);
}

TEST(Timeline, SpeedIsClampedAndNonPositiveSpeedsAreRefused) {
    Timeline timeline;
    EXPECT_TRUE(timeline.setSpeed(100.0));
    EXPECT_EQ(timeline.speed(), TIMELINE_MAX_SPEED);
    EXPECT_TRUE(timeline.setSpeed(0.01));
    EXPECT_EQ(timeline.speed(), TIMELINE_MIN_SPEED);
    EXPECT_TRUE(timeline.setSpeed(2.0));
    for (const double bad : {-1.0, 0.0, NAN_S, INF_S}) {
        EXPECT_FALSE(timeline.setSpeed(bad)) << bad;
        EXPECT_EQ(timeline.speed(), 2.0) << bad;
    }
}

TEST(Timeline, StepsMoveOnePhysicsStepPauseAndClampToTheRange) {
    Timeline timeline(0.0, 0.05, 0.02);
    timeline.play();
    TimeUpdate update = timeline.stepForward();
    EXPECT_FALSE(timeline.playing());
    EXPECT_EQ(update, (TimeUpdate{TimeChange::Continuous, 0.0, 0.02}));
    timeline.stepForward();
    update = timeline.stepForward();
    EXPECT_EQ(update.change, TimeChange::Continuous);
    EXPECT_EQ(timeline.timeS(), 0.05);
    EXPECT_EQ(timeline.stepForward().change, TimeChange::None);
    update = timeline.stepBack();
    EXPECT_TRUE(update.needsReset());
    EXPECT_NEAR(timeline.timeS(), 0.03, 1e-12);
    timeline.stepBack();
    timeline.stepBack();
    EXPECT_EQ(timeline.timeS(), 0.0);
    EXPECT_EQ(timeline.stepBack().change, TimeChange::None);
}

TEST(Timeline, StepSizeMustBePositiveAndFinite) {
    Timeline timeline;
    EXPECT_TRUE(timeline.setStep(0.01));
    for (const double bad : {0.0, -0.01, NAN_S, INF_S})
        EXPECT_FALSE(timeline.setStep(bad)) << bad;
    EXPECT_EQ(timeline.stepS(), 0.01);
}

TEST(Timeline, ScrubClampsAndReportsTheDirection) {
    Timeline timeline(1.0, 5.0, 0.02);
    EXPECT_EQ(timeline.scrub(3.0), (TimeUpdate{TimeChange::JumpForward, 1.0, 3.0}));
    EXPECT_FALSE(timeline.scrub(9.0).needsReset());
    EXPECT_EQ(timeline.timeS(), 5.0);
    const TimeUpdate back = timeline.scrub(-2.0);
    EXPECT_TRUE(back.needsReset());
    EXPECT_EQ(timeline.timeS(), 1.0);
    EXPECT_EQ(timeline.scrub(1.0).change, TimeChange::None);
    EXPECT_EQ(timeline.scrub(NAN_S).change, TimeChange::None);
    EXPECT_EQ(timeline.timeS(), 1.0);
    timeline.scrub(INF_S);
    EXPECT_EQ(timeline.timeS(), 5.0);
}

TEST(Timeline, ShorteningTheRangePastTheTimeIsAJumpBack) {
    Timeline timeline(0.0, 10.0, 0.02);
    timeline.scrub(8.0);
    TimeUpdate update;
    ASSERT_TRUE(timeline.setRange(0.0, 4.0, &update));
    EXPECT_TRUE(update.needsReset());
    EXPECT_EQ(timeline.timeS(), 4.0);
    EXPECT_FALSE(timeline.setRange(NAN_S, 4.0));
    EXPECT_EQ(timeline.startS(), 0.0);
}

Project projectWithKeys() {
    Project project;
    project.physics.dtS = 0.02f;
    WindDesc wind;
    wind.source.path = {{1.0f, glm::vec3(0)}, {4.0f, glm::vec3(1)}};
    project.wind.push_back(wind);
    ColliderDesc collider;
    collider.path = {{0.5f, glm::vec3(0)}, {4.0f, glm::vec3(2)}, {14.5f, glm::vec3(3)}};
    project.colliders.push_back(collider);
    return project;
}

TEST(Timeline, KeyTimesCollectEveryPathOnceSorted) {
    EXPECT_EQ(keyTimes(projectWithKeys()), (std::vector<float>{0.5f, 1.0f, 4.0f, 14.5f}));
    EXPECT_TRUE(keyTimes(Project{}).empty());
}

// Issue 26: the timeline strip's ticks know what each key moves, and a click near one finds it.
TEST(Timeline, OwnedKeysSayWhatEachKeyMoves) {
    const std::vector<OwnedKey> keys = ownedKeys(projectWithKeys());
    ASSERT_EQ(keys.size(), 5u);
    EXPECT_EQ(keys[0], (OwnedKey{0.5f, false, 0}));
    EXPECT_EQ(keys[1], (OwnedKey{1.0f, true, 0}));
    EXPECT_EQ(keys[2], (OwnedKey{4.0f, true, 0})) << "wind before collider at equal times";
    EXPECT_EQ(keys[3], (OwnedKey{4.0f, false, 0}));
    EXPECT_EQ(nearestOwnedKey(keys, 0.9f, 0.2f), std::optional<OwnedKey>(keys[1]));
    EXPECT_EQ(nearestOwnedKey(keys, 14.0f, 0.6f), std::optional<OwnedKey>(keys[4]));
    EXPECT_FALSE(nearestOwnedKey(keys, 8.0f, 1.0f).has_value());
}

TEST(Timeline, DefaultRangeReachesTheLastKeyOrTenSeconds) {
    const Timeline keyed = timelineFor(projectWithKeys());
    EXPECT_EQ(keyed.startS(), 0.0);
    EXPECT_EQ(keyed.endS(), 14.5);
    EXPECT_FLOAT_EQ(static_cast<float>(keyed.stepS()), 0.02f);
    EXPECT_EQ(timelineFor(Project{}).endS(), TIMELINE_MIN_DEFAULT_END_S);
}

TEST(PathKeys, SetKeyInsertsInTimeOrder) {
    std::vector<PathKey> path;
    EXPECT_EQ(setKey(path, 2.0f, glm::vec3(2), 0.01f), 0u);
    EXPECT_EQ(setKey(path, 0.0f, glm::vec3(0), 0.01f), 0u);
    EXPECT_EQ(setKey(path, 5.0f, glm::vec3(5), 0.01f), 2u);
    EXPECT_EQ(setKey(path, 1.0f, glm::vec3(1), 0.01f), 1u);
    ASSERT_EQ(path.size(), 4u);
    for (std::size_t i = 1; i < path.size(); ++i)
        EXPECT_LT(path[i - 1].timeS, path[i].timeS);
    EXPECT_EQ(path[2], (PathKey{2.0f, glm::vec3(2)}));
}

TEST(PathKeys, SetKeyWithinHalfAStepReplacesThePositionAndKeepsTheTime) {
    std::vector<PathKey> path = {{0.0f, glm::vec3(0)}, {1.0f, glm::vec3(1)}};
    const float halfStep = 0.01f;
    EXPECT_EQ(setKey(path, 1.005f, glm::vec3(7), halfStep), 1u);
    ASSERT_EQ(path.size(), 2u);
    EXPECT_EQ(path[1], (PathKey{1.0f, glm::vec3(7)}));
    // Just beyond the tolerance: a new key.
    EXPECT_EQ(setKey(path, 1.02f, glm::vec3(8), halfStep), 2u);
    EXPECT_EQ(path.size(), 3u);
}

TEST(PathKeys, RemoveKeyTakesOnlyTheNearestWithinTolerance) {
    std::vector<PathKey> path = {{0.0f, glm::vec3(0)}, {1.0f, glm::vec3(1)}, {2.0f, glm::vec3(2)}};
    EXPECT_FALSE(removeKey(path, 1.5f, 0.1f));
    EXPECT_EQ(path.size(), 3u);
    EXPECT_TRUE(removeKey(path, 1.05f, 0.1f));
    EXPECT_EQ(path, (std::vector<PathKey>{{0.0f, glm::vec3(0)}, {2.0f, glm::vec3(2)}}));
    std::vector<PathKey> empty;
    EXPECT_FALSE(removeKey(empty, 0.0f, 1.0f));
}

TEST(PathKeys, NearestKeyPrefersTheEarlierOnATie) {
    const std::vector<PathKey> path = {{0.0f, glm::vec3(0)}, {2.0f, glm::vec3(2)}};
    EXPECT_EQ(nearestKey(path, 1.0f), 0u);
    EXPECT_EQ(nearestKey(path, 1.5f), 1u);
    EXPECT_EQ(nearestKey(path, 9.0f), 1u);
    EXPECT_EQ(nearestKey(path, 1.0f, 0.5f), std::nullopt);
    EXPECT_EQ(nearestKey({}, 1.0f), std::nullopt);
}

TEST(PathKeys, SampledEditedPathsInterpolateBetweenTheKeys) {
    std::vector<PathKey> path;
    setKey(path, 2.0f, glm::vec3(4, 0, 0), 0.01f);
    setKey(path, 0.0f, glm::vec3(0, 0, 0), 0.01f);
    setKey(path, 4.0f, glm::vec3(4, 0, 8), 0.01f);
    const glm::vec3 fallback(-1.0f);
    EXPECT_EQ(samplePath(path, -1.0f, fallback), glm::vec3(0, 0, 0));  // clamped before
    EXPECT_EQ(samplePath(path, 1.0f, fallback), glm::vec3(2, 0, 0));
    EXPECT_EQ(samplePath(path, 3.0f, fallback), glm::vec3(4, 0, 4));
    EXPECT_EQ(samplePath(path, 9.0f, fallback), glm::vec3(4, 0, 8));  // clamped after
    // Moving the middle key re-shapes both segments around it.
    setKey(path, 2.004f, glm::vec3(0, 2, 0), 0.01f);
    EXPECT_EQ(samplePath(path, 1.0f, fallback), glm::vec3(0, 1, 0));
    EXPECT_EQ(samplePath(path, 3.0f, fallback), glm::vec3(2, 1, 4));
    ASSERT_TRUE(removeKey(path, 2.0f, 0.01f));
    EXPECT_EQ(samplePath(path, 2.0f, fallback), glm::vec3(2, 0, 4));
    EXPECT_EQ(samplePath({}, 2.0f, fallback), fallback);
}

}  // namespace
}  // namespace grass::core
