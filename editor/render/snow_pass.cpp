#include "render/snow_pass.h"

#include <algorithm>

namespace grass::render {

namespace {

void setView(const gl::Program& program, const core::OrthoSnowView& view) {
    program.set("uSnowOrigin", view.origin);
    program.set("uSnowRight", view.right);
    program.set("uSnowUpAxis", view.up);
    program.set("uSnowForward", view.forward);
    program.set("uSnowSizeM", view.sizeM);
    program.set("uSnowDepthRangeM", view.depthRangeM);
}

}  // namespace

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
    mProgram.use();
    setView(mProgram, view);
    draw(mProgram);
    glEnable(GL_MULTISAMPLE);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer));
    glViewport(previousViewport[0], previousViewport[1], previousViewport[2], previousViewport[3]);
}

void SnowPass::bind(const gl::Program& program, const core::SnowParams& params, float amountM,
                    int unit) const {
    program.set("uSnowEnabled", params.enabled != 0u && mResolution > 0 ? 1 : 0);
    program.set("uSnowAmountM", amountM);
    program.set("uSnowColor", params.snowColor);
    program.set("uSnowUp", core::snowUp(params));
    program.set("uSnowOctaves", params.noiseOctaves);
    program.set("uSnowNoiseA", params.noiseAmplitude);
    program.set("uSnowNoiseB", params.noiseFrequency);
    program.set("uSnowNoiseScaleM", params.noiseScaleM);
    program.set("uSnowInclineNoise", params.inclineNoise);
    program.set("uSnowSamples", params.samples);
    program.set("uSnowRadiusTexels", params.sampleRadiusTexels);
    const float texelM = mView.sizeM / float(std::max(mResolution, 1));
    program.set("uSnowBoundaryRadiusTexels",
                std::max(params.sampleRadiusTexels, params.boundaryFalloffM / texelM));
    program.set("uSnowBiasM", params.depthBiasM);
    program.set("uSnowResolution", mResolution);
    setView(program, mView);
    glBindTextureUnit(GLuint(unit), mDepth.texture.id());
    program.set("uSnowDepth", unit);
}

}  // namespace grass::render
