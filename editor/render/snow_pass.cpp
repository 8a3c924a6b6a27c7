#include "render/snow_pass.h"

#include "gl/scoped_framebuffer.h"

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
    if (resolution != mResolution) {
        mDepth = gl::makeDepthTarget(resolution, resolution, "snow depth map");
        mResolution = resolution;
    }
    mView = view;
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
}

void SnowPass::bind(const core::SnowParams& params, float amountM) {
    mSnowBlock.upload(snowBlock(params, amountM, mView, mResolution));
    mViewBlock.bind();
    glBindTextureUnit(SNOW_MAP_UNIT, mDepth.texture.id());
}

}  // namespace grass::render
