#include "render/cull_pass.h"

#include <algorithm>
#include <array>
#include <cstdint>

#include "gl/scoped_framebuffer.h"
#include "util/assert.h"
#include "util/blade_pass_group.h"
#include "util/dispatch_grid.h"

namespace grass::render {

namespace {
constexpr std::uint32_t COUNTER_BINDING = 7;
constexpr std::size_t COUNTER_COUNT = 8;
}  // namespace

Result<CullPass> CullPass::create() {
    const Result<std::uint32_t> groupSize = core::bladePassGroupSizeFromEnvironment();
    if (!groupSize)
        return groupSize.error();
    return create(*groupSize);
}

Result<CullPass> CullPass::create(std::uint32_t groupSize) {
    auto program = gl::Program::load({{GL_COMPUTE_SHADER, "cull.comp"}}, "blade cull",
                                     {core::cullGroupDefine(groupSize)});
    if (!program)
        return program.error();
    CullPass pass;
    pass.mGroupSize = groupSize;
    pass.mProgram = std::move(*program);
    const std::array<std::uint32_t, COUNTER_COUNT> zeros{};
    pass.mCounters = gl::Buffer(std::as_bytes(std::span(zeros)), "cull counters");
    return pass;
}

const gl::Program& CullPass::snowProgram() {
    return gl::loadOnFirstUse(mSnowProgram, [this] {
        return gl::Program::load({{GL_COMPUTE_SHADER, "cull.comp"}}, "blade cull (snow)",
                                 {"GRASS_SNOW", core::cullGroupDefine(mGroupSize)});
    });
}

// Occlusion depth: a single-sample depth texture of the framebuffer's size, which the frame's
// depth is resolved into, or a depth-only pre-pass of the opaque scene draws. The main
// framebuffer's depth is multisampled (and a renderbuffer), so it cannot be sampled directly;
// full resolution keeps the depth under a blade's root within a pixel of the root itself, so a
// small bias (cull.comp) keeps grass on visible terrain. A multisampled depth resolves to a
// value between its samples' nearest and farthest (GL 4.5 §18.3.1), as the pre-pass's pixel
// centre lies among them: at a silhouette either may hold the nearer surface.
void CullPass::resizeDepth(int width, int height) {
    if (width != mDepth.width || height != mDepth.height)
        mDepth = gl::makeDepthTarget(width, height, "cull depth pre-pass");
}

void CullPass::run(std::vector<FieldGpu>& fields, const CullView& view,
                   const CullSettings& settings, const std::function<void()>& drawOpaque,
                   GLuint depthSource) {
    resizeDepth(std::max(view.width, 1), std::max(view.height, 1));
    if (settings.occlusion && depthSource != 0) {
        // Blits obey the scissor test; nothing else of the frame's state touches them.
        const GLboolean scissor = glIsEnabled(GL_SCISSOR_TEST);
        glDisable(GL_SCISSOR_TEST);
        glBlitNamedFramebuffer(depthSource, mDepth.framebuffer.id(), 0, 0, mDepth.width,
                               mDepth.height, 0, 0, mDepth.width, mDepth.height,
                               GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        if (scissor == GL_TRUE)
            glEnable(GL_SCISSOR_TEST);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    } else if (settings.occlusion) {
        const float clearDepth = 1.0f;
        glClearNamedFramebufferfv(mDepth.framebuffer.id(), GL_DEPTH, 0, &clearDepth);
        {
            const gl::ScopedFramebuffer depthPass(mDepth.framebuffer, mDepth.width, mDepth.height);
            drawOpaque();
        }
        // The frame goes on in the view's viewport, whatever the caller had set.
        glViewport(0, 0, view.width, view.height);
        // The compute shader samples what the pre-pass wrote.
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    const gl::Program& program = settings.snow ? snowProgram() : mProgram;
    mStatsValid = settings.collectStats;
    if (settings.collectStats) {
        const std::uint32_t zero = 0;
        glClearNamedBufferData(mCounters.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    }
    program.use();
    program.set("uViewProj", view.projection * view.view);
    program.set("uCameraPosition", view.cameraPosition);
    program.set("uProj22", view.projection[2][2]);
    program.set("uProj32", view.projection[3][2]);
    program.set("uTestPatch", settings.frustum ? 1 : 0);
    program.set("uTestOrientation", settings.orientation ? 1 : 0);
    program.set("uTestFrustum", settings.frustum ? 1 : 0);
    program.set("uTestDistance", settings.distance && settings.maxDistanceM > 0.0f ? 1 : 0);
    program.set("uTestOcclusion", settings.occlusion ? 1 : 0);
    program.set("uDistanceClasses", std::max(settings.distanceClasses, 1));
    program.set("uMaxDistance", std::max(settings.maxDistanceM, 1e-3f));
    program.set("uCutoffDistance", std::max(settings.cutoffDistanceM, 0.0f));
    program.set("uKeepEvery", std::max(settings.keepEvery, 1));
    program.set("uLodDistance", std::max(settings.lodDistanceM, 0.0f));
    program.set("uLodBlend", settings.lodBlend);
    program.set("uCollectStats", settings.collectStats ? 1 : 0);
    program.set("uSceneDepth", 0);
    glBindTextureUnit(0, mDepth.texture.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, COUNTER_BINDING, mCounters.id());
    for (FieldGpu& field : fields) {
        field.resetCommands(view.stripSegments);
        if (field.bladeCount() == 0)
            continue;
        field.bindForCull();
        program.set("uBladeCount", static_cast<unsigned>(field.bladeCount()));
        program.set("uPatchSize", std::max(field.patchSize(), 1u));
        const core::DispatchGrid grid = core::dispatchGrid(field.bladeCount(), mGroupSize);
        glDispatchCompute(grid.x, grid.y, 1);
    }
    glBindTextureUnit(0, 0);
    // The draws read the commands (indirect) and the visible lists and tip snow (texel fetches)
    // the dispatch wrote.
    // Statistics are read with glGetNamedBufferSubData: that needs the buffer-update bit.
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_SHADER_STORAGE_BARRIER_BIT |
                    (settings.collectStats ? GL_BUFFER_UPDATE_BARRIER_BIT : 0u));
}

CullStats CullPass::readStats(const std::vector<FieldGpu>& fields) const {
    CullStats stats;
    if (!mStatsValid)
        return stats;
    std::array<std::uint32_t, COUNTER_COUNT> counters{};
    glGetNamedBufferSubData(mCounters.id(), 0, sizeof counters, counters.data());
    stats.bladesIn = counters[0];
    stats.culledPatch = counters[1];
    stats.culledOrientation = counters[2];
    stats.culledFrustum = counters[3];
    stats.culledDistance = counters[4];
    stats.culledOcclusion = counters[5];
    stats.culledSnow = counters[6];
    for (const FieldGpu& field : fields) {
        const core::BladeCommandBuffer commands = field.readCommands();
        for (int lod = 0; lod < LOD_COUNT; ++lod) {
            const std::size_t drawn = core::drawnAtLod(commands.draws, lod);
            stats.drawnPerLod[lod] += drawn;
            stats.drawn += drawn;
            stats.blendingPerLod[lod] += core::blendingAtLod(commands.draws, lod);
        }
        for (std::size_t drawClass = 0; drawClass < commands.stripBatches.size(); ++drawClass)
            stats.stripBatches[drawClass] += commands.stripBatches[drawClass].instanceCount;
    }
    return stats;
}

}  // namespace grass::render
