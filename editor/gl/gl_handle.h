// GlHandle: the one move-only owner of a GL name (STYLE.md §5). Each GL object kind is a
// GlHandle with its own deleter; created with DSA, deleted in the destructor, labelled for
// debuggers and GL debug output. Each handle that holds a name counts it (gl_object_count.h).
#pragma once

#include <epoxy/gl.h>

#include <string_view>
#include <utility>

#include "gl/gl_object_count.h"

namespace grass::gl {

template <class Traits>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : mId(id) {
        if (mId != 0)
            countGlObjectCreated(Traits::KIND);
    }
    ~GlHandle() {
        if (mId != 0) {
            Traits::destroy(mId);
            countGlObjectDeleted(Traits::KIND);
        }
    }
    GlHandle(GlHandle&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        std::swap(mId, other.mId);
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;

    GLuint id() const { return mId; }
    explicit operator bool() const { return mId != 0; }
    void setLabel(std::string_view label) {
        glObjectLabel(Traits::LABEL_KIND, mId, static_cast<GLsizei>(label.size()), label.data());
    }

private:
    GLuint mId = 0;
};

struct BufferTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::Buffer;
    static constexpr GLenum LABEL_KIND = GL_BUFFER;
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::VertexArray;
    static constexpr GLenum LABEL_KIND = GL_VERTEX_ARRAY;
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct TextureTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::Texture;
    static constexpr GLenum LABEL_KIND = GL_TEXTURE;
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::Framebuffer;
    static constexpr GLenum LABEL_KIND = GL_FRAMEBUFFER;
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct RenderbufferTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::Renderbuffer;
    static constexpr GLenum LABEL_KIND = GL_RENDERBUFFER;
    static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
struct ProgramTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::Program;
    static constexpr GLenum LABEL_KIND = GL_PROGRAM;
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct ShaderTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::Shader;
    static constexpr GLenum LABEL_KIND = GL_SHADER;
    static void destroy(GLuint id) { glDeleteShader(id); }
};
struct QueryTraits {
    static constexpr GlObjectKind KIND = GlObjectKind::Query;
    static constexpr GLenum LABEL_KIND = GL_QUERY;
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

using VertexArrayHandle = GlHandle<VertexArrayTraits>;
using TextureHandle = GlHandle<TextureTraits>;
using FramebufferHandle = GlHandle<FramebufferTraits>;
using RenderbufferHandle = GlHandle<RenderbufferTraits>;
using ProgramHandle = GlHandle<ProgramTraits>;
using ShaderHandle = GlHandle<ShaderTraits>;
using QueryHandle = GlHandle<QueryTraits>;

}  // namespace grass::gl
