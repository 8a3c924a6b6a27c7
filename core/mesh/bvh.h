// TriangleBvh: a bounding volume hierarchy over a triangle mesh, for picking under the mouse and
// snapping onto surfaces (issue 8) on any mesh (terrain, bunny, Möbius strip) without testing
// every triangle. World space, metres. Built once per mesh (binned SAH), stored as a flat
// depth-first node array and traversed iteratively, nearer child first, for the closest hit.
//
// Both sides of every triangle are hit (no backface culling: the Möbius strip has one side).
// The ray–triangle test is watertight (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): a ray through a shared edge or vertex hits at least one of the
// triangles that share it, so picks never fall through cracks between triangles. Both tests
// live in mesh/ray_triangle.h, shared with the brute-force reference below.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/ray.h"
#include "mesh/surface_mesh.h"

namespace grass::core {

struct RayHit {
    float t = 0.0f;  // metres along the ray (the ray's direction is unit length)
    glm::vec3 posWorld{0.0f};
    // The vertex normals interpolated by the barycentric weights, normalized (the geometric
    // normal where they cancel). As the mesh has them: not flipped towards the ray.
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    // normalize(cross(v1 − v0, v2 − v0)): the winding's side, not flipped either.
    glm::vec3 geometricNormal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};                 // interpolated UV0
    std::uint32_t triangle = 0;         // face index in the source mesh (face order)
    glm::vec3 barycentric{1.0f, 0, 0};  // weights of the triangle's corners 0, 1, 2
    bool frontFace = true;              // the ray arrives on the geometricNormal side
    bool operator==(const RayHit&) const = default;
};

// The triangle data a BVH is built from; normals and uvs are per vertex and may be empty
// (then hits report the geometric normal and uv 0).
struct TriangleSoup {
    std::vector<glm::vec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
};

// The mesh's vertices (position, normal, UV0) and faces, in the mesh's order: what a BVH of it
// is built from, taken apart from the mesh so the build can run on another thread.
TriangleSoup triangleSoupOf(const SurfaceMesh& mesh);

class TriangleBvh {
public:
    // An empty BVH: every ray misses.
    TriangleBvh() = default;
    explicit TriangleBvh(const SurfaceMesh& mesh);
    // Indices must be below positions.size() (GRASS_ASSERT); normals and uvs, when not empty,
    // have one entry per position.
    explicit TriangleBvh(TriangleSoup soup);

    // The closest hit with 0 ≤ t ≤ maxT; nullopt for a miss, an empty mesh, or a ray with a
    // non-finite origin/direction or a zero direction. Ties (equal t, e.g. a shared edge) go to
    // the lower triangle index, so the answer does not depend on the tree. A ray that starts
    // on the surface may or may not report it at t ≈ 0 (float rounding decides): to leave a
    // surface, offset the origin.
    std::optional<RayHit> intersect(const Ray& ray,
                                    float maxT = std::numeric_limits<float>::infinity()) const;

    std::size_t triangleCount() const { return mLeafTriangles.size(); }
    std::size_t nodeCount() const { return mNodes.size(); }
    Bounds bounds() const;

    // Tests every triangle with the same ray–triangle test and the same tie rule: the quality
    // reference for tests and benchmarks, not for the editor (it is O(triangles) per ray).
    friend std::optional<RayHit> bruteForceIntersect(const TriangleBvh& bvh, const Ray& ray,
                                                     float maxT);

private:
    // 32 bytes. Interior nodes: the left child follows at index + 1, `offset` is the right
    // child and count is 0. Leaves: `offset` is the first entry of mLeafTriangles, count > 0.
    struct Node {
        glm::vec3 boundsMin{0.0f};
        std::uint32_t offset = 0;
        glm::vec3 boundsMax{0.0f};
        std::uint32_t count = 0;
    };
    // A triangle's corners in leaf order, next to its source index, so a leaf reads one run
    // of memory.
    struct LeafTriangle {
        std::array<glm::vec3, 3> corners;
        std::uint32_t source = 0;
    };
    struct Candidate;  // a hit before its attributes are interpolated (bvh.cpp)

    void build();
    RayHit makeHit(const Ray& ray, const Candidate& candidate) const;

    TriangleSoup mSoup;
    std::vector<Node> mNodes;
    std::vector<LeafTriangle> mLeafTriangles;
};

std::optional<RayHit> bruteForceIntersect(const TriangleBvh& bvh, const Ray& ray,
                                          float maxT = std::numeric_limits<float>::infinity());

}  // namespace grass::core
