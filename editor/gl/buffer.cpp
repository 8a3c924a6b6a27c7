#include "gl/buffer.h"

namespace grass::gl {

Buffer::Buffer(std::span<const std::byte> data, std::string_view label, GLbitfield flags) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    mHandle = GlHandle<BufferTraits>(id);
    mSize = data.size();
    // Zero-size storage is an error in GL; keep one byte so an empty field still binds.
    const std::size_t storage = data.empty() ? 1 : data.size();
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(storage), data.empty() ? nullptr : data.data(),
                         flags);
    mHandle.setLabel(label);
}

void Buffer::update(std::span<const std::byte> data, std::size_t offset) {
    glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(data.size()),
                         data.data());
}

std::vector<std::byte> Buffer::read(std::size_t offset, std::size_t size) const {
    std::vector<std::byte> out(size);
    glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(size),
                            out.data());
    return out;
}

}  // namespace grass::gl
