// The two tests a BVH traversal runs per ray: ray–triangle (watertight, both sides) and
// ray–box (conservative slab test). Inline because they are the inner loop of every pick;
// kept apart from the BVH so the brute-force reference runs exactly the same arithmetic.
// World space, metres; t is in units of the ray direction's length.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/glm.hpp>

#include "mesh/ray.h"

namespace grass::core::raytri {

// Slab tests round; widening tFar by this relative amount keeps them conservative (Ize,
// "Robust BVH Ray Traversal", JCGT 2013: 1 + 2·gamma(3) for float).
constexpr float BOX_SLACK = 1.0f + 4.0f * std::numeric_limits<float>::epsilon();
constexpr float INF = std::numeric_limits<float>::infinity();

// Per-ray constants of the watertight test: the axis the ray mostly follows becomes z, and a
// shear maps the ray onto +z, so each triangle is then tested in 2D.
struct RayPrep {
    glm::vec3 origin{0.0f};
    glm::vec3 invDir{0.0f};
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;
};

inline RayPrep prepareRay(const Ray& ray) {
    RayPrep r;
    const glm::vec3 d = ray.direction;
    r.origin = ray.origin;
    // 1/0 gives ±inf, which the slab test handles (NaN from 0·inf is treated as a hit).
    r.invDir = glm::vec3(1.0f) / d;
    const glm::vec3 a = glm::abs(d);
    r.kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    r.kx = (r.kz + 1) % 3;
    r.ky = (r.kx + 1) % 3;
    // Keep the winding of the sheared triangle, so U, V, W keep their signs' meaning.
    if (d[r.kz] < 0.0f)
        std::swap(r.kx, r.ky);
    r.sx = d[r.kx] / d[r.kz];
    r.sy = d[r.ky] / d[r.kz];
    r.sz = 1.0f / d[r.kz];
    return r;
}

struct TriangleHit {
    float t = INF;
    glm::vec3 weights{0.0f};  // barycentric weights of corners 0, 1, 2
};

// Woop, Benthin, Wald 2013, without backface culling. The edge functions are recomputed in
// double when one is exactly zero, so a ray through an edge is decided the same way for both
// triangles sharing it.
inline bool intersectTriangle(const RayPrep& r, const std::array<glm::vec3, 3>& corners, float maxT,
                              TriangleHit& out) {
    const glm::vec3 A = corners[0] - r.origin;
    const glm::vec3 B = corners[1] - r.origin;
    const glm::vec3 C = corners[2] - r.origin;
    const float ax = A[r.kx] - r.sx * A[r.kz], ay = A[r.ky] - r.sy * A[r.kz];
    const float bx = B[r.kx] - r.sx * B[r.kz], by = B[r.ky] - r.sy * B[r.kz];
    const float cx = C[r.kx] - r.sx * C[r.kz], cy = C[r.ky] - r.sy * C[r.kz];
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
        v = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
        w = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f))
        return false;
    const float det = u + v + w;
    if (det == 0.0f)
        return false;
    const float az = r.sz * A[r.kz], bz = r.sz * B[r.kz], cz = r.sz * C[r.kz];
    const float t = (u * az + v * bz + w * cz) / det;
    if (!(t >= 0.0f && t <= maxT))
        return false;
    out.t = t;
    out.weights = glm::vec3(u, v, w) / det;
    return true;
}

// Entry distance of the ray into the box, or INF when it misses it within [0, maxT].
inline float enterBox(const RayPrep& r, glm::vec3 boxMin, glm::vec3 boxMax, float maxT) {
    float tNear = 0.0f, tFar = maxT;
    for (int axis = 0; axis < 3; ++axis) {
        float t0 = (boxMin[axis] - r.origin[axis]) * r.invDir[axis];
        float t1 = (boxMax[axis] - r.origin[axis]) * r.invDir[axis];
        if (t0 > t1)
            std::swap(t0, t1);
        // Written so that a NaN (origin on the slab, direction 0) leaves the bounds alone.
        tNear = t0 > tNear ? t0 : tNear;
        tFar = t1 < tFar ? t1 : tFar;
    }
    return tNear <= tFar * BOX_SLACK ? tNear : INF;
}

}  // namespace grass::core::raytri
