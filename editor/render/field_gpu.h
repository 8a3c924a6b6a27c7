// FieldGpu: one grass layer's blades on the GPU: the blade buffer (four vec4 per blade,
// SPEC §1, bound as SSBO 0), the patch boxes (SSBO 1: min, max vec4 per patch), and per level of
// detail a visible-index list (SSBO 5, one list of bladeCount entries per LOD) and two indirect
// draw commands (strips, then tessellation patches) that the cull pass (SPEC §6, cull_pass.h)
// fills each frame. Draws by either geometry path, one indirect draw per LOD.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "blade/blade_draw_commands.h"
#include "blade/strip_batch.h"
#include "scene/scene.h"

namespace grass::render {

// The draw commands and LODs are core's (core/blade/blade_draw_commands.h), shared with the
// reference runtime.
using core::DrawArraysIndirectCommand;
using core::LOD_COUNT;
using core::lodSegments;
using core::stripVertexCount;

enum class GeometryPath { Tessellation, Strips };

// The program each level of detail is drawn with (near blades lit per pixel, far ones per
// vertex: RenderOptions::pixelLitLods), at [lod] for the blades before the LOD's morph band and
// at [LOD_COUNT + lod] for those in it (the variant that blends: core::lodBlending); several
// entries may share one program.
using BladePrograms = std::array<const gl::Program*, 2 * LOD_COUNT>;


// SSBO bindings of shaders/cull.comp; the draw stages read the same buffers as buffer textures
// (core::BLADE_TEXELS_UNIT and the units after it, shaders/include/blade_texels.glsl).
inline constexpr std::uint32_t PATCH_BOUNDS_BINDING = 1;
inline constexpr std::uint32_t VISIBLE_BINDING = 5;
inline constexpr std::uint32_t COMMAND_BINDING = 6;
// shaders/cull.comp writes snow on each blade's tip; shaders/include/blade_shade.glsl reads it.
inline constexpr std::uint32_t TIP_SNOW_BINDING = 10;

class FieldGpu {
public:
    explicit FieldGpu(const core::LayerField& field);
    const core::LayerField& field() const { return *mField; }
    // Blade slots, padding included (a whole number of patches).
    std::size_t bladeCount() const { return mBladeCount; }
    std::uint32_t patchSize() const { return mField->patched.patchSize; }
    const gl::Buffer& bladeBuffer() const { return mBlades; }

    // Replaces every blade slot (the CPU physics' state); `blades` has bladeCount() slots.
    void uploadBlades(std::span<const core::Blade> blades);
    // Re-uploads the blades (and, when `withShading`, the shading) of these patches from the
    // layer after core::regrowLayerRegion changed them; the rest of the buffers stay.
    void uploadPatches(std::span<const std::uint32_t> patches, bool withShading);

    // Before the cull dispatch: zero survivors and batches, each LOD's strip vertex count for
    // `segments`, and the strip batches' index lists for `segments` (built when they change).
    void resetCommands(int segments);
    // Snow: allocates the per-slot tip-whiteness buffer (once); from then on the cull and the
    // draws bind it. A field never drawn with snow has none.
    void enableTipSnow();
    // The tip whiteness of every slot as the last cull wrote it (empty without snow; tests).
    std::vector<float> readTipSnow() const;
    bool hasTipSnow() const { return mTipSnow.id() != 0; }
    // The visible lists as the last cull left them: LOD_COUNT lists of bladeCount() slots, LOD
    // k's survivors from k·bladeCount() on, its blending ones backwards from its list's end
    // (shaders/cull.comp); slots no survivor took hold what was there before (tests).
    std::vector<std::uint32_t> readVisible() const;
    // Binds the blades' texel view and the patch-box, visible and command buffers for the cull
    // dispatch.
    void bindForCull() const;
    // The indirect draw commands as the last cull pass left them, the per-LOD ones and the strip
    // batches' (one read-back, for statistics).
    core::BladeCommandBuffer readCommands() const;

    // Binds the blade and visible buffers and issues one indirect draw per LOD; the caller has
    // bound `program` and run the cull pass. Sets uVisibleOffset (and, for strips, uSegments).
    // The strips are drawn in batches (core/blade/strip_batch.h) at the segments of the last
    // resetCommands, which its commands and index lists were made for.
    void drawStrips(const BladePrograms& programs) const;
    void drawTessellated(const BladePrograms& programs) const;

private:
    void bindForDraw() const;
    void setVisibleList(const gl::Program& program, int lod, bool blending) const;
    const core::LayerField* mField;
    std::size_t mBladeCount = 0;
    gl::Buffer mBlades;
    gl::Buffer mShading;
    gl::Buffer mPatchBounds;
    gl::Buffer mVisible;
    gl::Buffer mCommands;
    gl::Buffer mTipSnow;
    gl::Buffer mStripElements;  // core::stripBatchElements(mStripElementSegments)
    int mStripElementSegments = 0;  // of the last resetCommands; 0: none yet
    // Texel views of mBlades, mVisible, mShading, mTipSnow and mCommands for the draw stages.
    gl::TextureHandle mBladeTexels, mVisibleTexels, mShadingTexels, mTipSnowTexels,
        mCommandTexels;
    // No vertex attributes (the blades are read from texels); the strips' element buffer.
    gl::VertexArray mEmptyVertexArray;
};

}  // namespace grass::render
