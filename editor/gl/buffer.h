// Buffer: an immutable-storage GL buffer (glNamedBufferStorage) owned by one object.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "gl/gl_handle.h"
#include "gl/gl_ref.h"

namespace grass::gl {

class Buffer {
public:
    Buffer() = default;
    // DYNAMIC_STORAGE so later passes may update sub-ranges with glNamedBufferSubData.
    Buffer(std::span<const std::byte> data, std::string_view label,
           GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
    template <class T>
    static Buffer fromVector(const std::vector<T>& values, std::string_view label,
                             GLbitfield flags = GL_DYNAMIC_STORAGE_BIT) {
        return Buffer(std::as_bytes(std::span<const T>(values)), label, flags);
    }

    GLuint id() const { return mHandle.id(); }
    // A view for code that uses the buffer without owning it.
    operator BufferRef() const { return BufferRef(mHandle); }
    std::size_t size() const { return mSize; }
    void update(std::span<const std::byte> data, std::size_t offset = 0);
    std::vector<std::byte> read(std::size_t offset, std::size_t size) const;

private:
    GlHandle<BufferTraits> mHandle;
    std::size_t mSize = 0;
};

}  // namespace grass::gl
