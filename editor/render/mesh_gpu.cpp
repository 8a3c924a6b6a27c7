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

    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    mVertexArray = gl::VertexArrayHandle(vao);
    mVertexArray.setLabel("mesh");
    glVertexArrayVertexBuffer(vao, 0, mVertices.id(), 0, sizeof(MeshVertex));
    glVertexArrayElementBuffer(vao, mIndices.id());
    const GLuint offsets[3] = {offsetof(MeshVertex, position), offsetof(MeshVertex, normal),
                               offsetof(MeshVertex, uv)};
    const GLint sizes[3] = {3, 3, 2};
    for (GLuint i = 0; i < 3; ++i) {
        glEnableVertexArrayAttrib(vao, i);
        glVertexArrayAttribFormat(vao, i, sizes[i], GL_FLOAT, GL_FALSE, offsets[i]);
        glVertexArrayAttribBinding(vao, i, 0);
    }
}

void MeshGpu::draw() const {
    if (mIndexCount == 0)
        return;
    glBindVertexArray(mVertexArray.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mIndexCount), GL_UNSIGNED_INT, nullptr);
}

void MeshGpu::drawPatches() const {
    if (mIndexCount == 0)
        return;
    glBindVertexArray(mVertexArray.id());
    glPatchParameteri(GL_PATCH_VERTICES, 3);
    glDrawElements(GL_PATCHES, static_cast<GLsizei>(mIndexCount), GL_UNSIGNED_INT, nullptr);
}

}  // namespace grass::render
