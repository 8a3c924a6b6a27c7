#include "render/snow_pass.h"

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
    GLint previousFramebuffer = 0;
    GLint previousViewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_VIEWPORT, previousViewport);
    const float clearDepth = 1.0f;  // nothing above: every point is exposed
    glClearNamedFramebufferfv(mDepth.framebuffer.id(), GL_DEPTH, 0, &clearDepth);
    glBindFramebuffer(GL_FRAMEBUFFER, mDepth.framebuffer.id());
    glViewport(0, 0, resolution, resolution);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // Texel-centre sampling, like core::renderSnowDepthMap: no multisampling.
    glDisable(GL_MULTISAMPLE);
    mViewBlock.upload(snowViewBlock(view, resolution));
    mProgram.use();
    draw(mProgram);
    glEnable(GL_MULTISAMPLE);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer));
    glViewport(previousViewport[0], previousViewport[1], previousViewport[2], previousViewport[3]);
}

void SnowPass::bind(const core::SnowParams& params, float amountM) {
    mSnowBlock.upload(snowBlock(params, amountM, mView, mResolution));
    mViewBlock.bind();
    glBindTextureUnit(SNOW_MAP_UNIT, mDepth.texture.id());
}

}  // namespace grass::render
