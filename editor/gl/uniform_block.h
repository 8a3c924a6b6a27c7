// UniformBlock<Block>: the one uniform buffer that holds a std140 block, bound at Block::BINDING,
// the binding point the block's GLSL declaration names (layout(std140, binding = ...)). Uploaded
// once a frame, it serves every program drawn after it: values shared by many programs go up
// once instead of as uniforms set by name on each program.
//
// Block is the C++ mirror of the GLSL block; its header static_asserts size and offsets, and a
// GL test compares them with what the driver reports.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>

#include "gl/buffer.h"

namespace grass::gl {

template <class Block>
class UniformBlock {
    static_assert(std::is_trivially_copyable_v<Block>, "a uniform block is uploaded as bytes");
    static_assert(sizeof(Block) % 16 == 0, "a std140 block is a whole number of vec4");

public:
    // The buffer starts as a value-initialized Block; bound only by upload() or bind().
    explicit UniformBlock(std::string_view label) : mBuffer(bytesOf(Block{}), label) {}

    // Writes `block` and binds the buffer at Block::BINDING, where the following draws and
    // dispatches read it.
    void upload(const Block& block) {
        mBuffer.update(bytesOf(block));
        bind();
    }
    void bind() const { glBindBufferBase(GL_UNIFORM_BUFFER, Block::BINDING, mBuffer.id()); }

private:
    static std::span<const std::byte> bytesOf(const Block& block) {
        return std::as_bytes(std::span<const Block>(&block, 1));
    }
    Buffer mBuffer;
};

}  // namespace grass::gl
