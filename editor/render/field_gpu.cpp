#include "field_gpu.h"

namespace grass::render {

FieldGpu::FieldGpu(const core::LayerField& field) : mField(&field) {
    mBladeCount = field.patched.blades.size();
    mBlades = gl::Buffer::fromVector(field.patched.blades, "blades " + field.name);
    const DrawArraysIndirectCommand patches{static_cast<GLuint>(mBladeCount), 1, 0, 0};
    mPatchCommand = gl::Buffer(std::as_bytes(std::span(&patches, 1)), "patch draw command");
    const DrawArraysIndirectCommand strips{0, static_cast<GLuint>(mBladeCount), 0, 0};
    mStripCommand = gl::Buffer(std::as_bytes(std::span(&strips, 1)), "strip draw command");
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    mEmptyVertexArray = gl::VertexArrayHandle(vao);
}

void FieldGpu::drawStrips(int segments) {
    if (mBladeCount == 0)
        return;
    if (segments != mStripSegments) {
        // The vertex count per instance follows the segment count; the cull pass (issue 5) will
        // write the instance count, this side only the shape of the strip.
        const GLuint count = static_cast<GLuint>(2 * (segments + 1));
        mStripCommand.update(std::as_bytes(std::span(&count, 1)), 0);
        mStripSegments = segments;
    }
    glBindVertexArray(mEmptyVertexArray.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mBlades.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mStripCommand.id());
    glDrawArraysIndirect(GL_TRIANGLE_STRIP, nullptr);
}

void FieldGpu::drawTessellated() const {
    if (mBladeCount == 0)
        return;
    glBindVertexArray(mEmptyVertexArray.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mBlades.id());
    glPatchParameteri(GL_PATCH_VERTICES, 1);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mPatchCommand.id());
    glDrawArraysIndirect(GL_PATCHES, nullptr);
}

}  // namespace grass::render
