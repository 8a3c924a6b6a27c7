#include "util/pareto.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace grass::core {
namespace {

TEST(Pareto, DominatedPointsAreOffTheFront) {
    const std::vector<CostError> points = {
        {1.0, 10.0}, {2.0, 5.0}, {3.0, 6.0}, {4.0, 1.0}, {4.0, 2.0}};
    const std::vector<bool> expected = {true, true, false, true, false};
    EXPECT_EQ(paretoFront(points), expected);
}

TEST(Pareto, EqualPointsStayOnTheFront) {
    const std::vector<CostError> points = {{1.0, 1.0}, {1.0, 1.0}};
    EXPECT_EQ(paretoFront(points), (std::vector<bool>{true, true}));
}

TEST(Pareto, NonFinitePointsNeitherJoinNorDominate) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<CostError> points = {
        {0.0, nan}, {2.0, 2.0}, {-1.0, std::numeric_limits<double>::infinity()}};
    EXPECT_EQ(paretoFront(points), (std::vector<bool>{false, true, false}));
}

// Property: over seeded random clouds, no front point is dominated and every point off the
// front is dominated by some front point.
TEST(Pareto, FrontIsExactlyTheUndominatedSet) {
    for (unsigned seed = 1; seed < 50; ++seed) {
        std::vector<CostError> points;
        unsigned state = seed;
        const auto next = [&state] {
            state = state * 1664525u + 1013904223u;
            return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
        };
        for (int i = 0; i < 30; ++i)
            points.push_back({std::floor(next() * 10.0), std::floor(next() * 10.0)});
        const std::vector<bool> front = paretoFront(points);
        for (std::size_t i = 0; i < points.size(); ++i) {
            bool dominated = false;
            for (std::size_t j = 0; j < points.size(); ++j)
                if (front[j] && points[j].cost <= points[i].cost &&
                    points[j].error <= points[i].error &&
                    (points[j].cost < points[i].cost || points[j].error < points[i].error))
                    dominated = true;
            EXPECT_EQ(front[i], !dominated) << "seed " << seed << " point " << i;
        }
    }
}

}  // namespace
}  // namespace grass::core
