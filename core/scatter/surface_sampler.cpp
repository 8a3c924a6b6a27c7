#include "scatter/surface_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/assert.h"

namespace grass::core {

namespace {

constexpr float TWO_PI = 6.28318530717958647692f;
constexpr float PI = 3.14159265358979323846f;
// Triangles per BVH leaf: small enough that the exact distance test rarely runs in vain.
constexpr std::uint32_t BVH_LEAF_SIZE = 4;

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection §5.1.5).
glm::vec3 closestPointOnTriangle(glm::vec3 p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const float denom = 1.0f / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

float squaredDistanceToBox(glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 d = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    return glm::dot(d, d);
}

}  // namespace

SurfaceSampler::SurfaceSampler(const SurfaceMesh& mesh) {
    mTriangles.reserve(mesh.n_faces());
    mCumulativeArea.reserve(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        Triangle t;
        int i = 0;
        for (const auto vh : mesh.fv_range(fh)) {
            if (i == 3) break;
            const auto k = static_cast<std::size_t>(i++);
            t.p[k] = toGlm(mesh.point(vh));
            t.n[k] = toGlm(mesh.normal(vh));
            t.uv[k] = toGlm(mesh.texcoord2D(vh));
        }
        if (i != 3) continue;
        const glm::dvec3 a = t.p[0], b = t.p[1], c = t.p[2];
        const glm::dvec3 cross = glm::cross(b - a, c - a);
        const double twiceArea = glm::length(cross);
        // A NaN or infinite vertex must not poison the whole distribution: such a face gets no
        // area, so it is never picked.
        t.area = std::isfinite(twiceArea) ? 0.5 * twiceArea : 0.0;
        if (t.area > 0.0) t.faceNormal = glm::vec3(cross / twiceArea);
        mTotalArea += t.area;
        mTriangles.push_back(t);
        mCumulativeArea.push_back(mTotalArea);
    }
}

std::uint32_t SurfaceSampler::pickTriangle(Rng& rng) const {
    const double r = rng.uniformDouble() * mTotalArea;
    // upper_bound never lands on a zero-area triangle: its cumulative value equals the
    // previous one, and r must be strictly below it.
    const auto it = std::upper_bound(mCumulativeArea.begin(), mCumulativeArea.end(), r);
    const auto index = static_cast<std::size_t>(it - mCumulativeArea.begin());
    if (index < mTriangles.size()) return static_cast<std::uint32_t>(index);
    // r rounded up to the total: take the last triangle that has area.
    std::size_t last = mTriangles.size() - 1;
    while (last > 0 && mTriangles[last].area <= 0.0) --last;
    return static_cast<std::uint32_t>(last);
}

SurfaceSampler::Location SurfaceSampler::locate(Rng& rng) const {
    GRASS_ASSERT(!empty());
    Location l;
    l.triangle = pickTriangle(rng);
    l.b1 = rng.uniform();
    l.b2 = rng.uniform();
    // Reflect the upper half of the unit square onto the lower: uniform over the triangle.
    if (l.b1 + l.b2 > 1.0f) {
        l.b1 = 1.0f - l.b1;
        l.b2 = 1.0f - l.b2;
    }
    const Triangle& t = mTriangles[l.triangle];
    l.position = (1.0f - l.b1 - l.b2) * t.p[0] + l.b1 * t.p[1] + l.b2 * t.p[2];
    return l;
}

SurfaceSample SurfaceSampler::sample(Rng& rng) const {
    const Location l = locate(rng);
    return evaluate(l.triangle, l.b1, l.b2);
}

SurfaceSample SurfaceSampler::evaluate(std::uint32_t triangle, float b1, float b2) const {
    const Triangle& t = mTriangles[triangle];
    const float b0 = 1.0f - b1 - b2;
    SurfaceSample s;
    s.triangle = triangle;
    s.position = b0 * t.p[0] + b1 * t.p[1] + b2 * t.p[2];
    s.uv = b0 * t.uv[0] + b1 * t.uv[1] + b2 * t.uv[2];
    const glm::vec3 n = b0 * t.n[0] + b1 * t.n[1] + b2 * t.n[2];
    const float length = glm::length(n);
    s.normal = (length > 1e-6f && std::isfinite(length)) ? n / length : t.faceNormal;
    return s;
}

void SurfaceSampler::buildNeighbourhoodIndex() {
    if (!mBvh.empty() || mTriangles.empty()) return;
    mBvhOrder.resize(mTriangles.size());
    for (std::size_t i = 0; i < mBvhOrder.size(); ++i) mBvhOrder[i] = static_cast<std::uint32_t>(i);
    mBvh.reserve(2 * mTriangles.size() / BVH_LEAF_SIZE + 1);
    buildNode(0, static_cast<std::uint32_t>(mTriangles.size()));
}

std::uint32_t SurfaceSampler::buildNode(std::uint32_t first, std::uint32_t count) {
    const auto nodeIndex = static_cast<std::uint32_t>(mBvh.size());
    mBvh.push_back({});
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    glm::vec3 centroidLo = lo, centroidHi = hi;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const Triangle& t = mTriangles[mBvhOrder[i]];
        const glm::vec3 tmin = glm::min(glm::min(t.p[0], t.p[1]), t.p[2]);
        const glm::vec3 tmax = glm::max(glm::max(t.p[0], t.p[1]), t.p[2]);
        lo = glm::min(lo, tmin);
        hi = glm::max(hi, tmax);
        centroidLo = glm::min(centroidLo, 0.5f * (tmin + tmax));
        centroidHi = glm::max(centroidHi, 0.5f * (tmin + tmax));
    }
    mBvh[nodeIndex].min = lo;
    mBvh[nodeIndex].max = hi;
    if (count <= BVH_LEAF_SIZE) {
        mBvh[nodeIndex].first = first;
        mBvh[nodeIndex].count = count;
        return nodeIndex;
    }
    const glm::vec3 extent = centroidHi - centroidLo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t half = count / 2;
    const auto key = [&](std::uint32_t index) {
        const Triangle& t = mTriangles[index];
        return std::min({t.p[0][axis], t.p[1][axis], t.p[2][axis]}) +
               std::max({t.p[0][axis], t.p[1][axis], t.p[2][axis]});
    };
    // Ties broken by index: the tree is the same on every standard library.
    const auto begin = mBvhOrder.begin() + first;
    std::nth_element(begin, begin + half, begin + count, [&](std::uint32_t l, std::uint32_t r) {
        const float kl = key(l), kr = key(r);
        return kl < kr || (kl == kr && l < r);
    });
    buildNode(first, half);
    const std::uint32_t right = buildNode(first + half, count - half);
    mBvh[nodeIndex].first = right;
    mBvh[nodeIndex].count = 0;
    return nodeIndex;
}

void SurfaceSampler::trianglesNear(glm::vec3 centre, float radius,
                                   std::vector<std::uint32_t>& out) const {
    GRASS_ASSERT(hasNeighbourhoodIndex());
    out.clear();
    if (mBvh.empty() || !(radius >= 0.0f)) return;
    const float r2 = radius * radius;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const std::uint32_t nodeIndex = stack.back();
        stack.pop_back();
        const BvhNode& node = mBvh[nodeIndex];
        if (squaredDistanceToBox(centre, node.min, node.max) > r2) continue;
        if (node.count == 0) {
            stack.push_back(node.first);
            stack.push_back(nodeIndex + 1);
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            const Triangle& t = mTriangles[mBvhOrder[i]];
            const glm::vec3 q = closestPointOnTriangle(centre, t.p[0], t.p[1], t.p[2]);
            if (glm::dot(q - centre, q - centre) <= r2) out.push_back(mBvhOrder[i]);
        }
    }
    std::sort(out.begin(), out.end());
}

std::size_t SurfaceSampler::sampleNear(glm::vec3 centre, float radius, std::size_t count,
                                       std::size_t maxAttempts, Rng& rng,
                                       std::vector<SurfaceSample>& out) const {
    std::vector<std::uint32_t> near;
    trianglesNear(centre, radius, near);
    // Rejection sampling over the union of each triangle's intersection with the ball. Each
    // triangle proposes from the smaller of two domains that both contain that intersection:
    // the triangle itself (rejecting points outside the ball), or the disc the ball cuts from
    // its plane (rejecting points outside the triangle). Each proposal is uniform on its
    // domain and the domain is picked with probability ∝ its area, so accepted points are
    // uniform over the surface inside the ball, whatever the triangle sizes.
    struct Domain {
        std::uint32_t triangle;
        bool disc;
        glm::vec3 discCentre;
        float discRadius;
    };
    std::vector<Domain> domains;
    std::vector<double> cumulative;
    double total = 0.0;
    for (const std::uint32_t index : near) {
        const Triangle& t = mTriangles[index];
        if (!(t.area > 0.0)) continue;
        const float planeDistance = glm::dot(centre - t.p[0], t.faceNormal);
        const float discRadius2 = std::max(radius * radius - planeDistance * planeDistance, 0.0f);
        const double discArea = static_cast<double>(PI * discRadius2);
        Domain d{index, discArea < t.area, centre - planeDistance * t.faceNormal,
                 std::sqrt(discRadius2)};
        total += std::min(discArea, t.area);
        domains.push_back(d);
        cumulative.push_back(total);
    }
    if (!(total > 0.0)) return 0;
    const float r2 = radius * radius;
    std::size_t added = 0;
    for (std::size_t attempt = 0; attempt < maxAttempts && added < count; ++attempt) {
        const double pick = rng.uniformDouble() * total;
        const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), pick);
        const Domain& d = domains[std::min(static_cast<std::size_t>(it - cumulative.begin()),
                                           domains.size() - 1)];
        const Triangle& t = mTriangles[d.triangle];
        const float x = rng.uniform(), y = rng.uniform();
        if (!d.disc) {
            float b1 = x, b2 = y;
            if (b1 + b2 > 1.0f) {
                b1 = 1.0f - b1;
                b2 = 1.0f - b2;
            }
            const SurfaceSample s = evaluate(d.triangle, b1, b2);
            if (glm::dot(s.position - centre, s.position - centre) > r2) continue;
            out.push_back(s);
            ++added;
            continue;
        }
        // Uniform in the disc: radius ∝ √x.
        const glm::vec3 tangent = glm::normalize(t.p[1] - t.p[0]);
        const glm::vec3 bitangent = glm::cross(t.faceNormal, tangent);
        const float rho = d.discRadius * std::sqrt(x), angle = TWO_PI * y;
        const glm::vec3 q =
            d.discCentre + rho * (std::cos(angle) * tangent + std::sin(angle) * bitangent);
        // Barycentrics of q (Ericson §3.4).
        const glm::vec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0], e = q - t.p[0];
        const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
        const float de1 = glm::dot(e, e1), de2 = glm::dot(e, e2);
        const float denom = d11 * d22 - d12 * d12;
        if (!(denom > 0.0f)) continue;
        const float b1 = (d22 * de1 - d12 * de2) / denom;
        const float b2 = (d11 * de2 - d12 * de1) / denom;
        if (b1 < 0.0f || b2 < 0.0f || b1 + b2 > 1.0f) continue;
        out.push_back(evaluate(d.triangle, b1, b2));
        ++added;
    }
    return added;
}

}  // namespace grass::core
