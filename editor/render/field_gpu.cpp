#include "field_gpu.h"

#include <array>

#include <glm/glm.hpp>

namespace grass::render {

namespace {
constexpr GLintptr STRIP_COMMAND_OFFSET = 0;
constexpr GLintptr PATCH_COMMAND_OFFSET = sizeof(DrawArraysIndirectCommand);
}  // namespace

FieldGpu::FieldGpu(const core::LayerField& field) : mField(&field) {
    mBladeCount = field.patched.blades.size();
    mBlades = gl::Buffer::fromVector(field.patched.blades, "blades " + field.name);
    std::vector<glm::vec4> bounds;
    bounds.reserve(2 * field.patched.patches.size() + 2);
    for (const auto& patch : field.patched.patches) {
        bounds.emplace_back(patch.bounds.min, 0.0f);
        bounds.emplace_back(patch.bounds.max, 0.0f);
    }
    // Zero-sized buffers cannot be bound: keep one dummy box for an empty field.
    if (bounds.empty())
        bounds.resize(2, glm::vec4(0.0f));
    mPatchBounds = gl::Buffer::fromVector(bounds, "patch bounds " + field.name);
    const std::vector<GLuint> visible(std::max<std::size_t>(mBladeCount, 1), 0);
    mVisible = gl::Buffer::fromVector(visible, "visible blades " + field.name);
    const std::array<DrawArraysIndirectCommand, 2> commands{{{0, 0, 0, 0}, {0, 1, 0, 0}}};
    mCommands = gl::Buffer(std::as_bytes(std::span(commands)), "draw commands " + field.name);
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    mEmptyVertexArray = gl::VertexArrayHandle(vao);
}

void FieldGpu::resetCommands(int segments) {
    // A buffer update from the CPU, not a read-back: the frame never waits on the GPU.
    const std::array<DrawArraysIndirectCommand, 2> commands{
        {{static_cast<GLuint>(2 * (segments + 1)), 0, 0, 0}, {0, 1, 0, 0}}};
    mCommands.update(std::as_bytes(std::span(commands)), 0);
}

void FieldGpu::bindForCull() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mBlades.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PATCH_BOUNDS_BINDING, mPatchBounds.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, VISIBLE_BINDING, mVisible.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, COMMAND_BINDING, mCommands.id());
}

std::size_t FieldGpu::readDrawnCount() const {
    if (mBladeCount == 0)
        return 0;
    GLuint instances = 0;
    glGetNamedBufferSubData(mCommands.id(), STRIP_COMMAND_OFFSET + sizeof(GLuint), sizeof instances,
                            &instances);
    return instances;
}

void FieldGpu::drawStrips() const {
    if (mBladeCount == 0)
        return;
    glBindVertexArray(mEmptyVertexArray.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mBlades.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, VISIBLE_BINDING, mVisible.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mCommands.id());
    glDrawArraysIndirect(GL_TRIANGLE_STRIP, reinterpret_cast<const void*>(STRIP_COMMAND_OFFSET));
}

void FieldGpu::drawTessellated() const {
    if (mBladeCount == 0)
        return;
    glBindVertexArray(mEmptyVertexArray.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mBlades.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, VISIBLE_BINDING, mVisible.id());
    glPatchParameteri(GL_PATCH_VERTICES, 1);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mCommands.id());
    glDrawArraysIndirect(GL_PATCHES, reinterpret_cast<const void*>(PATCH_COMMAND_OFFSET));
}

}  // namespace grass::render
