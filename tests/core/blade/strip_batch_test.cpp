// Strip batches (core/blade/strip_batch.h): a batch's index list draws each blade's strip as GL's
// triangle strip would, the commands point at each LOD's list, the cull pass's per-group batch
// counts add up to the batches of the survivors, and the shaders agree on the batch size.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <utility>

#include "blade/strip_batch.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"

namespace grass::core {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// GL_TRIANGLE_STRIP's triangles of `vertices` vertices from `first`, as the GL specification
// orders them (10.1.3: triangle i is (i, i+1, i+2), the first two swapped when i is odd).
std::vector<Triangle> glStripTriangles(std::uint32_t first, int vertices) {
    std::vector<Triangle> triangles;
    for (int i = 0; i + 2 < vertices; ++i) {
        const std::uint32_t a = first + std::uint32_t(i);
        triangles.push_back(i % 2 == 0 ? Triangle{a, a + 1, a + 2} : Triangle{a + 1, a, a + 2});
    }
    return triangles;
}

// The strip vertex's row along the blade (blade_strip.vert's numbering).
int stripRow(int vertex, int segments, bool folded) {
    const int half = 2 * (segments + 1);
    if (!folded || vertex < half)
        return vertex / 2;
    return segments - (vertex - half) / 2;
}

TEST(StripBatch, EachBladeIsItsStripsTrianglesWithTheirWinding) {
    for (const bool folded : {true, false})
        for (const int segments : {1, 2, 4, 8, 32}) {
            const int vertices = stripVertexCount(segments, folded);
            const std::vector<std::uint32_t> indices = stripBatchIndices(segments, folded);
            const int perBlade = stripBatchTriangles(segments, folded);
            ASSERT_EQ(indices.size(), std::size_t(3 * STRIP_BATCH_BLADES * perBlade));
            for (int blade = 0; blade < STRIP_BATCH_BLADES; blade += STRIP_BATCH_BLADES - 1) {
                const auto first = std::uint32_t(blade * vertices);
                std::vector<Triangle> expected;
                // The strip's triangles less the zero-area ones: all three vertices on one row.
                for (const Triangle& t : glStripTriangles(first, vertices)) {
                    const int row0 = stripRow(int(t[0] - first), segments, folded);
                    if (row0 == stripRow(int(t[1] - first), segments, folded) &&
                        row0 == stripRow(int(t[2] - first), segments, folded))
                        continue;
                    expected.push_back(t);
                }
                ASSERT_EQ(expected.size(), std::size_t(perBlade)) << segments << " " << folded;
                for (int t = 0; t < perBlade; ++t) {
                    const std::size_t at = std::size_t(3 * (blade * perBlade + t));
                    const Triangle got{indices[at], indices[at + 1], indices[at + 2]};
                    EXPECT_EQ(got, expected[std::size_t(t)])
                        << "segments " << segments << " folded " << folded << " blade " << blade
                        << " triangle " << t;
                }
            }
            // Every vertex id lies within the batch's blades.
            EXPECT_EQ(*std::max_element(indices.begin(), indices.end()),
                      std::uint32_t(STRIP_BATCH_BLADES * vertices - 1));
        }
}

// A folded blade of 8 segments is 32 triangles a blade (34 in the strip, two of them at the tip
// of zero area), its far LODs 8 and 4 (the edges alone at 4 and 2 segments).
TEST(StripBatch, CommandsPointAtEachLodsListInTheElementBuffer) {
    const StripBatchCommands commands = emptyStripBatchCommands(8);
    const std::vector<std::uint32_t> elements = stripBatchElements(8);
    const std::array<std::uint32_t, LOD_COUNT> triangles{32, 8, 4};
    std::uint32_t first = 0;
    for (int lod = 0; lod < LOD_COUNT; ++lod) {
        const DrawElementsIndirectCommand& command = commands[std::size_t(lod)];
        EXPECT_EQ(command.count, 3u * STRIP_BATCH_BLADES * triangles[std::size_t(lod)]) << lod;
        EXPECT_EQ(command.firstIndex, first) << lod;
        EXPECT_EQ(command.instanceCount, 0u) << "the cull pass fills these";
        const std::vector<std::uint32_t> own =
            stripBatchIndices(lodSegments(8, lod), lodFolded(lod));
        ASSERT_LE(first + command.count, elements.size());
        EXPECT_TRUE(std::equal(own.begin(), own.end(), elements.begin() + first)) << lod;
        const DrawElementsIndirectCommand& blending = commands[std::size_t(LOD_COUNT + lod)];
        EXPECT_EQ(blending.count, command.count);
        EXPECT_EQ(blending.firstIndex, command.firstIndex);
        first += command.count;
    }
    EXPECT_EQ(first, elements.size());
    // The batch commands follow the per-LOD ones, where cull.comp writes them.
    EXPECT_EQ(stripBatchCommandOffset(0), sizeof(BladeDrawCommands));
    EXPECT_EQ(stripBatchCommandOffset(1, true) - stripBatchCommandOffset(0),
              std::size_t(LOD_COUNT + 1) * sizeof(DrawElementsIndirectCommand));
    // blade_strip.vert's survivors: the instance count of the class's strip command.
    BladeCommandBuffer buffer = emptyBladeCommandBuffer(8);
    buffer.draws[stripCommandOffset(2, true) / sizeof(DrawArraysIndirectCommand)].instanceCount =
        77;
    const auto* words = reinterpret_cast<const std::uint32_t*>(&buffer);
    EXPECT_EQ(words[stripSurvivorWord(2, true)], 77u);
}

// cull.comp's work groups reserve disjoint survivor ranges in any order; each adds the batches
// its range begins. Together they count the batches of all survivors.
TEST(StripBatch, GroupsCountingTheBatchesTheyBeginCountEveryBatchOnce) {
    EXPECT_EQ(stripBatches(0), 0u);
    EXPECT_EQ(stripBatches(1), 1u);
    EXPECT_EQ(stripBatches(STRIP_BATCH_BLADES), 1u);
    EXPECT_EQ(stripBatches(STRIP_BATCH_BLADES + 1), 2u);
    std::mt19937 random(7);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<std::uint32_t> groupSurvivors(1 + random() % 300);
        for (std::uint32_t& n : groupSurvivors)
            n = std::uint32_t(random() % 33);  // a group of 32 invocations keeps 0..32 blades
        std::shuffle(groupSurvivors.begin(), groupSurvivors.end(), random);
        std::uint32_t base = 0, batches = 0;
        for (const std::uint32_t n : groupSurvivors) {
            batches += stripBatches(base + n) - stripBatches(base);
            base += n;
        }
        EXPECT_EQ(batches, stripBatches(base)) << trial;
    }
}

// A frame's blade triangles: 32 a folded blade of 8 segments at LOD 0, 8 and 4 at half and a
// quarter of the segments without the fold, never below one quad of two.
TEST(StripBatch, DrawnTrianglesFollowEachLodsSegmentsAndFold) {
    EXPECT_EQ(drawnBladeTriangles({10, 20, 30}, 8), 10u * 32 + 20u * 8 + 30u * 4);
    EXPECT_EQ(drawnBladeTriangles({0, 0, 5}, 1), 5u * 2);
    EXPECT_EQ(drawnBladeTriangles({0, 0, 0}, 8), 0u);
}

TEST(StripBatch, TheShadersBatchAsManyBladesAsTheCommands) {
    const std::pair<const char*, const char*> defines[] = {
        {"blade_strip.vert", "#define STRIP_BATCH_BLADES "},
        {"cull.comp", "#define STRIP_BATCH_BLADES "},
        {"blade_tess.vert", "#define PATCH_BATCH_BLADES "}};
    for (const auto& [file, define] : defines) {
        const auto source = readFile(test::sourceDir() / "shaders" / file);
        ASSERT_TRUE(source.ok()) << source.error().str();
        const std::size_t at = source->find(define);
        ASSERT_NE(at, std::string::npos) << file;
        EXPECT_EQ(std::stoi(source->substr(at + std::string(define).size())), STRIP_BATCH_BLADES)
            << file;
    }
    // Both batch paths read their survivors from the command texels on COMMAND_TEXELS_UNIT.
    const auto texels = readFile(test::sourceDir() / "shaders" / "include" / "blade_texels.glsl");
    ASSERT_TRUE(texels.ok()) << texels.error().str();
    EXPECT_NE(texels->find("layout(binding = " + std::to_string(COMMAND_TEXELS_UNIT) +
                           ") uniform usamplerBuffer uCommandTexels;"),
              std::string::npos);
}

}  // namespace
}  // namespace grass::core
