// The levels of detail of the blades and the indirect draw commands the cull pass fills
// (shaders/include/lod.glsl, shaders/cull.comp), GL-free and header-only so the editor's
// renderer (render/field_gpu.h) and the reference runtime (editor/runtime) lay them out alike.
// Per layer: one command per LOD for the strips, then one per LOD for the tessellation patches;
// the cull pass writes each one's instance count (the strips' is the LOD's survivors: they are
// drawn in batches by the commands that follow, core/blade/strip_batch.h; the patches' is the
// LOD's batches of PATCH_BATCH_BLADES patches).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace grass::core {

// LOD_COUNT in shaders/include/lod.glsl: LOD k draws max(segments >> k, 1) segments.
inline constexpr int LOD_COUNT = 3;

// How many LODs, from the nearest, are lit per pixel; the rest are lit per vertex
// (shaders/blade.frag, GRASS_LIGHT_PER_VERTEX). By default the near blades keep per-pixel light
// and the blades beyond the LOD distance, a few pixels wide, are lit per vertex. A software
// rasterizer drawing multisampled lights every blade per vertex: there per-pixel shading of the
// samples was the dearest stage of the grass pass (projects/nature at 4× MSAA on llvmpipe, one
// run: grass pass 1.28 s per pixel, 0.62 s per vertex), and the pictures differ by less than the
// golden tolerance (no pixel of projects/nature beyond 48 levels, mean 0.07; docs/rendering.md).
// Without multisampling the vertex work, on one thread there, costs more than the pixels
// (every blade of projects/nature in full: 1.09 s per pixel, 1.72 s per vertex).
inline constexpr int DEFAULT_PIXEL_LIT_LODS = 1;

inline int defaultPixelLitLods(bool softwareRenderer, int samplesPerPixel) {
    return softwareRenderer && samplesPerPixel > 1 ? 0 : DEFAULT_PIXEL_LIT_LODS;
}

inline int lodSegments(int fullSegments, int lod) {
    return std::max(fullSegments >> lod, 1);
}

// lod.glsl's bladeLod: LOD 0 up to lodDistance, LOD 1 up to 3·lodDistance, LOD 2 beyond;
// lodDistance ≤ 0 keeps every blade at LOD 0.
inline int bladeLod(float distance, float lodDistance) {
    if (lodDistance <= 0.0f || distance < lodDistance)
        return 0;
    return distance < 3.0f * lodDistance ? 1 : 2;
}

// LOD_BLEND in lod.glsl: the share of each LOD's distance range over which its blades morph
// into the next LOD's shape. A quarter keeps the morphing blades (three surface evaluations a
// vertex instead of one) a small part of the field, and is wide enough that a blade crossing
// it moves by a fraction of a pixel a frame at walking speed.
inline constexpr float LOD_BLEND = 0.25f;

// lod.glsl's lodMorph (continuous level of detail, issue 30 item 12): how far a blade of LOD
// `lod` at `distance` has morphed towards LOD lod + 1, rising linearly from 0 to 1 over the last
// `blend` share of its range ([0, d) for LOD 0, [d, 3d) for LOD 1), so that at the switch the
// two LODs draw the same surface. 0 for the last LOD, without LODs and with blend ≤ 0.
inline float lodMorph(float distance, float lodDistance, int lod, float blend) {
    if (lodDistance <= 0.0f || blend <= 0.0f || lod >= LOD_COUNT - 1)
        return 0.0f;
    const float start = lod == 0 ? 0.0f : lodDistance;
    const float end = lod == 0 ? lodDistance : 3.0f * lodDistance;
    const float band = std::min(blend, 1.0f) * (end - start);
    return std::clamp((distance - (end - band)) / band, 0.0f, 1.0f);
}

// FOLDED_LODS in shaders/include/lod.glsl: the LODs, from the nearest, whose blades keep a
// vertex column on the midrib so the V fold of SPEC §7 shows. Beyond the LOD distance a blade is
// a few pixels wide and the fold cannot be seen; the two edges alone draw it with half the
// triangles (the strips and the tessellation alike). On llvmpipe the grass pass of nature-100k
// is bound by triangle setup and rasterization, not by its fragments (docs/rendering.md).
inline constexpr int FOLDED_LODS = 1;

inline bool lodFolded(int lod) {
    return lod < FOLDED_LODS;
}

// Vertices of one instanced strip of `segments` segments (blade_strip.vert). Folded: the left
// half (u = 0, ½) up the blade, then the right half (u = 1, ½) down, so the midrib is a vertex
// column. Not folded: the two edges (u = 0, 1) up the blade.
inline int stripVertexCount(int segments, bool folded) {
    return (folded ? 4 : 2) * (segments + 1);
}

// Texture units of the buffer textures the blade draw stages read (shaders/include/
// blade_texels.glsl; texelFetch is far cheaper than an SSBO load on software GL): the blades
// (4 RGBA32F texels a slot), the visible lists (R32UI), the baked shading (2 RGBA32F texels a
// slot), the tip snow (R32F). Above the units the editor's other passes use (0, 5, 6).
inline constexpr unsigned BLADE_TEXELS_UNIT = 8;
inline constexpr unsigned VISIBLE_TEXELS_UNIT = 9;
inline constexpr unsigned SHADING_TEXELS_UNIT = 10;
inline constexpr unsigned TIP_SNOW_TEXELS_UNIT = 11;
// The command buffer as 32-bit words (R32UI): the strip batches read their survivors there
// (core/blade/strip_batch.h). Units 12 and 13 hold the snow drift map and the sun's shadow map.
inline constexpr unsigned COMMAND_TEXELS_UNIT = 14;

// Matches GL's DrawArraysIndirectCommand.
struct DrawArraysIndirectCommand {
    std::uint32_t count;
    std::uint32_t instanceCount;
    std::uint32_t first;
    std::uint32_t baseInstance;
};
static_assert(sizeof(DrawArraysIndirectCommand) == 16);

// A LOD's blades in its morph band (lodMorph > 0: they blend towards the next LOD's shape) are
// drawn apart from the others, by a program variant that holds the blend (GRASS_LOD_BLEND,
// blade_lod_blend.glsl); the others by one without it. Software GL runs the blend's extra
// surface evaluations and shadings for every vertex of a program that holds it, whatever the
// blade (nature-100k on llvmpipe: ~20 % of the grass pass), and three quarters of a LOD's blades
// lie before its band. The cull pass sorts them (shaders/cull.comp): a LOD's visible list takes
// the others from its start and the blending ones from its end, backwards.
inline bool lodBlending(float distance, float lodDistance, int lod, float blend) {
    return lodMorph(distance, lodDistance, lod, blend) > 0.0f;
}

// Per LOD k: its strips at [k], its patches at [LOD_COUNT + k], then the same for its blades in
// the morph band at [2·LOD_COUNT + k] and [3·LOD_COUNT + k].
using BladeDrawCommands = std::array<DrawArraysIndirectCommand, 4 * LOD_COUNT>;

// Byte offsets in the command buffer.
inline std::size_t stripCommandOffset(int lod, bool blending = false) {
    return std::size_t((blending ? 2 * LOD_COUNT : 0) + lod) * sizeof(DrawArraysIndirectCommand);
}
inline std::size_t patchCommandOffset(int lod, bool blending = false) {
    return std::size_t((blending ? 3 * LOD_COUNT : LOD_COUNT) + lod) *
           sizeof(DrawArraysIndirectCommand);
}

// Where a draw reads its blades in the visible lists of a layer of `slots` blade slots
// (shaders/cull.comp writes them): LOD k's list spans [k·slots, (k + 1)·slots); its blades before
// the morph band from the start forwards, those in it from the last entry backwards.
inline std::size_t visibleListStart(int lod, std::size_t slots, bool blending) {
    const std::size_t first = std::size_t(lod) * slots;
    return blending ? first + slots - 1 : first;
}

// Blades drawn at `lod` in its morph band, and blending or not (the strips' and the patches'
// counts are the same).
inline std::uint32_t blendingAtLod(const BladeDrawCommands& commands, int lod) {
    return commands[stripCommandOffset(lod, true) / sizeof(DrawArraysIndirectCommand)]
        .instanceCount;
}
inline std::uint32_t drawnAtLod(const BladeDrawCommands& commands, int lod) {
    return commands[stripCommandOffset(lod) / sizeof(DrawArraysIndirectCommand)].instanceCount +
           blendingAtLod(commands, lod);
}

// The tessellation path draws a LOD's blades in batches of PATCH_BATCH_BLADES single-vertex
// patches an instance (shaders/blade_tess.vert), as the strips are drawn 64 to an instance
// (core/blade/strip_batch.h), and for the same reason: an implementation pays for every instance
// (llvmpipe runs its vertex pipeline once per instance; a GPU starts a vertex batch per instance,
// and one instance per blade was ~40 ns a drawn blade on an H200 whatever its triangles). Not
// one list of all survivors: llvmpipe drew patch lists beyond ~10k patches wrongly (docs/
// rendering.md); 64 stay far below. The patches past the survivors in the last batch get
// tessellation level 0 and are discarded (blade.tesc).
inline constexpr int PATCH_BATCH_BLADES = 64;

// The commands before the cull pass: no instances; each LOD's strip vertex count for
// `segments`, one patch vertex per tessellated blade in batches of PATCH_BATCH_BLADES.
inline BladeDrawCommands emptyBladeDrawCommands(int segments) {
    BladeDrawCommands commands{};
    for (int lod = 0; lod < LOD_COUNT; ++lod) {
        const auto strip = static_cast<std::uint32_t>(
            stripVertexCount(lodSegments(segments, lod), lodFolded(lod)));
        commands[std::size_t(lod)] = {strip, 0, 0, 0};
        const auto patches = static_cast<std::uint32_t>(PATCH_BATCH_BLADES);
        commands[std::size_t(LOD_COUNT + lod)] = {patches, 0, 0, 0};
        commands[std::size_t(2 * LOD_COUNT + lod)] = {strip, 0, 0, 0};
        commands[std::size_t(3 * LOD_COUNT + lod)] = {patches, 0, 0, 0};
    }
    return commands;
}

}  // namespace grass::core
