// The indirect draw commands the cull pass starts from (core/blade/blade_draw_commands.h): each
// LOD's strip vertex count follows its segments and whether it keeps the midrib column.
#include <gtest/gtest.h>

#include <cmath>

#include "blade/blade_draw_commands.h"

namespace grass::core {
namespace {

TEST(BladeDrawCommands, NearStripsKeepTheMidribAndFarStripsDrawTheEdgesAlone) {
    ASSERT_TRUE(lodFolded(0));
    EXPECT_FALSE(lodFolded(1));
    EXPECT_FALSE(lodFolded(LOD_COUNT - 1));
    // 8 segments: 9 rows of 4 vertices (u = 0, ½ up, u = 1, ½ down), 34 triangles.
    EXPECT_EQ(stripVertexCount(8, true), 36);
    // 4 segments without the fold: 5 rows of the two edges, 8 triangles instead of 18.
    EXPECT_EQ(stripVertexCount(4, false), 10);
    const BladeDrawCommands commands = emptyBladeDrawCommands(8);
    EXPECT_EQ(commands[0].count, 36u);  // LOD 0: 8 segments, folded
    EXPECT_EQ(commands[1].count, 10u);  // LOD 1: 4 segments, edges
    EXPECT_EQ(commands[2].count, 6u);   // LOD 2: 2 segments, edges
    for (int lod = 0; lod < LOD_COUNT; ++lod) {
        EXPECT_EQ(commands[std::size_t(lod)].instanceCount, 0u) << "the cull pass fills these";
        // One single-vertex patch a blade, PATCH_BATCH_BLADES blades an instance.
        EXPECT_EQ(commands[std::size_t(LOD_COUNT + lod)].count, 64u);
    }
    // A single segment never drops below one quad.
    EXPECT_EQ(emptyBladeDrawCommands(1)[2].count, 4u);
}

// The blades in a LOD's morph band have commands of their own after the others' (strips, then
// patches), with the same vertex counts; a LOD's drawn blades are both commands' together.
TEST(BladeDrawCommands, BlendingBladesHaveCommandsOfTheirOwn) {
    BladeDrawCommands commands = emptyBladeDrawCommands(8);
    for (int lod = 0; lod < LOD_COUNT; ++lod) {
        const auto plain = stripCommandOffset(lod) / sizeof(DrawArraysIndirectCommand);
        const auto blending = stripCommandOffset(lod, true) / sizeof(DrawArraysIndirectCommand);
        EXPECT_EQ(plain, std::size_t(lod));
        EXPECT_EQ(blending, std::size_t(2 * LOD_COUNT + lod));
        EXPECT_EQ(patchCommandOffset(lod) / sizeof(DrawArraysIndirectCommand),
                  std::size_t(LOD_COUNT + lod));
        EXPECT_EQ(patchCommandOffset(lod, true) / sizeof(DrawArraysIndirectCommand),
                  std::size_t(3 * LOD_COUNT + lod));
        EXPECT_EQ(commands[blending].count, commands[plain].count) << lod;
        EXPECT_EQ(commands[3 * LOD_COUNT + std::size_t(lod)].count,
                  std::uint32_t(PATCH_BATCH_BLADES))
            << lod;
        commands[plain].instanceCount = 10u + std::uint32_t(lod);
        commands[blending].instanceCount = 3u;
        EXPECT_EQ(drawnAtLod(commands, lod), 13u + std::uint32_t(lod));
        EXPECT_EQ(blendingAtLod(commands, lod), 3u);
    }
    // LOD 1 of a 100-slot layer: its list is [100, 200); forwards from 100, backwards from 199.
    EXPECT_EQ(visibleListStart(1, 100, false), 100u);
    EXPECT_EQ(visibleListStart(1, 100, true), 199u);
    // The band: the last quarter of LOD 0's range and of LOD 1's; never LOD 2 nor without LODs.
    EXPECT_FALSE(lodBlending(5.9f, 8.0f, 0, LOD_BLEND));
    EXPECT_TRUE(lodBlending(6.1f, 8.0f, 0, LOD_BLEND));
    EXPECT_FALSE(lodBlending(19.9f, 8.0f, 1, LOD_BLEND));
    EXPECT_TRUE(lodBlending(20.1f, 8.0f, 1, LOD_BLEND));
    EXPECT_FALSE(lodBlending(30.0f, 8.0f, 2, LOD_BLEND));
    EXPECT_FALSE(lodBlending(7.9f, 8.0f, 0, 0.0f)) << "a hard switch blends nothing";
    EXPECT_FALSE(lodBlending(7.9f, 0.0f, 0, LOD_BLEND)) << "no LODs, nothing to blend into";
}

TEST(BladeLod, FullUpToTheDistanceHalfToThreeTimesItQuarterBeyond) {
    EXPECT_EQ(bladeLod(7.99f, 8.0f), 0);
    EXPECT_EQ(bladeLod(8.0f, 8.0f), 1);
    EXPECT_EQ(bladeLod(23.99f, 8.0f), 1);
    EXPECT_EQ(bladeLod(24.0f, 8.0f), 2);
    EXPECT_EQ(bladeLod(1e6f, 0.0f), 0) << "no LOD distance: full detail everywhere";
}

// The blend band of lod.glsl's lodMorph: 0 before it, linear across it, 1 at the switch, with
// the band a share of each LOD's own range (LOD 0: [0, d), LOD 1: [d, 3d)).
TEST(BladeLod, MorphRisesOverTheLastShareOfEachRange) {
    const float d = 8.0f;
    // LOD 0, band [6, 8).
    EXPECT_EQ(lodMorph(5.9f, d, 0, 0.25f), 0.0f);
    EXPECT_NEAR(lodMorph(6.5f, d, 0, 0.25f), 0.25f, 1e-6f);
    EXPECT_NEAR(lodMorph(7.0f, d, 0, 0.25f), 0.5f, 1e-6f);
    EXPECT_NEAR(lodMorph(7.999f, d, 0, 0.25f), 1.0f, 1e-3f);
    // LOD 1, range [8, 24), band [20, 24): not [22, 24) as a share of d would give.
    EXPECT_EQ(lodMorph(19.9f, d, 1, 0.25f), 0.0f);
    EXPECT_NEAR(lodMorph(21.0f, d, 1, 0.25f), 0.25f, 1e-6f);
    EXPECT_NEAR(lodMorph(23.999f, d, 1, 0.25f), 1.0f, 1e-3f);
    // The last LOD has nothing to morph into; no blend and no LODs switch hard.
    EXPECT_EQ(lodMorph(100.0f, d, LOD_COUNT - 1, 0.25f), 0.0f);
    EXPECT_EQ(lodMorph(7.9f, d, 0, 0.0f), 0.0f);
    EXPECT_EQ(lodMorph(7.9f, 0.0f, 0, 0.25f), 0.0f);
    // A whole-range blend starts at the range's start.
    EXPECT_NEAR(lodMorph(4.0f, d, 0, 1.0f), 0.5f, 1e-6f);
    EXPECT_NEAR(lodMorph(16.0f, d, 1, 2.0f), 0.5f, 1e-6f) << "shares above 1 clamp to 1";
}

// Walking out through the field, a blade's (LOD, morph) never jumps: each switch happens where
// the morph has reached 1, which is where the coarser LOD's surface (morph 0) is the same.
TEST(BladeLod, MorphReachesOneExactlyWhereTheLodChanges) {
    const float d = 5.0f;
    int previousLod = 0;
    float previousMorph = 0.0f;
    for (int i = 1; i <= 40000; ++i) {
        const float distance = 0.001f * static_cast<float>(i);
        const int lod = bladeLod(distance, d);
        const float morph = lodMorph(distance, d, lod, LOD_BLEND);
        if (lod != previousLod) {
            EXPECT_EQ(lod, previousLod + 1) << distance;
            EXPECT_GT(previousMorph, 0.998f) << "switched before the blend was done at " << distance;
            EXPECT_LT(morph, 1e-6f) << distance;
        } else {
            EXPECT_LE(std::abs(morph - previousMorph), 0.002f) << "a jump at " << distance;
        }
        previousLod = lod;
        previousMorph = morph;
    }
    EXPECT_EQ(previousLod, 2);
}

}  // namespace
}  // namespace grass::core
