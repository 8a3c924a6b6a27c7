#include "mesh/bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "mesh/gltf_loader.h"
#include "mesh/procedural.h"
#include "mesh/surface_ring.h"
#include "support/test_paths.h"
#include "util/rng.h"

namespace grass::core {
namespace {

SurfaceMesh procedural(ProceduralShape shape, int resolution) {
    ProceduralMeshParams params;
    params.shape = shape;
    params.resolution = resolution;
    if (shape == ProceduralShape::Hills)
        params.hillHeight = 3.0f;
    return makeProceduralMesh(params);
}

SurfaceMesh bunny() {
    auto loaded = loadGltf(test::sourceDir() / "projects" / "nature" / "bunny.glb");
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    return loaded.ok() ? std::move(loaded).value().mesh : SurfaceMesh{};
}

glm::vec3 randomIn(Rng& rng, const Bounds& b) {
    return {rng.uniform(b.min.x, b.max.x), rng.uniform(b.min.y, b.max.y),
            rng.uniform(b.min.z, b.max.z)};
}

Bounds grown(const Bounds& b, float factor) {
    const glm::vec3 half = 0.5f * factor * glm::max(b.size(), glm::vec3(1e-3f));
    return {b.centre() - half, b.centre() + half};
}

// Rays of every kind a pick produces and some it should not: from outside and inside the box
// towards the mesh, towards nothing, through vertices and edges, and grazing the surface.
Ray randomRay(Rng& rng, const SurfaceMesh& mesh, const Bounds& bounds) {
    const glm::vec3 origin = randomIn(rng, grown(bounds, rng.uniform() < 0.5f ? 3.0f : 1.0f));
    glm::vec3 target{0.0f};
    const auto face = mesh.face_handle(static_cast<int>(rng.below(std::uint32_t(mesh.n_faces()))));
    const auto corners = facePositions(mesh, face);
    switch (rng.below(5)) {
        case 0:  // anywhere in the box: many misses
            target = randomIn(rng, grown(bounds, 1.5f));
            break;
        case 1:  // a vertex
            target = corners[rng.below(3)];
            break;
        case 2: {  // a point on an edge
            const std::uint32_t i = rng.below(3);
            target = glm::mix(corners[i], corners[(i + 1) % 3], rng.uniform());
            break;
        }
        case 3: {  // grazing: along the triangle's plane, tilted by a hair
            const glm::vec3 n =
                glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
            const glm::vec3 inside = (corners[0] + corners[1] + corners[2]) / 3.0f;
            const glm::vec3 along = glm::normalize(corners[rng.below(3)] - inside);
            const glm::vec3 dir = glm::normalize(along + rng.uniform(-1e-3f, 1e-3f) * n);
            return Ray{inside - dir * rng.uniform(0.01f, 2.0f) * glm::length(bounds.size()), dir};
        }
        default:  // inside a triangle
            target = (corners[0] + corners[1] + corners[2]) / 3.0f;
            break;
    }
    const glm::vec3 d = target - origin;
    return Ray{origin, glm::length(d) > 0.0f ? glm::normalize(d) : glm::vec3(0, -1, 0)};
}

void expectSameAsBruteForce(const SurfaceMesh& mesh, const std::string& name, int rayCount) {
    const TriangleBvh bvh(mesh);
    ASSERT_EQ(bvh.triangleCount(), mesh.n_faces()) << name;
    ASSERT_LT(bvh.nodeCount(), 2 * mesh.n_faces()) << name;
    const Bounds bounds = meshBounds(mesh);
    const float scale = glm::length(bounds.size());
    int hits = 0;
    for (std::uint64_t seed = 0; seed < std::uint64_t(rayCount); ++seed) {
        Rng rng(seed, 11);
        const Ray ray = randomRay(rng, mesh, bounds);
        const auto fast = bvh.intersect(ray);
        const auto slow = bruteForceIntersect(bvh, ray);
        ASSERT_EQ(fast.has_value(), slow.has_value()) << name << " seed " << seed;
        if (!fast)
            continue;
        ++hits;
        EXPECT_NEAR(fast->t, slow->t, 1e-5f * std::max(slow->t, 1.0f)) << name << " seed " << seed;
        // Same triangle, or a tie in t (a shared edge) that either may win.
        EXPECT_TRUE(fast->triangle == slow->triangle || fast->t == slow->t)
            << name << " seed " << seed;
        // The point lies on its triangle and on the ray.
        const auto corners =
            facePositions(mesh, mesh.face_handle(static_cast<int>(fast->triangle)));
        const glm::vec3 b = fast->barycentric;
        EXPECT_GE(std::min({b.x, b.y, b.z}), 0.0f) << name << " seed " << seed;
        EXPECT_NEAR(b.x + b.y + b.z, 1.0f, 1e-5f) << name << " seed " << seed;
        const glm::vec3 onTriangle = b.x * corners[0] + b.y * corners[1] + b.z * corners[2];
        EXPECT_LT(glm::length(fast->posWorld - onTriangle), 1e-5f * scale) << name << seed;
        EXPECT_LT(glm::length(fast->posWorld - ray.at(fast->t)), 1e-4f * (scale + fast->t))
            << name << " seed " << seed;
        EXPECT_NEAR(glm::length(fast->normal), 1.0f, 1e-4f) << name << " seed " << seed;
        EXPECT_NEAR(glm::length(fast->geometricNormal), 1.0f, 1e-4f) << name << " seed " << seed;
    }
    // The ray mix must actually exercise hits and misses.
    EXPECT_GT(hits, rayCount / 4) << name;
    EXPECT_LT(hits, rayCount) << name;
}

TEST(Bvh, BunnyMatchesBruteForce) {
    const SurfaceMesh mesh = bunny();
    ASSERT_GT(mesh.n_faces(), 1000u);
    expectSameAsBruteForce(mesh, "bunny", 2000);
}

TEST(Bvh, MoebiusMatchesBruteForce) {
    expectSameAsBruteForce(procedural(ProceduralShape::Moebius, 96), "moebius", 3000);
}

TEST(Bvh, HillsMatchesBruteForce) {
    expectSameAsBruteForce(procedural(ProceduralShape::Hills, 96), "hills", 3000);
}

TEST(Bvh, TorusMatchesBruteForce) {
    expectSameAsBruteForce(procedural(ProceduralShape::Torus, 64), "torus", 3000);
}

TEST(Bvh, FindsTheNearestOfStackedSurfaces) {
    // A sphere: a ray through the centre meets the near side at distance − radius.
    const TriangleBvh bvh(procedural(ProceduralShape::Sphere, 48));
    const auto hit = bvh.intersect(Ray{{0, 0, 30}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 20.0f, 0.05f);
    EXPECT_GT(hit->posWorld.z, 0.0f);
    EXPECT_TRUE(hit->frontFace);
}

TEST(Bvh, HitsBothSidesOfTheMoebiusStrip) {
    const TriangleBvh bvh(procedural(ProceduralShape::Moebius, 96));
    // At φ = 0 the strip's ruling is radial and horizontal through (10, 0, 0).
    const auto fromAbove = bvh.intersect(Ray{{10.2f, 5, 0.01f}, {0, -1, 0}});
    const auto fromBelow = bvh.intersect(Ray{{10.2f, -5, 0.01f}, {0, 1, 0}});
    ASSERT_TRUE(fromAbove);
    ASSERT_TRUE(fromBelow);
    EXPECT_NEAR(fromAbove->posWorld.y, fromBelow->posWorld.y, 1e-4f);
    EXPECT_NE(fromAbove->frontFace, fromBelow->frontFace);
}

TEST(Bvh, InterpolatesNormalAndUv) {
    const TriangleBvh bvh(procedural(ProceduralShape::Plane, 8));
    const auto hit = bvh.intersect(Ray{{1.3f, 4, -2.1f}, glm::normalize(glm::vec3(0.1f, -1, 0))});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->posWorld.y, 0.0f, 1e-6f);
    EXPECT_NEAR(hit->normal.y, 1.0f, 1e-6f);
    EXPECT_NEAR(std::abs(hit->geometricNormal.y), 1.0f, 1e-6f);
    // The plane's UVs run linearly from corner to corner of its 10 m side.
    EXPECT_NEAR(hit->uv.x, (hit->posWorld.x + 5.0f) / 10.0f, 1e-4f);
    EXPECT_NEAR(hit->uv.y, (hit->posWorld.z + 5.0f) / 10.0f, 1e-4f);
}

TEST(Bvh, RayParallelToAPlaneMisses) {
    const TriangleBvh bvh(procedural(ProceduralShape::Plane, 8));
    EXPECT_FALSE(bvh.intersect(Ray{{-20, 1, 0.3f}, {1, 0, 0}}));
    // In the plane itself: the triangles have no extent across the ray.
    EXPECT_FALSE(bvh.intersect(Ray{{-20, 0, 0.3f}, glm::normalize(glm::vec3(1, 0, 0.2f))}));
}

TEST(Bvh, RayStartingOnTheSurface) {
    const TriangleBvh bvh(procedural(ProceduralShape::Plane, 8));
    const glm::vec3 up = glm::normalize(glm::vec3(0.3f, 1, 0.2f));
    // On the surface: reported at t ≈ 0 or not at all (documented), never further away.
    const auto onSurface = bvh.intersect(Ray{{0.37f, 0, 1.21f}, up});
    if (onSurface) {
        EXPECT_LT(onSurface->t, 1e-5f);
    }
    const auto intoSurface = bvh.intersect(Ray{{0.37f, 0, 1.21f}, -up});
    ASSERT_TRUE(intoSurface);
    EXPECT_LT(intoSurface->t, 1e-5f);
    // Offset off the surface, the surface is behind the ray.
    EXPECT_FALSE(bvh.intersect(Ray{glm::vec3(0.37f, 0, 1.21f) + 1e-4f * up, up}));
}

TEST(Bvh, UnusableRaysAndEmptyMeshesMiss) {
    const TriangleBvh bvh(procedural(ProceduralShape::Plane, 8));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(bvh.intersect(Ray{{0, 1, 0}, {nan, -1, 0}}));
    EXPECT_FALSE(bvh.intersect(Ray{{0, 1, 0}, {0, nan, 0}}));
    EXPECT_FALSE(bvh.intersect(Ray{{inf, 1, 0}, {0, -1, 0}}));
    EXPECT_FALSE(bvh.intersect(Ray{{0, 1, 0}, {0, 0, 0}}));
    EXPECT_FALSE(bvh.intersect(Ray{{0, 1, 0}, {0, -1, 0}}, 0.5f));
    EXPECT_FALSE(bvh.intersect(Ray{{0, 1, 0}, {0, -1, 0}}, -1.0f));
    EXPECT_FALSE(bvh.intersect(Ray{{0, 1, 0}, {0, -1, 0}}, nan));
    EXPECT_TRUE(bvh.intersect(Ray{{0, 1, 0}, {0, -1, 0}}, 1.5f));
    EXPECT_FALSE(bruteForceIntersect(bvh, Ray{{0, 1, 0}, {nan, -1, 0}}));
    const TriangleBvh empty;
    EXPECT_FALSE(empty.intersect(Ray{{0, 1, 0}, {0, -1, 0}}));
    EXPECT_FALSE(bruteForceIntersect(empty, Ray{{0, 1, 0}, {0, -1, 0}}));
    const TriangleBvh emptyMesh{SurfaceMesh{}};
    EXPECT_FALSE(emptyMesh.intersect(Ray{{0, 1, 0}, {0, -1, 0}}));
}

TEST(Bvh, CoincidentTrianglesGoToTheLowerIndex) {
    // Many copies of one triangle: the median fallback must split them, and the tie rule picks
    // the first.
    TriangleSoup soup;
    soup.positions = {{-1, 0, -1}, {1, 0, -1}, {0, 0, 1}};
    soup.triangles.assign(100, {0, 1, 2});
    const TriangleBvh bvh(soup);
    const auto hit = bvh.intersect(Ray{{0, 1, 0}, {0, -1, 0}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->triangle, 0u);
    EXPECT_NEAR(hit->t, 1.0f, 1e-6f);
}

TEST(SurfaceRing, LiesOnAFlatSurfaceAtTheRadius) {
    const TriangleBvh bvh(procedural(ProceduralShape::Plane, 8));
    const glm::vec3 centre(0.5f, 0, -1);
    const auto ring = surfacePointsOnRing(bvh, centre, {0, 2, 0}, 1.5f, 32);
    ASSERT_EQ(ring.size(), 32u);
    for (const glm::vec3 p : ring) {
        EXPECT_NEAR(p.y, 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(p - centre), 1.5f, 1e-4f);
    }
    // Counter-clockwise seen from above (+Y): the signed area about +Y is positive.
    float area = 0.0f;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const glm::vec3 a = ring[i] - centre, b = ring[(i + 1) % ring.size()] - centre;
        area += glm::cross(a, b).y;
    }
    EXPECT_GT(area, 0.0f);
}

TEST(SurfaceRing, FollowsHillsAndFallsBackOffTheEdge) {
    ProceduralMeshParams params;
    params.shape = ProceduralShape::Hills;
    params.hillHeight = 2.0f;
    params.resolution = 96;
    const TriangleBvh bvh(makeProceduralMesh(params));
    const auto centreHit = bvh.intersect(Ray{{1, 10, 2}, {0, -1, 0}});
    ASSERT_TRUE(centreHit);
    const auto ring = surfacePointsOnRing(bvh, centreHit->posWorld, centreHit->normal, 0.8f, 24);
    for (const glm::vec3 p : ring) {
        // Each point is on the mesh: a vertical ray finds the surface at its height.
        const auto below = bvh.intersect(Ray{{p.x, 10, p.z}, {0, -1, 0}});
        ASSERT_TRUE(below);
        EXPECT_NEAR(below->posWorld.y, p.y, 1e-3f);
    }
    // Past the terrain's edge (x = 5) the points stay in the tangent plane at the radius.
    const TriangleBvh plane(procedural(ProceduralShape::Plane, 8));
    const auto edge = surfacePointsOnRing(plane, {4.5f, 0, 0}, {0, 1, 0}, 2.0f, 16);
    for (const glm::vec3 p : edge) {
        EXPECT_NEAR(p.y, 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(p - glm::vec3(4.5f, 0, 0)), 2.0f, 1e-4f);
    }
}

TEST(SurfaceRing, DegenerateInputs) {
    const TriangleBvh bvh(procedural(ProceduralShape::Plane, 8));
    EXPECT_TRUE(surfacePointsOnRing(bvh, {0, 0, 0}, {0, 1, 0}, 1.0f, 0).empty());
    const auto zeroNormal = surfacePointsOnRing(bvh, {1, 0, 0}, {0, 0, 0}, 1.0f, 4);
    ASSERT_EQ(zeroNormal.size(), 4u);
    EXPECT_EQ(zeroNormal[3], glm::vec3(1, 0, 0));
    const auto zeroRadius = surfacePointsOnRing(bvh, {1, 0, 0}, {0, 1, 0}, 0.0f, 3);
    EXPECT_EQ(zeroRadius, std::vector<glm::vec3>(3, glm::vec3(1, 0, 0)));
}

}  // namespace
}  // namespace grass::core
