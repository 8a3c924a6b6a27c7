// SurfaceSampler: uniform random points on a triangle mesh (SPEC §2), in the mesh's units.
// Whole-surface sampling picks a triangle by area (Walker/Vose alias table: O(1), two memory
// reads, where a binary search over millions of triangles misses the cache ~10 times) and a
// point in it by uniform barycentrics. Neighbourhood sampling (for clumps) draws points
// uniformly from the part of the surface inside a ball, through a bounding-volume hierarchy
// over the triangles; the points lie on the triangles, never off an edge.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/surface_mesh.h"
#include "util/rng.h"

namespace grass::core {

struct SurfaceSample {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // interpolated vertex normal, unit length
    glm::vec2 uv{0.0f};
    std::uint32_t triangle = 0;
};

class SurfaceSampler {
public:
    explicit SurfaceSampler(const SurfaceMesh& mesh);

    double totalArea() const { return mTotalArea; }
    // True when no triangle has area: nothing can be sampled.
    bool empty() const { return !(mTotalArea > 0.0); }
    std::size_t triangleCount() const { return mTriangles.size(); }

    // A uniform point on the whole surface. Precondition: !empty().
    SurfaceSample sample(Rng& rng) const;
    // The same point as sample() draws from the same rng state, without its normal and UV
    // (for rejection loops that mostly reject): evaluate(triangle, b1, b2) completes it.
    struct Location {
        std::uint32_t triangle = 0;
        float b1 = 0.0f;
        float b2 = 0.0f;
        glm::vec3 position{0.0f};
    };
    Location locate(Rng& rng) const;
    // The surface point at barycentrics (1 − b1 − b2, b1, b2) of a triangle. The normal is the
    // interpolated vertex normal, or the face normal where that is degenerate.
    SurfaceSample evaluate(std::uint32_t triangle, float b1, float b2) const;

    // Builds the hierarchy the neighbourhood queries below need (O(n log n)); whole-surface
    // sampling does not need it.
    void buildNeighbourhoodIndex();
    bool hasNeighbourhoodIndex() const { return !mBvh.empty() || mTriangles.empty(); }

    // Indices of the triangles that come within `radius` of `centre` (exact point-triangle
    // distance), in increasing index order. Precondition: hasNeighbourhoodIndex().
    void trianglesNear(glm::vec3 centre, float radius, std::vector<std::uint32_t>& out) const;

    // Up to `count` uniform points on the surface inside the ball (centre, radius), appended to
    // `out`. Gives up after `maxAttempts` proposals (the ball may hold almost no surface), so
    // it always terminates. Returns the number of points appended. Precondition:
    // hasNeighbourhoodIndex().
    std::size_t sampleNear(glm::vec3 centre, float radius, std::size_t count,
                           std::size_t maxAttempts, Rng& rng,
                           std::vector<SurfaceSample>& out) const;

private:
    struct BvhNode {
        glm::vec3 min{0.0f};
        glm::vec3 max{0.0f};
        std::uint32_t first = 0;  // leaf: first index into mBvhOrder; inner: right child
        std::uint32_t count = 0;  // leaf: triangle count; inner: 0 (left child is next node)
    };
    struct BvhItem {
        glm::vec3 min;
        glm::vec3 max;
        std::uint32_t triangle;
    };

    std::uint32_t pickTriangle(Rng& rng) const;
    glm::vec3 point(std::uint32_t triangle, int corner) const {
        return mPositions[mTriangles[triangle][static_cast<std::size_t>(corner)]];
    }
    glm::vec3 faceNormal(std::uint32_t triangle) const;
    std::uint32_t buildNode(std::vector<BvhItem>& items, std::uint32_t first, std::uint32_t count);

    // The mesh's vertices and faces as plain arrays (32 bytes a vertex, 12 a face: 5× less
    // than per-face copies, which matters at millions of faces).
    std::vector<glm::vec3> mPositions;
    std::vector<glm::vec3> mNormals;
    std::vector<glm::vec2> mUvs;
    std::vector<std::array<std::uint32_t, 3>> mTriangles;
    std::vector<float> mArea;
    double mTotalArea = 0.0;
    // Alias table: pick i uniformly, keep it with probability mAliasProbability[i], else take
    // mAlias[i].
    std::vector<float> mAliasProbability;
    std::vector<std::uint32_t> mAlias;
    std::vector<BvhNode> mBvh;
    std::vector<std::uint32_t> mBvhOrder;
};

}  // namespace grass::core
