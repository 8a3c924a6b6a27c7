// Strip batches: the strip path draws a LOD's blades STRIP_BATCH_BLADES to an instance, as
// indexed triangles, instead of one tiny instance per blade. A GL implementation pays for each
// instance of an instanced draw: Mesa's llvmpipe runs its vertex pipeline (fetch, vertex shader,
// clipping) once per instance, on the application's thread (read in Mesa's draw module), and
// GPU vendors advise against instances of a few vertices, which leave their vertex batches
// mostly empty (not measured here yet); a far blade is 6 or 10 vertices. Drawn in batches, every
// blade of projects/nature at quarter segments (398k blades, 4 triangles each, llvmpipe, no MSAA)
// took a median 221 ms of grass pass instead of 249 ms (interleaved runs), with the same picture (0
// differing pixels); docs/rendering.md, "Strip batches", has the figures.
//
// A batch instance draws vertices [0, STRIP_BATCH_BLADES · V) of one index list, V being a
// blade's strip vertices at the draw's LOD (stripVertexCount); blade_strip.vert turns a vertex
// id into (blade of the batch, vertex of its strip) and the instance into the batch. The
// triangles are those GL_TRIANGLE_STRIP makes of each blade's strip, with the same winding,
// less the two zero-area ones at a folded blade's tip (all their vertices on the tip's row). The
// last batch of a draw is partly empty: blade_strip.vert puts the vertices of the blades past the
// LOD's survivors outside the clip volume.
//
// The cull pass (shaders/cull.comp) counts batches as it counts survivors: a work group that
// reserves the survivor range [base, base + n) adds stripBatches(base + n) − stripBatches(base)
// to the class's batch command; over the disjoint ranges of all groups the sum is
// stripBatches(survivors), whatever the groups' order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "blade/blade_draw_commands.h"

namespace grass::core {

// STRIP_BATCH_BLADES in shaders/blade_strip.vert. 64 blades of the densest strip (64 segments,
// folded: 260 vertices) stay within 16,640 vertex ids; at 2 to 4 segments a batch is 384 to 640
// vertices, the size of a mesh rather than of a blade.
inline constexpr int STRIP_BATCH_BLADES = 64;
static_assert(STRIP_BATCH_BLADES == PATCH_BATCH_BLADES,
              "cull.comp adds one count of batches begun to the strips' and the patches' commands");

// Matches GL's DrawElementsIndirectCommand.
struct DrawElementsIndirectCommand {
    std::uint32_t count;
    std::uint32_t instanceCount;
    std::uint32_t firstIndex;
    std::int32_t baseVertex;
    std::uint32_t baseInstance;
};
static_assert(sizeof(DrawElementsIndirectCommand) == 20);

// One batch command per cull class: LOD k's blades before its morph band at [k], those in it at
// [LOD_COUNT + k] (the classes of shaders/cull.comp).
using StripBatchCommands = std::array<DrawElementsIndirectCommand, 2 * LOD_COUNT>;

// A layer's command buffer as the cull pass fills it: the per-LOD commands (whose strip instance
// counts are the survivors of each class, read by the statistics and by blade_strip.vert), then
// the batch commands the strips are drawn with.
struct BladeCommandBuffer {
    BladeDrawCommands draws;
    StripBatchCommands stripBatches;
};
static_assert(sizeof(BladeCommandBuffer) == sizeof(BladeDrawCommands) + sizeof(StripBatchCommands));
static_assert(offsetof(BladeCommandBuffer, stripBatches) == sizeof(BladeDrawCommands),
              "cull.comp addresses the batch commands right after the per-LOD ones");

// Byte offset of a class's batch command in the command buffer.
inline std::size_t stripBatchCommandOffset(int lod, bool blending = false) {
    return offsetof(BladeCommandBuffer, stripBatches) +
           std::size_t((blending ? LOD_COUNT : 0) + lod) * sizeof(DrawElementsIndirectCommand);
}

// Where blade_strip.vert finds its draw's survivors in the command buffer read as 32-bit words:
// the instance count of the class's strip command.
inline int stripSurvivorWord(int lod, bool blending = false) {
    return int(stripCommandOffset(lod, blending) / sizeof(std::uint32_t)) + 1;
}

// Batches that draw `blades` blades.
inline std::uint32_t stripBatches(std::uint32_t blades) {
    return (blades + STRIP_BATCH_BLADES - 1) / STRIP_BATCH_BLADES;
}

// Triangles of one blade's strip in a batch (the strip's, less a folded tip's two zero-area ones).
inline int stripBatchTriangles(int segments, bool folded) {
    return (folded ? 4 : 2) * segments;
}

// Triangles the blades of a frame draw, `drawnPerLod` of them at each LOD of blades of `segments`
// segments at full detail; the same on both paths (the tessellation's quads of lodSegments ×
// (2 folded, 1 flat) cells make as many). `grass bench` reports them, so a frame's cost can be
// read per triangle as well as per blade.
inline std::uint64_t drawnBladeTriangles(const std::array<std::size_t, LOD_COUNT>& drawnPerLod,
                                         int segments) {
    std::uint64_t triangles = 0;
    for (int lod = 0; lod < LOD_COUNT; ++lod)
        triangles += std::uint64_t(drawnPerLod[std::size_t(lod)]) *
                     std::uint64_t(stripBatchTriangles(lodSegments(segments, lod), lodFolded(lod)));
    return triangles;
}

// The index list of one batch at `segments` segments and the given fold: each blade b's
// triangles, its vertices numbered from b · stripVertexCount.
inline std::vector<std::uint32_t> stripBatchIndices(int segments, bool folded) {
    const int vertices = stripVertexCount(segments, folded);
    std::vector<std::uint32_t> indices;
    indices.reserve(std::size_t(3 * STRIP_BATCH_BLADES * stripBatchTriangles(segments, folded)));
    for (int blade = 0; blade < STRIP_BATCH_BLADES; ++blade) {
        const auto first = std::uint32_t(blade * vertices);
        for (int i = 0; i + 2 < vertices; ++i) {
            // A folded strip turns at the tip: triangles 2s and 2s + 1 lie on the tip's row.
            if (folded && (i == 2 * segments || i == 2 * segments + 1))
                continue;
            // GL_TRIANGLE_STRIP's triangle i: (i, i+1, i+2) when i is even, (i+1, i, i+2) when
            // odd, so that every triangle keeps the first one's winding.
            const std::uint32_t a = first + std::uint32_t(i);
            const bool odd = (i & 1) != 0;
            indices.insert(indices.end(), {odd ? a + 1 : a, odd ? a : a + 1, a + 2});
        }
    }
    return indices;
}

// The batch commands at `segments`, with no instances yet: LOD k draws its index list, which
// follows LOD k − 1's in the element buffer (stripBatchElements).
inline StripBatchCommands emptyStripBatchCommands(int segments) {
    StripBatchCommands commands{};
    std::uint32_t first = 0;
    for (int lod = 0; lod < LOD_COUNT; ++lod) {
        const auto count =
            std::uint32_t(3 * STRIP_BATCH_BLADES *
                          stripBatchTriangles(lodSegments(segments, lod), lodFolded(lod)));
        commands[std::size_t(lod)] = {count, 0, first, 0, 0};
        commands[std::size_t(LOD_COUNT + lod)] = commands[std::size_t(lod)];
        first += count;
    }
    return commands;
}

// The element buffer of a layer's strip batches at `segments`: every LOD's index list, LOD 0's
// first.
inline std::vector<std::uint32_t> stripBatchElements(int segments) {
    std::vector<std::uint32_t> elements;
    for (int lod = 0; lod < LOD_COUNT; ++lod) {
        const std::vector<std::uint32_t> indices =
            stripBatchIndices(lodSegments(segments, lod), lodFolded(lod));
        elements.insert(elements.end(), indices.begin(), indices.end());
    }
    return elements;
}

// The command buffer before the cull pass (emptyBladeDrawCommands, then the batches').
inline BladeCommandBuffer emptyBladeCommandBuffer(int segments) {
    return {emptyBladeDrawCommands(segments), emptyStripBatchCommands(segments)};
}

}  // namespace grass::core
