// GlRef: a typed view of a GL object that another object owns (a GlHandle, a gl::Buffer, a
// gl::Framebuffer), for code that uses an object without taking it: physics steps the blade
// buffers the scene renderer owns, a test reads the snow pass's depth texture. A view never
// deletes, so its owner must outlive every use. The type keeps a texture from going where a
// buffer is wanted, which a bare GLuint cannot (STYLE.md §7, as bgfx's typed handles).
#pragma once

#include "gl/gl_handle.h"

namespace grass::gl {

template <class Traits>
class GlRef {
public:
    GlRef() = default;  // no object
    // Implicit, as std::string_view from std::string: a view of what the owner holds.
    GlRef(const GlHandle<Traits>& owner) : mId(owner.id()) {}
    // A name no wrapper owns; prefer passing the owner.
    explicit GlRef(GLuint id) : mId(id) {}

    GLuint id() const { return mId; }
    explicit operator bool() const { return mId != 0; }
    bool operator==(const GlRef&) const = default;

private:
    GLuint mId = 0;
};

using BufferRef = GlRef<BufferTraits>;
using TextureRef = GlRef<TextureTraits>;

// The framebuffer a pass draws into: a gl::Framebuffer converts to it, and the window's default
// framebuffer, which no wrapper owns (the window toolkit made it), is FramebufferRef::window().
class FramebufferRef : public GlRef<FramebufferTraits> {
public:
    using GlRef::GlRef;
    static FramebufferRef window() { return FramebufferRef(GLuint{0}); }
};

}  // namespace grass::gl
