// Framebuffer: an offscreen colour + depth target, optionally multisampled, with a resolve to
// RGBA8 pixels. The headless renderer draws here; the editor blits it to the window.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gl/gl_handle.h"
#include "gl/gl_ref.h"

namespace grass::gl {

// A depth-only target whose depth can be sampled (texelFetch, no comparison): the cull pass's
// occlusion pre-pass and the snow depth map.
struct DepthTarget {
    TextureHandle texture;
    FramebufferHandle framebuffer;
    int width = 0, height = 0;
};
// A 32-bit float depth texture of width × height, nearest filtering, clamped, attached to a
// framebuffer with no colour buffer; both labelled `label`.
DepthTarget makeDepthTarget(int width, int height, const std::string& label);

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // row 0 = TOP of the image, 4 bytes per pixel
};

class Framebuffer {
public:
    Framebuffer(int width, int height, int samples);
    GLuint id() const { return mFramebuffer.id(); }
    // A view for the passes that draw into it (render::SceneRenderer::render).
    operator FramebufferRef() const { return FramebufferRef(mFramebuffer); }
    int width() const { return mWidth; }
    int height() const { return mHeight; }
    int samples() const { return mSamples; }
    // The samples a framebuffer asked for `asked` gets: at least 1 (0 means none), at most the
    // driver's limit. A caller that keeps one compares against this, not what it asked for.
    static int samplesFor(int asked);
    // Whether this framebuffer is what Framebuffer(width, height, samples) would make.
    bool fits(int width, int height, int samples) const {
        return mWidth == width && mHeight == height && mSamples == samplesFor(samples);
    }
    void bind() const;
    // Resolves (if multisampled) and reads back the colour, flipped so row 0 is the top.
    Rgba8Image readPixels() const;
    // Resolves into another framebuffer (0 = the window's).
    void blitTo(GLuint target, int targetWidth, int targetHeight) const;

private:
    int mWidth, mHeight, mSamples;
    FramebufferHandle mFramebuffer;
    RenderbufferHandle mColor, mDepth;
    // Single-sampled resolve target for readback.
    FramebufferHandle mResolve;
    RenderbufferHandle mResolveColor;
};

// Reads the currently bound read framebuffer (e.g. the window's back buffer).
Rgba8Image readFramebuffer(GLuint framebuffer, int width, int height);

}  // namespace grass::gl
