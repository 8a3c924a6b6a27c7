// CullPass: the per-blade GPU culling of SPEC §6 (Jahrmann §6). Each frame it draws the opaque
// terrain into its own depth texture (for the occlusion test), then runs shaders/cull.comp over
// every layer, which writes each layer's visible-index list and indirect draw commands. The
// draws follow without any CPU read-back; per-test counters are read only when asked.
// Distances are metres in world space.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "render/field_gpu.h"
#include "gl/framebuffer.h"
#include "gl/gl_handle.h"
#include "gl/program.h"

namespace grass::render {

struct CullSettings {
    // Stage 1 (patch boxes) runs with the frustum test: it is the same test, per patch.
    bool frustum = true;
    bool orientation = true;
    bool distance = true;
    bool occlusion = true;
    // Distance thinning: n classes, blade i kept while i mod n < ceil(n·(1 − d/dmax)). With
    // n = 8 the field thins in 12.5 % steps; 100 m keeps everything within 12.5 m whole and
    // a 20 m meadow seen from 20 m at 7/8 density, where the loss is hard to see.
    int distanceClasses = 8;
    float maxDistanceM = 100.0f;
    // Level of detail (SPEC §7, shaders/include/lod.glsl): full segments up to lodDistanceM,
    // half up to 3·lodDistanceM, a quarter beyond; 0 keeps every blade at full detail. Blades
    // 8 m away stand ~40 px tall at 720p (0.4 m, 45° field of view): 4 segments of 10 px
    // still follow the curve; measured in docs/rendering.md.
    float lodDistanceM = 8.0f;
    // lod.glsl's morph band (RenderOptions::lodBlend; the renderer copies it here): blades in it
    // are listed and drawn apart from their LOD's others (core::lodBlending).
    float lodBlend = core::LOD_BLEND;
    // Blades farther than this (measured like the thinning) are culled outright, counted as
    // distance; 0 = none. The hybrid technique sets it to the end of its cross-fade.
    float cutoffDistanceM = 0.0f;
    // Uniform thinning: only blade i with i mod keepEvery = 0 is drawn (the rest counted as
    // distance); 1 draws every blade. The editor's reduced picture while the user interacts
    // (core/quality/interaction_quality.h), never the project's own.
    int keepEvery = 1;
    // Count blades per test (statistics); costs a few atomics per work-group.
    bool collectStats = false;
    // Snow lies (SPEC §11): run the snow variant of the cull, which buries blades and writes the
    // tips' whiteness; its snow uniforms are set through snowProgram() before run().
    bool snow = false;
    bool anyEnabled() const { return frustum || orientation || distance || occlusion; }
    bool operator==(const CullSettings&) const = default;
};

// Blades of the last culled frame, summed over layers. in = drawn + Σ culled.
struct CullStats {
    std::size_t bladesIn = 0;  // live blades (padding is not counted)
    std::size_t culledPatch = 0;
    std::size_t culledOrientation = 0;
    std::size_t culledFrustum = 0;
    std::size_t culledDistance = 0;
    std::size_t culledOcclusion = 0;
    std::size_t culledSnow = 0;  // buried: shorter than the snow at the root (SPEC §11)
    std::size_t drawn = 0;
    std::array<std::size_t, LOD_COUNT> drawnPerLod{};  // sums to drawn
    // Of drawnPerLod, the blades in the LOD's morph band, drawn by the blending program
    // (core::lodBlending).
    std::array<std::size_t, LOD_COUNT> blendingPerLod{};
    // The strip batches each class is drawn in (core/blade/strip_batch.h): LOD k's blades before
    // its morph band at [k], those in it at [LOD_COUNT + k], summed over the fields.
    std::array<std::size_t, 2 * LOD_COUNT> stripBatches{};
    std::size_t culledTotal() const {
        return culledPatch + culledOrientation + culledFrustum + culledDistance + culledOcclusion +
               culledSnow;
    }
};

struct CullView {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    int width = 1;
    int height = 1;
    int stripSegments = 8;
};

class CullPass {
public:
    // Work groups of 32 invocations, or GRASS_COMPUTE_GROUP's (core/util/blade_pass_group.h).
    static Result<CullPass> create();
    // Work groups of `groupSize` (a multiple of 32 up to 256): the same blades culled, counted
    // and listed per level of detail whatever the size (only their order in a list differs).
    static Result<CullPass> create(std::uint32_t groupSize);
    std::uint32_t groupSize() const { return mGroupSize; }

    // The occlusion depth, then the cull dispatch for every field, ending with the barrier the
    // indirect draws need. The depth (only when occlusion culling is on): `depthSource`'s, a
    // framebuffer holding the opaque scene's depth already (the frame's own after its opaque
    // pass; 32-bit float depth, multisampled or not, at least the view's size), resolved into
    // the cull's texture; with none (0), a pre-pass: `drawOpaque` draws the opaque scene with
    // the bound framebuffer's state (depth test on). The pre-pass draws the scene a second
    // time: 250-300 ms of a frame for an 8.4-million-triangle ground on llvmpipe.
    void run(std::vector<FieldGpu>& fields, const CullView& view, const CullSettings& settings,
             const std::function<void()>& drawOpaque, GLuint depthSource = 0);
    // Counters of the last run(); zero unless it ran with collectStats. Waits for the GPU.
    CullStats readStats(const std::vector<FieldGpu>& fields) const;
    // The snow variant of the cull program (compiled on first use), for SnowPass::bind.
    const gl::Program& snowProgram();

private:
    void resizeDepth(int width, int height);
    gl::Program mProgram;
    gl::Program mSnowProgram;
    gl::Buffer mCounters;
    gl::DepthTarget mDepth;
    bool mStatsValid = false;
    std::uint32_t mGroupSize = 32;
};

}  // namespace grass::render
