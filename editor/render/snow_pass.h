// The snow depth pass (SPEC §11): the terrain and the props rendered orthographically along the
// snowfall into a depth texture of the project's map resolution, which the mesh shaders read to
// find where the sky reaches (shaders/include/snow.glsl). Runs only when snow is on.
#pragma once

#include <functional>

#include "gl/framebuffer.h"
#include "gl/gl_handle.h"
#include "gl/program.h"
#include "snow/snow.h"
#include "util/result.h"

namespace grass::render {

class SnowPass {
public:
    static Result<SnowPass> create();

    // Renders the depth map of `view` at `resolution`²; `draw(program)` draws every occluder
    // with the program's uModel set. Restores the framebuffer and viewport.
    void run(const core::OrthoSnowView& view, int resolution,
             const std::function<void(const gl::Program&)>& draw);
    // The uniforms of shaders/include/snow.glsl for `program`, the map on texture `unit`.
    void bind(const gl::Program& program, const core::SnowParams& params, float amountM,
              int unit) const;
    // The depth texture (depth / depthRange), for tests.
    GLuint depthTexture() const { return mDepth.texture.id(); }
    const core::OrthoSnowView& view() const { return mView; }

private:
    gl::Program mProgram;
    gl::DepthTarget mDepth;
    int mResolution = 0;
    core::OrthoSnowView mView;
};

}  // namespace grass::render
