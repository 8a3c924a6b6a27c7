#include "render/snow_pass.h"

#include "gl/scoped_framebuffer.h"
#include "snow/snow_drift.h"
#include "util/assert.h"

namespace grass::render {

Result<SnowPass> SnowPass::create() {
    auto program = gl::Program::load({{GL_VERTEX_SHADER, "snow_depth.vert"}}, "snow depth");
    if (!program)
        return program.error();
    SnowPass pass;
    pass.mProgram = std::move(*program);
    return pass;
}

void SnowPass::run(const core::OrthoSnowView& view, int resolution,
                   const std::function<void(const gl::Program&)>& draw) {
    mDrawn.reset();
    run(view, resolution, Occluders{}, draw);
    mDrawn.reset();
}

bool SnowPass::run(const core::OrthoSnowView& view, int resolution, const Occluders& occluders,
                   const std::function<void(const gl::Program&)>& draw) {
    if (resolution == mResolution && view == mView && mDrawn == occluders) {
        mViewBlock.upload(snowViewBlock(view, resolution));
        return false;
    }
    if (resolution != mResolution) {
        mDepth = gl::makeDepthTarget(resolution, resolution, "snow depth map");
        mResolution = resolution;
    }
    mView = view;
    mDrawn = occluders;
    const float clearDepth = 1.0f;  // nothing above: every point is exposed
    glClearNamedFramebufferfv(mDepth.framebuffer.id(), GL_DEPTH, 0, &clearDepth);
    const gl::ScopedFramebuffer depthPass(mDepth.framebuffer, resolution, resolution);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // Texel-centre sampling, like core::renderSnowDepthMap: no multisampling.
    glDisable(GL_MULTISAMPLE);
    mViewBlock.upload(snowViewBlock(view, resolution));
    mProgram.use();
    draw(mProgram);
    glEnable(GL_MULTISAMPLE);
    return true;
}

bool SnowPass::bind(const core::SnowParams& params, float amountM) {
    const SnowBlock block = snowBlock(params, amountM, mView, mResolution);
    mSnowBlock.upload(block);
    mViewBlock.bind();
    glBindTextureUnit(SNOW_MAP_UNIT, mDepth.texture.id());
    if (!(block.drift > 0.0f))
        return false;
    computeDrift();
    return true;
}

void SnowPass::computeDrift() {
    const int cells = mResolution / core::SNOW_DRIFT_CELL_TEXELS;
    if (cells != mDriftCells) {
        mDrift = gl::makeTexture2D(GL_R32F, cells, cells, 1, "snow drift cells");
        gl::setClampedFiltering(mDrift, GL_NEAREST, GL_NEAREST);
        mDriftCells = cells;
    }
    if (!mDriftProgram) {
        auto program = gl::Program::load({{GL_COMPUTE_SHADER, "snow_drift.comp"}}, "snow drift");
        GRASS_ASSERT(program.ok());  // the shader ships with the program; a failure is a bug
        mDriftProgram = std::move(*program);
    }
    mDriftProgram->use();
    glBindImageTexture(0, mDrift.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    const GLuint groups = static_cast<GLuint>((cells + 7) / 8);
    glDispatchCompute(groups, groups, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindTextureUnit(SNOW_DRIFT_UNIT, mDrift.id());
}

}  // namespace grass::render
