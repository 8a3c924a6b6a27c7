// The indirect draw commands the cull pass starts from (core/blade/blade_draw_commands.h): each
// LOD's strip vertex count follows its segments and whether it keeps the midrib column.
#include <gtest/gtest.h>

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
        EXPECT_EQ(commands[std::size_t(LOD_COUNT + lod)].count, 1u) << "one patch vertex a blade";
    }
    // A single segment never drops below one quad.
    EXPECT_EQ(emptyBladeDrawCommands(1)[2].count, 4u);
}

}  // namespace
}  // namespace grass::core
