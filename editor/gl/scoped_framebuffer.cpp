#include "gl/scoped_framebuffer.h"

namespace grass::gl {

ScopedFramebuffer::ScopedFramebuffer(FramebufferRef target, int width, int height) {
    GLint previous = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
    mPrevious = FramebufferRef(static_cast<GLuint>(previous));
    glGetIntegerv(GL_VIEWPORT, mPreviousViewport);
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, width, height);
}

ScopedFramebuffer::~ScopedFramebuffer() {
    glBindFramebuffer(GL_FRAMEBUFFER, mPrevious.id());
    glViewport(mPreviousViewport[0], mPreviousViewport[1], mPreviousViewport[2],
               mPreviousViewport[3]);
}

}  // namespace grass::gl
