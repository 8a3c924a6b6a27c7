// SurfaceMesh: the triangle mesh grass grows on (SPEC §2), an OpenMesh TriMesh with per-vertex
// position, normal and UV0. World units are the source file's (metres for glTF). Vertices are
// not welded: a glTF vertex with its own normal/UV stays its own vertex, as the file has it.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "util/assert.h"

namespace grass::core {

struct SurfaceMeshTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3f;
    using Normal = OpenMesh::Vec3f;
    using TexCoord2D = OpenMesh::Vec2f;
    VertexAttributes(OpenMesh::Attributes::Normal | OpenMesh::Attributes::TexCoord2D);
};

using SurfaceMesh = OpenMesh::TriMesh_ArrayKernelT<SurfaceMeshTraits>;

// A SurfaceMesh that moves. OpenMesh's kernels declare destructors, so C++ gives them no move
// constructor or move assignment: std::move on a SurfaceMesh copies every vertex, face and
// property. An 8-million-triangle ground took three such copies between the glTF reader and
// the built scene (about a second and a gigabyte each). This holds the mesh on the heap, so a
// move hands the pointer over; a copy is still a deep copy. It converts to SurfaceMesh& where a
// function takes one; members are reached with ->. A moved-from one may only be assigned to or
// destroyed.
class MovableSurfaceMesh {
public:
    MovableSurfaceMesh() : mMesh(std::make_shared<SurfaceMesh>()) {}
    MovableSurfaceMesh(const MovableSurfaceMesh& other)
        : mMesh(std::make_shared<SurfaceMesh>(*other)) {}
    MovableSurfaceMesh(MovableSurfaceMesh&&) noexcept = default;
    MovableSurfaceMesh& operator=(const MovableSurfaceMesh& other) {
        if (this != &other)
            mMesh = std::make_shared<SurfaceMesh>(*other);
        return *this;
    }
    MovableSurfaceMesh& operator=(MovableSurfaceMesh&&) noexcept = default;

    // The same mesh, not a copy: a field grown again on the surface of the one before it
    // (regrowOnSameSurface) holds its mesh too, where a copy cost 0.3 s of the 1.1 s re-grow on
    // that 8-million-triangle ground at every edit. A scene's mesh is only read once the scene is
    // built (its changes, frames and UVs, are made while it is read), so holders never see
    // each other's changes; both may read it from different threads.
    MovableSurfaceMesh shared() const {
        GRASS_ASSERT(mMesh);
        MovableSurfaceMesh same(Empty{});
        same.mMesh = mMesh;
        return same;
    }
    bool sameMeshAs(const MovableSurfaceMesh& other) const { return mMesh == other.mMesh; }

    SurfaceMesh& operator*() {
        GRASS_ASSERT(mMesh);  // a moved-from one was used
        return *mMesh;
    }
    const SurfaceMesh& operator*() const {
        GRASS_ASSERT(mMesh);
        return *mMesh;
    }
    SurfaceMesh* operator->() { return &**this; }
    const SurfaceMesh* operator->() const { return &**this; }
    operator SurfaceMesh&() { return **this; }
    operator const SurfaceMesh&() const { return **this; }

private:
    struct Empty {};
    explicit MovableSurfaceMesh(Empty) {}
    std::shared_ptr<SurfaceMesh> mMesh;
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 centre() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return max - min; }
    // Closed boxes: touching counts.
    bool overlaps(const Bounds& o) const {
        return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y &&
               min.z <= o.max.z && o.min.z <= max.z;
    }
    bool contains(glm::vec3 p) const {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y &&
               p.z <= max.z;
    }
    bool operator==(const Bounds&) const = default;
};

// Builds a SurfaceMesh from a triangle soup. OpenMesh refuses faces that would make the mesh
// non-manifold (real files have such faces); those triangles get their own copies of their
// three vertices, so nothing a file contains is dropped. Degenerate triangles (a repeated
// index) have no area and are skipped and counted.
class SurfaceMeshBuilder {
public:
    // Room for `vertices` and `triangles` more: OpenMesh's arrays otherwise grow by doubling,
    // copying every vertex, edge and face on the way (an 8-million-triangle ground: 0.3 s of
    // its 3.3 s read). Grows the room at least twofold, so many small reserves stay linear.
    void reserveMore(std::size_t vertices, std::size_t triangles);
    std::uint32_t addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv);
    void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    std::size_t degenerateTriangles() const { return mDegenerate; }
    std::size_t duplicatedForManifold() const { return mDuplicated; }
    SurfaceMesh& mesh() { return *mMesh; }
    MovableSurfaceMesh take() { return std::move(mMesh); }

private:
    MovableSurfaceMesh mMesh;
    std::size_t mRoomVertices = 0, mRoomTriangles = 0;
    std::size_t mDegenerate = 0;
    std::size_t mDuplicated = 0;
};

glm::vec3 toGlm(const OpenMesh::Vec3f& v);
glm::vec2 toGlm(const OpenMesh::Vec2f& v);

// The three corner positions of a face.
std::array<glm::vec3, 3> facePositions(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle face);

// Sum of triangle areas, in squared file units.
double surfaceArea(const SurfaceMesh& mesh);
Bounds meshBounds(const SurfaceMesh& mesh);

// Vertex normals as the area-weighted sum of the adjacent face normals (cross products are
// already area-weighted). For meshes that come without normals.
void computeAreaWeightedNormals(SurfaceMesh& mesh);

// UVs for meshes that come without UV0. Scheme: planar projection onto the two largest axes
// of the bounding box, scaled by the largest of them so texels stay square, in [0, 1]².
// Documented in docs/meshes.md.
void generatePlanarUVs(SurfaceMesh& mesh);

// The three vertex indices of every face, in face order: what GPU index buffers take.
std::vector<std::array<std::uint32_t, 3>> triangleIndices(const SurfaceMesh& mesh);

}  // namespace grass::core
