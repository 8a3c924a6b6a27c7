// SurfaceSampler: uniform random points on a triangle mesh (SPEC §2), in the mesh's units.
// Whole-surface sampling picks a triangle by area (binary search in the cumulative areas) and
// a point in it by uniform barycentrics. Neighbourhood sampling (for clumps) draws points
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
    struct Triangle {
        std::array<glm::vec3, 3> p;
        std::array<glm::vec3, 3> n;
        std::array<glm::vec2, 3> uv;
        glm::vec3 faceNormal{0.0f, 1.0f, 0.0f};
        double area = 0.0;
    };
    struct BvhNode {
        glm::vec3 min{0.0f};
        glm::vec3 max{0.0f};
        std::uint32_t first = 0;  // leaf: first index into mBvhOrder; inner: right child
        std::uint32_t count = 0;  // leaf: triangle count; inner: 0 (left child is next node)
    };

    std::uint32_t pickTriangle(Rng& rng) const;
    std::uint32_t buildNode(std::uint32_t first, std::uint32_t count);

    std::vector<Triangle> mTriangles;
    std::vector<double> mCumulativeArea;
    double mTotalArea = 0.0;
    std::vector<BvhNode> mBvh;
    std::vector<std::uint32_t> mBvhOrder;
};

}  // namespace grass::core
