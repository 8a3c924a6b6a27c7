#include "physics/path_loop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace grass::core {
namespace {

// The loop every window must reproduce: forth from the first key to the last, back, again.
glm::vec3 pingPongAt(const std::vector<PathKey>& path, double timeS) {
    const double firstS = path.front().timeS, spanS = path.back().timeS - firstS;
    double u = std::fmod(std::max(0.0, timeS - firstS), 2.0 * spanS);
    if (u > spanS)
        u = 2.0 * spanS - u;
    return samplePath(path, static_cast<float>(firstS + u), glm::vec3(0.0f));
}

const std::vector<PathKey> PATH{
    {2.0f, {0, 0, 0}}, {3.0f, {1, 0, 0}}, {5.0f, {1, 2, 0}}, {6.0f, {4, 2, 1}}};

TEST(PathLoop, PeriodIsTwiceTheSpan) {
    EXPECT_FLOAT_EQ(pingPongPeriodS(PATH), 8.0f);
    EXPECT_EQ(pingPongPeriodS({}), 0.0f);
    EXPECT_EQ(pingPongPeriodS({{1.0f, {1, 1, 1}}}), 0.0f);
    EXPECT_EQ(pingPongPeriodS({{1.0f, {1, 1, 1}}, {1.0f, {2, 2, 2}}}), 0.0f);
}

TEST(PathLoop, WindowsFollowTheLoopForAnHour) {
    // Windows of 64 s all through an hour, sampled every 0.37 s: the position is the loop's.
    for (double fromS = 0.0; fromS < 3600.0; fromS += 64.0) {
        const auto window =
            pingPongWindow(PATH, static_cast<float>(fromS), static_cast<float>(fromS + 64.0));
        ASSERT_TRUE(
            std::is_sorted(window.begin(), window.end(),
                           [](const PathKey& a, const PathKey& b) { return a.timeS < b.timeS; }));
        ASSERT_LE(window.size(), 2 * PATH.size() * 10);
        for (double t = fromS; t <= fromS + 64.0; t += 0.37) {
            const glm::vec3 got = samplePath(window, static_cast<float>(t), glm::vec3(0.0f));
            const glm::vec3 want = pingPongAt(PATH, t);
            // Float key times near an hour are exact to ~2.4e-4 s; the path moves <= 3.2 m/s.
            ASSERT_LT(glm::length(got - want), 2e-3f) << "t = " << t;
        }
    }
}

TEST(PathLoop, StillPathsComeBackUnchanged) {
    const std::vector<PathKey> one{{1.0f, {1, 2, 3}}};
    EXPECT_EQ(pingPongWindow(one, 100.0f, 200.0f), one);
    EXPECT_TRUE(pingPongWindow({}, 0.0f, 10.0f).empty());
}

TEST(PathLoop, LooperSwapsWindowsBeforeTheyRunOut) {
    const std::vector<PathKey> windPath{{0.0f, {0, 0, 0}}, {1.0f, {2, 0, 0}}};
    std::vector<WindSource> wind(2);
    wind[1].path = windPath;
    std::vector<SphereCollider> colliders(1);
    colliders[0].path = PATH;
    PathLooper looper(wind, colliders);
    EXPECT_EQ(looper.loopingPaths(), 2u);
    EXPECT_FLOAT_EQ(looper.longestPeriodS(), 8.0f);
    const float dtS = 1.0f / 60.0f;
    std::size_t swaps = 0;
    for (int step = 0; step < 216000; ++step) {
        const double t = step * double(dtS);
        swaps += looper.update(wind, colliders, static_cast<float>(t), dtS) ? 1 : 0;
        if (step % 997 != 0)
            continue;
        // The step samples up to t + dt (substeps): both ends must be on the loop.
        for (const double s : {t, t + dtS}) {
            ASSERT_LT(glm::length(samplePath(colliders[0].path, static_cast<float>(s), {}) -
                                  pingPongAt(PATH, s)),
                      2e-3f)
                << "t = " << s;
            ASSERT_LT(glm::length(samplePath(wind[1].path, static_cast<float>(s), {}) -
                                  pingPongAt(windPath, s)),
                      2e-3f)
                << "t = " << s;
        }
    }
    EXPECT_TRUE(wind[0].path.empty());
    // One swap per window of 64 s over an hour, give or take the first.
    EXPECT_NEAR(static_cast<double>(swaps), 3600.0 / 64.0, 2.0);
}

}  // namespace
}  // namespace grass::core
