#include "render/mesh_gpu.h"

#include <cstddef>

namespace grass::render {

namespace {
struct MeshVertex {
    float position[3];
    float normal[3];
    float uv[2];
};
}  // namespace

MeshGpu::MeshGpu(const core::SurfaceMesh& mesh) {
    std::vector<MeshVertex> vertices;
    vertices.reserve(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) {
        const auto& p = mesh.point(vh);
        const auto& n = mesh.normal(vh);
        const auto& t = mesh.texcoord2D(vh);
        vertices.push_back({{p[0], p[1], p[2]}, {n[0], n[1], n[2]}, {t[0], t[1]}});
    }
    const auto triangles = core::triangleIndices(mesh);
    mIndexCount = triangles.size() * 3;
    mVertices = gl::Buffer::fromVector(vertices, "mesh vertices");
    mIndices = gl::Buffer::fromVector(triangles, "mesh indices");

    mVertexArray = gl::VertexArray("mesh");
    mVertexArray.setVertexBuffer(mVertices, sizeof(MeshVertex));
    mVertexArray.setElementBuffer(mIndices);
    const gl::VertexAttribute attributes[] = {{3, offsetof(MeshVertex, position)},
                                              {3, offsetof(MeshVertex, normal)},
                                              {2, offsetof(MeshVertex, uv)}};
    mVertexArray.setAttributes(attributes);
}

void MeshGpu::draw() const {
    if (mIndexCount == 0)
        return;
    mVertexArray.bind();
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mIndexCount), GL_UNSIGNED_INT, nullptr);
}

void MeshGpu::drawPatches() const {
    if (mIndexCount == 0)
        return;
    mVertexArray.bind();
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    glDrawElements(GL_PATCHES, static_cast<GLsizei>(mIndexCount), GL_UNSIGNED_INT, nullptr);
}

}  // namespace grass::render
