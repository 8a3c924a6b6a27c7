// FieldGpu: one grass layer's blades on the GPU: the blade buffer (four vec4 per blade,
// SPEC §1, bound as SSBO 0) and the indirect draw command the cull pass will write (issue 5;
// for now it is filled on upload with every blade). Draws by either geometry path.
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

class FieldGpu {
public:
    explicit FieldGpu(const core::LayerField& field);
    const core::LayerField& field() const { return *mField; }
    std::size_t bladeCount() const { return mBladeCount; }
    GLuint bladeBuffer() const { return mBlades.id(); }

    // Binds the blade buffer and issues the draw; the caller has bound the program.
    void drawStrips(int segments);
    void drawTessellated() const;

private:
    const core::LayerField* mField;
    std::size_t mBladeCount = 0;
    gl::Buffer mBlades;
    gl::Buffer mStripCommand;
    gl::Buffer mPatchCommand;
    gl::VertexArrayHandle mEmptyVertexArray;  // core profile needs a VAO bound to draw
    int mStripSegments = -1;
};

}  // namespace grass::render
