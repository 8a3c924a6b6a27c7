// The few GL objects the runtime needs, on plain GL 4.5 calls through libepoxy: programs built
// from the embedded shaders (with their #include lines expanded and defines added) and
// immutable-storage buffers. Moveable, not copyable; each deletes its object.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

namespace grass::runtime {

class GlProgram {
public:
    GlProgram() = default;
    // Stages as (GL stage, embedded shader name). On failure id() is 0 and `error` holds the log.
    GlProgram(const std::vector<std::pair<GLenum, std::string>>& stages,
              const std::vector<std::string>& defines, std::string& error);
    GlProgram(GlProgram&& other) noexcept;
    GlProgram& operator=(GlProgram&& other) noexcept;
    GlProgram(const GlProgram&) = delete;
    GlProgram& operator=(const GlProgram&) = delete;
    ~GlProgram();

    GLuint id() const { return mId; }
    void use() const { glUseProgram(mId); }
    // Uniforms by name; a name the compiler dropped is ignored, as GL does.
    void set(const char* name, int value) const;
    void set(const char* name, unsigned value) const;
    void set(const char* name, float value) const;
    void set(const char* name, glm::vec2 value) const;
    void set(const char* name, glm::vec3 value) const;
    void set(const char* name, const glm::mat4& value) const;

private:
    GLuint mId = 0;
};

class GlBuffer {
public:
    GlBuffer() = default;
    // Storage of `bytes` (at least 4 bytes, so that an empty list can still be bound), updatable.
    explicit GlBuffer(std::span<const std::byte> bytes);
    template <class T>
    static GlBuffer of(const std::vector<T>& values) {
        return GlBuffer(std::as_bytes(std::span<const T>(values)));
    }
    GlBuffer(GlBuffer&& other) noexcept;
    GlBuffer& operator=(GlBuffer&& other) noexcept;
    GlBuffer(const GlBuffer&) = delete;
    GlBuffer& operator=(const GlBuffer&) = delete;
    ~GlBuffer();

    GLuint id() const { return mId; }
    std::size_t size() const { return mSize; }
    // Replaces the contents when the size matches, else makes new storage.
    template <class T>
    void assign(const std::vector<T>& values) {
        const auto bytes = std::as_bytes(std::span<const T>(values));
        if (mId != 0 && bytes.size() == mSize)
            glNamedBufferSubData(mId, 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
        else
            *this = GlBuffer(bytes);
    }
    void bindStorage(GLuint binding) const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, mId); }

private:
    GLuint mId = 0;
    std::size_t mSize = 0;
};

// A buffer texture over all of a GlBuffer, texels of `internalFormat`: the draw stages read the
// blades, visible lists and shading through these (shaders/include/blade_texels.glsl). The
// buffer must outlive the view.
class GlTexelView {
public:
    GlTexelView() = default;
    GlTexelView(const GlBuffer& buffer, GLenum internalFormat);
    GlTexelView(GlTexelView&& other) noexcept;
    GlTexelView& operator=(GlTexelView&& other) noexcept;
    GlTexelView(const GlTexelView&) = delete;
    GlTexelView& operator=(const GlTexelView&) = delete;
    ~GlTexelView();

    void bind(GLuint unit) const { glBindTextureUnit(unit, mId); }

private:
    GLuint mId = 0;
};

}  // namespace grass::runtime
