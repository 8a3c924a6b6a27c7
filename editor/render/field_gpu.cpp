#include "render/field_gpu.h"

#include <algorithm>

#include <glm/glm.hpp>

namespace grass::render {

FieldGpu::FieldGpu(const core::LayerField& field) : mField(&field) {
    mBladeCount = field.patched.blades.size();
    mBlades = gl::Buffer::fromVector(field.patched.blades, "blades " + field.name);
    // Scenes built without a bake (tests that assemble a LayerField by hand) light every blade
    // as open ground: default shading per slot.
    if (field.shading.size() == mBladeCount && mBladeCount > 0)
        mShading = gl::Buffer::fromVector(field.shading, "blade shading " + field.name);
    else
        mShading = gl::Buffer::fromVector(
            std::vector<core::BladeShading>(std::max<std::size_t>(mBladeCount, 1)),
            "blade shading " + field.name);
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
    const std::vector<std::uint32_t> visible(LOD_COUNT * std::max<std::size_t>(mBladeCount, 1), 0);
    mVisible = gl::Buffer::fromVector(visible, "visible blades " + field.name);
    const core::BladeCommandBuffer commands = core::emptyBladeCommandBuffer(1);
    mCommands = gl::Buffer(std::as_bytes(std::span(&commands, 1)), "draw commands " + field.name);
    mEmptyVertexArray = gl::VertexArray("no vertices " + field.name);
    mBladeTexels = gl::makeBufferTexture(GL_RGBA32F, mBlades.id(), "blade texels " + field.name);
    mVisibleTexels =
        gl::makeBufferTexture(GL_R32UI, mVisible.id(), "visible blade texels " + field.name);
    mShadingTexels =
        gl::makeBufferTexture(GL_RGBA32F, mShading.id(), "blade shading texels " + field.name);
    mCommandTexels =
        gl::makeBufferTexture(GL_R32UI, mCommands.id(), "draw command texels " + field.name);
}

void FieldGpu::uploadPatches(std::span<const std::uint32_t> patches, bool withShading) {
    const std::size_t size = mField->patched.patchSize;
    const bool hasShading = mField->shading.size() == mBladeCount;
    for (std::uint32_t p : patches) {
        const std::size_t first = p * size;
        if (first + size > mBladeCount)
            continue;
        mBlades.update(std::as_bytes(std::span(mField->patched.blades).subspan(first, size)),
                       first * sizeof(core::Blade));
        if (withShading && hasShading)
            mShading.update(std::as_bytes(std::span(mField->shading).subspan(first, size)),
                            first * sizeof(core::BladeShading));
    }
}

void FieldGpu::uploadBlades(std::span<const core::Blade> blades) {
    if (blades.size() == mBladeCount && mBladeCount > 0)
        mBlades.update(std::as_bytes(blades), 0);
}

void FieldGpu::resetCommands(int segments) {
    // A buffer update from the CPU, not a read-back: the frame never waits on the GPU.
    const core::BladeCommandBuffer commands = core::emptyBladeCommandBuffer(segments);
    mCommands.update(std::as_bytes(std::span(&commands, 1)), 0);
    if (segments != mStripElementSegments) {
        mStripElements = gl::Buffer::fromVector(core::stripBatchElements(segments),
                                                "strip batch indices " + mField->name);
        mEmptyVertexArray.setElementBuffer(mStripElements);
        mStripElementSegments = segments;
    }
}

void FieldGpu::enableTipSnow() {
    if (mTipSnow.id() == 0)
        mTipSnow = gl::Buffer::fromVector(
            std::vector<float>(std::max<std::size_t>(mBladeCount, 1), 0.0f),
            "tip snow " + mField->name);
    if (mTipSnowTexels.id() == 0)
        mTipSnowTexels = gl::makeBufferTexture(GL_R32F, mTipSnow.id(), "tip snow texels " + mField->name);
}

std::vector<float> FieldGpu::readTipSnow() const {
    if (mTipSnow.id() == 0 || mBladeCount == 0)
        return {};
    std::vector<float> values(mBladeCount);
    glGetNamedBufferSubData(mTipSnow.id(), 0, GLsizeiptr(values.size() * sizeof(float)),
                            values.data());
    return values;
}

std::vector<std::uint32_t> FieldGpu::readVisible() const {
    std::vector<std::uint32_t> slots(LOD_COUNT * mBladeCount);
    if (!slots.empty())
        glGetNamedBufferSubData(mVisible.id(), 0, GLsizeiptr(slots.size() * sizeof(std::uint32_t)),
                                slots.data());
    return slots;
}

void FieldGpu::bindForCull() const {
    glBindTextureUnit(core::BLADE_TEXELS_UNIT, mBladeTexels.id());  // what cull.comp reads
    if (mTipSnow.id() != 0)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, TIP_SNOW_BINDING, mTipSnow.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PATCH_BOUNDS_BINDING, mPatchBounds.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, VISIBLE_BINDING, mVisible.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, COMMAND_BINDING, mCommands.id());
}

core::BladeCommandBuffer FieldGpu::readCommands() const {
    core::BladeCommandBuffer commands{};
    if (mBladeCount > 0)
        glGetNamedBufferSubData(mCommands.id(), 0, sizeof commands, &commands);
    return commands;
}

void FieldGpu::bindForDraw() const {
    mEmptyVertexArray.bind();
    glBindTextureUnit(core::BLADE_TEXELS_UNIT, mBladeTexels.id());
    glBindTextureUnit(core::VISIBLE_TEXELS_UNIT, mVisibleTexels.id());
    glBindTextureUnit(core::SHADING_TEXELS_UNIT, mShadingTexels.id());
    glBindTextureUnit(core::TIP_SNOW_TEXELS_UNIT, mTipSnowTexels.id());
    glBindTextureUnit(core::COMMAND_TEXELS_UNIT, mCommandTexels.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mCommands.id());
}

void FieldGpu::drawStrips(const BladePrograms& programs) const {
    const int segments = mStripElementSegments;
    if (mBladeCount == 0 || segments == 0)
        return;  // never culled: nothing listed to draw
    bindForDraw();
    for (const bool blending : {false, true})
        for (int lod = 0; lod < LOD_COUNT; ++lod) {
            const gl::Program& program = *programs[std::size_t(blending * LOD_COUNT + lod)];
            program.use();
            setVisibleList(program, lod, blending);
            program.set("uSegments", lodSegments(segments, lod));
            program.set("uLod", lod);
            glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                   reinterpret_cast<const void*>(
                                       core::stripBatchCommandOffset(lod, blending)));
        }
}

// LOD `lod`'s visible list as shaders/cull.comp wrote it: from its start, or for the blades in
// its morph band from its end, backwards; and where its length lies in the command buffer, which
// tells the padding of the draw's last batch (blade_texels.glsl's listedInDraw).
void FieldGpu::setVisibleList(const gl::Program& program, int lod, bool blending) const {
    program.set("uVisibleOffset",
                static_cast<unsigned>(core::visibleListStart(lod, mBladeCount, blending)));
    program.set("uVisibleBackwards", blending ? 1 : 0);
    program.set("uSurvivorWord", core::stripSurvivorWord(lod, blending));
}

void FieldGpu::drawTessellated(const BladePrograms& programs) const {
    if (mBladeCount == 0)
        return;
    bindForDraw();
    glPatchParameteri(GL_PATCH_VERTICES, 1);
    for (const bool blending : {false, true})
        for (int lod = 0; lod < LOD_COUNT; ++lod) {
            const gl::Program& program = *programs[std::size_t(blending * LOD_COUNT + lod)];
            program.use();
            setVisibleList(program, lod, blending);
            glDrawArraysIndirect(GL_PATCHES, reinterpret_cast<const void*>(
                                                 core::patchCommandOffset(lod, blending)));
        }
}

}  // namespace grass::render
