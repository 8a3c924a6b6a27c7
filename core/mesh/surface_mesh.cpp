#include "mesh/surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <OpenMesh/Core/System/omstream.hh>

namespace grass::core {

glm::vec3 toGlm(const OpenMesh::Vec3f& v) {
    return {v[0], v[1], v[2]};
}
glm::vec2 toGlm(const OpenMesh::Vec2f& v) {
    return {v[0], v[1]};
}

void SurfaceMeshBuilder::reserveMore(std::size_t vertices, std::size_t triangles) {
    const std::size_t needVertices = mMesh->n_vertices() + vertices;
    const std::size_t needTriangles = mMesh->n_faces() + triangles;
    if (needVertices <= mRoomVertices && needTriangles <= mRoomTriangles)
        return;
    mRoomVertices = std::max(needVertices, 2 * mRoomVertices);
    mRoomTriangles = std::max(needTriangles, 2 * mRoomTriangles);
    // Edges: V + F by Euler's formula for a surface of a few pieces (V - E + F = 2 per piece).
    mMesh->reserve(mRoomVertices, mRoomVertices + mRoomTriangles, mRoomTriangles);
}

std::uint32_t SurfaceMeshBuilder::addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv) {
    const auto vh = mMesh->add_vertex(OpenMesh::Vec3f(position.x, position.y, position.z));
    mMesh->set_normal(vh, OpenMesh::Vec3f(normal.x, normal.y, normal.z));
    mMesh->set_texcoord2D(vh, OpenMesh::Vec2f(uv.x, uv.y));
    return static_cast<std::uint32_t>(vh.idx());
}

void SurfaceMeshBuilder::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a == b || b == c || a == c) {
        ++mDegenerate;
        return;
    }
    const SurfaceMesh::VertexHandle handles[3] = {mMesh->vertex_handle(static_cast<int>(a)),
                                                  mMesh->vertex_handle(static_cast<int>(b)),
                                                  mMesh->vertex_handle(static_cast<int>(c))};
    // OpenMesh logs "complex edge" when it refuses a face; the refusal is handled below, so
    // the log line would only alarm the user.
    omerr().disable();
    const bool added = mMesh->add_face(handles[0], handles[1], handles[2]).is_valid();
    omerr().enable();
    if (added)
        return;
    SurfaceMesh::VertexHandle copies[3];
    for (int i = 0; i < 3; ++i) {
        // Copies, not references: add_vertex may reallocate the arrays they point into.
        const OpenMesh::Vec3f point = mMesh->point(handles[i]);
        const OpenMesh::Vec3f normal = mMesh->normal(handles[i]);
        const OpenMesh::Vec2f uv = mMesh->texcoord2D(handles[i]);
        copies[i] = mMesh->add_vertex(point);
        mMesh->set_normal(copies[i], normal);
        mMesh->set_texcoord2D(copies[i], uv);
    }
    mMesh->add_face(copies[0], copies[1], copies[2]);
    ++mDuplicated;
}

std::array<glm::vec3, 3> facePositions(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle face) {
    auto fv = mesh.cfv_iter(face);
    std::array<glm::vec3, 3> p;
    p[0] = toGlm(mesh.point(*fv++));
    p[1] = toGlm(mesh.point(*fv++));
    p[2] = toGlm(mesh.point(*fv));
    return p;
}

double surfaceArea(const SurfaceMesh& mesh) {
    double area = 0.0;
    for (const auto fh : mesh.faces()) {
        const auto p = facePositions(mesh, fh);
        const glm::dvec3 a = p[0], b = p[1], c = p[2];
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

Bounds meshBounds(const SurfaceMesh& mesh) {
    if (mesh.n_vertices() == 0)
        return {};
    Bounds bounds{glm::vec3(std::numeric_limits<float>::max()),
                  glm::vec3(std::numeric_limits<float>::lowest())};
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 p = toGlm(mesh.point(vh));
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    return bounds;
}

void computeAreaWeightedNormals(SurfaceMesh& mesh) {
    // In double: a cross product of finite float positions far from the origin (a glTF may
    // hold 1e30) overflows float, and inf / inf would make the normal NaN (found by fuzzing).
    std::vector<glm::dvec3> sums(mesh.n_vertices(), glm::dvec3(0.0));
    for (const auto fh : mesh.faces()) {
        SurfaceMesh::VertexHandle v[3];
        int i = 0;
        for (const auto vh : mesh.fv_range(fh))
            v[i++] = vh;
        const glm::dvec3 a(toGlm(mesh.point(v[0])));
        const glm::dvec3 b(toGlm(mesh.point(v[1])));
        const glm::dvec3 c(toGlm(mesh.point(v[2])));
        const glm::dvec3 weighted = glm::cross(b - a, c - a);  // length = 2·area
        for (const auto vh : v)
            sums[static_cast<std::size_t>(vh.idx())] += weighted;
    }
    for (const auto vh : mesh.vertices()) {
        const glm::dvec3 sum = sums[static_cast<std::size_t>(vh.idx())];
        const double length = glm::length(sum);
        const glm::vec3 n = length > 0.0 && std::isfinite(length) ? glm::vec3(sum / length)
                                                                   : glm::vec3(0, 1, 0);
        mesh.set_normal(vh, OpenMesh::Vec3f(n.x, n.y, n.z));
    }
}

void generatePlanarUVs(SurfaceMesh& mesh) {
    const Bounds bounds = meshBounds(mesh);
    const glm::vec3 size = bounds.size();
    // The two axes with the largest extent span the projection plane.
    int axes[3] = {0, 1, 2};
    std::sort(axes, axes + 3, [&](int l, int r) { return size[l] > size[r]; });
    const float scale = size[axes[0]] > 0.0f ? 1.0f / size[axes[0]] : 1.0f;
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 p = toGlm(mesh.point(vh)) - bounds.min;
        mesh.set_texcoord2D(vh, OpenMesh::Vec2f(p[axes[0]] * scale, p[axes[1]] * scale));
    }
}

std::vector<std::array<std::uint32_t, 3>> triangleIndices(const SurfaceMesh& mesh) {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    triangles.reserve(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        std::array<std::uint32_t, 3> t{};
        int i = 0;
        for (const auto vh : mesh.fv_range(fh))
            t[static_cast<std::size_t>(i++)] = static_cast<std::uint32_t>(vh.idx());
        triangles.push_back(t);
    }
    return triangles;
}

}  // namespace grass::core
