// forEachDispatchChunk: long passes are cut at GL's guaranteed 65535 work groups per call, every
// item lands in exactly one chunk, and a pass that fits takes one call (issue 29: a 10M-blade
// layer needs 312,500 groups of 32).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "util/dispatch_chunks.h"

namespace grass::core {
namespace {

using Calls = std::vector<std::pair<std::size_t, std::uint32_t>>;

Calls chunksOf(std::size_t items, std::size_t groupSize) {
    Calls calls;
    forEachDispatchChunk(items, groupSize, [&](std::size_t first, std::uint32_t groups) {
        calls.emplace_back(first, groups);
    });
    return calls;
}

TEST(DispatchChunks, AFieldThatFitsTakesOneCall) {
    EXPECT_EQ(chunksOf(100, 32), (Calls{{0, 4}}));
    EXPECT_EQ(chunksOf(32 * MAX_DISPATCH_GROUPS, 32), (Calls{{0, 65535}}));
}

TEST(DispatchChunks, NothingToDoCallsNothing) {
    EXPECT_TRUE(chunksOf(0, 32).empty());
}

TEST(DispatchChunks, TenMillionBladesTakeFiveCallsCoveringEverySlotOnce) {
    const std::size_t items = 10'000'000;
    const Calls calls = chunksOf(items, 32);
    ASSERT_EQ(calls.size(), 5u);
    std::size_t next = 0, groups = 0;
    for (const auto& [first, count] : calls) {
        EXPECT_EQ(first, next);
        EXPECT_LE(count, MAX_DISPATCH_GROUPS);
        next = first + std::size_t(count) * 32;
        groups += count;
    }
    EXPECT_EQ(groups, (items + 31) / 32);  // 312,500
    EXPECT_GE(next, items);
    EXPECT_LT(next - items, 32u);
}

}  // namespace
}  // namespace grass::core
