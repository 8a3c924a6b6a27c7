// dispatchGrid: a pass of any length runs as one grid of work groups within GL's guaranteed
// 65535 per dimension, every item covered once in the order of the groups, few groups idle, and
// the second dimension in use from 8,192 items (groups of 32) so the GL tests run it (issue 29:
// a 10M-blade layer needs 312,500 groups of 32).
#include <gtest/gtest.h>

#include <algorithm>

#include "util/dispatch_grid.h"

namespace grass::core {
namespace {

// The grid covers [0, items) with fewer idle groups than rows, within GL's limits.
void expectCovers(std::size_t items, std::size_t groupSize) {
    const DispatchGrid grid = dispatchGrid(items, groupSize);
    const std::size_t groups = (items + groupSize - 1) / groupSize;
    const std::size_t launched = std::size_t(grid.x) * grid.y;
    EXPECT_GE(launched, groups) << items;
    EXPECT_LT(launched - groups, std::max<std::size_t>(grid.y, 1)) << items;
    EXPECT_LE(grid.x, DISPATCH_ROW_GROUPS) << items;
    EXPECT_LE(grid.y, MAX_DISPATCH_GROUPS) << items;
}

TEST(DispatchGrid, AShortPassIsOneRow) {
    EXPECT_EQ(dispatchGrid(100, 32).x, 4u);
    EXPECT_EQ(dispatchGrid(100, 32).y, 1u);
    EXPECT_EQ(dispatchGrid(32 * DISPATCH_ROW_GROUPS, 32).y, 1u);
    EXPECT_EQ(dispatchGrid(32 * DISPATCH_ROW_GROUPS + 1, 32).y, 2u);
}

TEST(DispatchGrid, NothingToDoDispatchesNothing) {
    const DispatchGrid grid = dispatchGrid(0, 32);
    EXPECT_EQ(grid.x, 0u);
    EXPECT_EQ(grid.y, 0u);
}

TEST(DispatchGrid, TenMillionBladesTakeOneGridCoveringEverySlot) {
    const DispatchGrid grid = dispatchGrid(10'000'000, 32);
    EXPECT_EQ(grid.y, 1221u);  // ceil(312,500 / 256)
    EXPECT_EQ(grid.x, 256u);
    expectCovers(10'000'000, 32);
    for (const std::size_t items : {1u, 31u, 32u, 33u, 8191u, 8192u, 8193u, 58942u, 398083u,
                                    2'097'120u, 2'097'121u, 20'000'000u, 500'000'000u})
        expectCovers(items, 32);
}

}  // namespace
}  // namespace grass::core
