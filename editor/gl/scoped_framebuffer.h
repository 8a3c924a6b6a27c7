// ScopedFramebuffer: draws into a target of its own for a scope, then binds again the draw
// framebuffer (as GL_FRAMEBUFFER, draw and read) and the viewport that were current. The passes
// that render mid-frame into their own targets (the snow depth map, the cull's occlusion
// pre-pass) hand the frame back as they found it.
#pragma once

#include "gl/gl_ref.h"

namespace grass::gl {

class ScopedFramebuffer {
public:
    // Binds `target` and sets the viewport to width × height.
    ScopedFramebuffer(FramebufferRef target, int width, int height);
    ~ScopedFramebuffer();
    ScopedFramebuffer(const ScopedFramebuffer&) = delete;
    ScopedFramebuffer& operator=(const ScopedFramebuffer&) = delete;

private:
    FramebufferRef mPrevious;
    GLint mPreviousViewport[4] = {0, 0, 0, 0};
};

}  // namespace grass::gl
