// MeshGpu: a SurfaceMesh uploaded for drawing: interleaved position/normal/uv, 32-bit indices.
#pragma once

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "mesh/surface_mesh.h"

namespace grass::render {

class MeshGpu {
public:
    explicit MeshGpu(const core::SurfaceMesh& mesh);
    void draw() const;
    // The triangles as 3-vertex patches, for the tessellated snow surface (mesh_snow.tesc).
    void drawPatches() const;
    std::size_t triangleCount() const { return mIndexCount / 3; }

private:
    gl::Buffer mVertices;
    gl::Buffer mIndices;
    gl::VertexArray mVertexArray;
    std::size_t mIndexCount = 0;
};

}  // namespace grass::render
