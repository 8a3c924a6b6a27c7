#include "gl/framebuffer.h"

#include <algorithm>
#include <cstring>

#include "gl/texture.h"

namespace grass::gl {

namespace {

RenderbufferHandle makeRenderbuffer(GLenum format, int width, int height, int samples) {
    GLuint id = 0;
    glCreateRenderbuffers(1, &id);
    if (samples > 1)
        glNamedRenderbufferStorageMultisample(id, samples, format, width, height);
    else
        glNamedRenderbufferStorage(id, format, width, height);
    return RenderbufferHandle(id);
}

FramebufferHandle makeFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return FramebufferHandle(id);
}

}  // namespace

int Framebuffer::samplesFor(int asked) {
    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    return std::clamp(asked, 1, std::max(maxSamples, 1));
}

Framebuffer::Framebuffer(int width, int height, int samples)
    : mWidth(width), mHeight(height), mSamples(samplesFor(samples)) {
    mFramebuffer = makeFramebuffer();
    mColor = makeRenderbuffer(GL_RGBA8, width, height, mSamples);
    mDepth = makeRenderbuffer(GL_DEPTH_COMPONENT32F, width, height, mSamples);
    glNamedFramebufferRenderbuffer(mFramebuffer.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                   mColor.id());
    glNamedFramebufferRenderbuffer(mFramebuffer.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                   mDepth.id());
    mFramebuffer.setLabel("scene framebuffer");
    mResolve = makeFramebuffer();
    mResolveColor = makeRenderbuffer(GL_RGBA8, width, height, 1);
    glNamedFramebufferRenderbuffer(mResolve.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                   mResolveColor.id());
    mResolve.setLabel("resolve framebuffer");
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, mFramebuffer.id());
    glViewport(0, 0, mWidth, mHeight);
}

void Framebuffer::blitTo(GLuint target, int targetWidth, int targetHeight) const {
    const bool sameSize = targetWidth == mWidth && targetHeight == mHeight;
    if (mSamples > 1 && !sameSize) {
        // A multisampled blit cannot scale: resolve first, then scale from the resolve target.
        glBlitNamedFramebuffer(mFramebuffer.id(), mResolve.id(), 0, 0, mWidth, mHeight, 0, 0,
                               mWidth, mHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBlitNamedFramebuffer(mResolve.id(), target, 0, 0, mWidth, mHeight, 0, 0, targetWidth,
                               targetHeight, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        return;
    }
    glBlitNamedFramebuffer(mFramebuffer.id(), target, 0, 0, mWidth, mHeight, 0, 0, targetWidth,
                           targetHeight, GL_COLOR_BUFFER_BIT, sameSize ? GL_NEAREST : GL_LINEAR);
}

Rgba8Image Framebuffer::readPixels() const {
    glBlitNamedFramebuffer(mFramebuffer.id(), mResolve.id(), 0, 0, mWidth, mHeight, 0, 0, mWidth,
                           mHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    return readFramebuffer(mResolve.id(), mWidth, mHeight);
}

Rgba8Image readFramebuffer(GLuint framebuffer, int width, int height) {
    Rgba8Image image;
    image.width = width;
    image.height = height;
    const auto rowBytes = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> bottomUp(rowBytes * static_cast<std::size_t>(height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    image.pixels.resize(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::memcpy(image.pixels.data() + static_cast<std::size_t>(y) * rowBytes,
                    bottomUp.data() + static_cast<std::size_t>(height - 1 - y) * rowBytes,
                    rowBytes);
    return image;
}

DepthTarget makeDepthTarget(int width, int height, const std::string& label) {
    DepthTarget target;
    target.texture = makeTexture2D(GL_DEPTH_COMPONENT32F, width, height, 1, label);
    setClampedFiltering(target.texture, GL_NEAREST, GL_NEAREST);
    glTextureParameteri(target.texture.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    target.framebuffer = makeFramebuffer();
    target.framebuffer.setLabel(label);
    glNamedFramebufferTexture(target.framebuffer.id(), GL_DEPTH_ATTACHMENT, target.texture.id(), 0);
    glNamedFramebufferDrawBuffer(target.framebuffer.id(), GL_NONE);
    target.width = width;
    target.height = height;
    return target;
}

}  // namespace grass::gl
