// FieldGpu: one grass layer's blades on the GPU: the blade buffer (four vec4 per blade,
// SPEC §1, bound as SSBO 0), the patch boxes (SSBO 1: min, max vec4 per patch), the visible-index
// list (SSBO 5) and the two indirect draw commands (strips at offset 0, tessellation patches at
// 16) that the cull pass (SPEC §6, cull_pass.h) fills each frame. Draws by either geometry path.
#pragma once

#include "buffer.h"
#include "gl_handle.h"
#include "scene/scene.h"

namespace grass::render {

// Matches GL's DrawArraysIndirectCommand.
struct DrawArraysIndirectCommand {
    GLuint count;
    GLuint instanceCount;
    GLuint first;
    GLuint baseInstance;
};
static_assert(sizeof(DrawArraysIndirectCommand) == 16);

enum class GeometryPath { Tessellation, Strips };

// SSBO bindings shared with shaders/cull.comp and shaders/include/visible.glsl.
inline constexpr GLuint PATCH_BOUNDS_BINDING = 1;
inline constexpr GLuint VISIBLE_BINDING = 5;
inline constexpr GLuint COMMAND_BINDING = 6;

class FieldGpu {
public:
    explicit FieldGpu(const core::LayerField& field);
    const core::LayerField& field() const { return *mField; }
    // Blade slots, padding included (a whole number of patches).
    std::size_t bladeCount() const { return mBladeCount; }
    std::uint32_t patchSize() const { return mField->patched.patchSize; }
    GLuint bladeBuffer() const { return mBlades.id(); }

    // Before the cull dispatch: zero survivors, and the strip's vertex count for `segments`.
    void resetCommands(int segments);
    // Binds the blade, patch-box, visible and command buffers for the cull dispatch.
    void bindForCull() const;
    // The instance count the cull pass wrote (waits for the GPU; statistics only).
    std::size_t readDrawnCount() const;

    // Binds the blade and visible buffers and issues the indirect draw; the caller has bound
    // the program and run the cull pass.
    void drawStrips() const;
    void drawTessellated() const;

private:
    const core::LayerField* mField;
    std::size_t mBladeCount = 0;
    gl::Buffer mBlades;
    gl::Buffer mPatchBounds;
    gl::Buffer mVisible;
    gl::Buffer mCommands;
    gl::VertexArrayHandle mEmptyVertexArray;  // core profile needs a VAO bound to draw
};

}  // namespace grass::render
