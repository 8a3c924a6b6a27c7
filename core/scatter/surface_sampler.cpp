#include "scatter/surface_sampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/closest_point.h"
#include "util/assert.h"

namespace grass::core {

namespace {

constexpr float TWO_PI = 6.28318530717958647692f;
constexpr float PI = 3.14159265358979323846f;
// Triangles per BVH leaf: small enough that the exact distance test rarely runs in vain.
constexpr std::uint32_t BVH_LEAF_SIZE = 4;

float squaredDistanceToBox(glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 d = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    return glm::dot(d, d);
}

}  // namespace

SurfaceSampler::SurfaceSampler(const SurfaceMesh& mesh) {
    mPositions.reserve(mesh.n_vertices());
    mNormals.reserve(mesh.n_vertices());
    mUvs.reserve(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) {
        mPositions.push_back(toGlm(mesh.point(vh)));
        mNormals.push_back(toGlm(mesh.normal(vh)));
        mUvs.push_back(toGlm(mesh.texcoord2D(vh)));
    }
    mTriangles.reserve(mesh.n_faces());
    mArea.reserve(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        std::array<std::uint32_t, 3> t{};
        std::size_t corners = 0;
        for (const auto vh : mesh.fv_range(fh)) {
            if (corners < 3)
                t[corners] = static_cast<std::uint32_t>(vh.idx());
            ++corners;
        }
        if (corners != 3)
            continue;
        const glm::dvec3 a = mPositions[t[0]], b = mPositions[t[1]], c = mPositions[t[2]];
        const double twiceArea = glm::length(glm::cross(b - a, c - a));
        // A NaN or infinite vertex must not poison the whole distribution: such a face gets no
        // area, so it is never picked.
        const double area = std::isfinite(twiceArea) ? 0.5 * twiceArea : 0.0;
        mTotalArea += area;
        mTriangles.push_back(t);
        mArea.push_back(static_cast<float>(area));
    }
    if (empty())
        return;

    // Vose's alias method: weights scaled to mean 1 are split into "small" (< 1) and "large";
    // each small one is topped up from a large one, which becomes its alias.
    const std::size_t n = mTriangles.size();
    const double scale = static_cast<double>(n) / mTotalArea;
    std::vector<double> weight(n);
    std::vector<std::uint32_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        weight[i] = static_cast<double>(mArea[i]) * scale;
        (weight[i] < 1.0 ? small : large).push_back(static_cast<std::uint32_t>(i));
    }
    mAliasProbability.assign(n, 1.0f);
    mAlias.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        mAlias[i] = static_cast<std::uint32_t>(i);
    while (!small.empty() && !large.empty()) {
        const std::uint32_t s = small.back(), l = large.back();
        small.pop_back();
        mAliasProbability[s] = static_cast<float>(weight[s]);
        mAlias[s] = l;
        weight[l] -= 1.0 - weight[s];
        if (weight[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Whatever is left holds ≈ 1 up to rounding and keeps probability 1, except a face with no
    // area, which rounding must never make pickable: point it at the largest face.
    const auto largest =
        static_cast<std::uint32_t>(std::max_element(mArea.begin(), mArea.end()) - mArea.begin());
    for (std::size_t i = 0; i < n; ++i) {
        if (!(mArea[i] > 0.0f)) {
            mAliasProbability[i] = 0.0f;
            if (!(mArea[mAlias[i]] > 0.0f))
                mAlias[i] = largest;
        }
    }
}

std::uint32_t SurfaceSampler::pickTriangle(Rng& rng) const {
    const std::uint32_t i = rng.below(static_cast<std::uint32_t>(mTriangles.size()));
    return rng.uniform() < mAliasProbability[i] ? i : mAlias[i];
}

glm::vec3 SurfaceSampler::faceNormal(std::uint32_t triangle) const {
    const glm::vec3 a = point(triangle, 0);
    const glm::vec3 n = glm::cross(point(triangle, 1) - a, point(triangle, 2) - a);
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
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
    l.position = (1.0f - l.b1 - l.b2) * point(l.triangle, 0) + l.b1 * point(l.triangle, 1) +
                 l.b2 * point(l.triangle, 2);
    return l;
}

SurfaceSample SurfaceSampler::sample(Rng& rng) const {
    const Location l = locate(rng);
    return evaluate(l.triangle, l.b1, l.b2);
}

SurfaceSample SurfaceSampler::evaluate(std::uint32_t triangle, float b1, float b2) const {
    const std::array<std::uint32_t, 3>& t = mTriangles[triangle];
    const float b0 = 1.0f - b1 - b2;
    SurfaceSample s;
    s.triangle = triangle;
    s.position = b0 * mPositions[t[0]] + b1 * mPositions[t[1]] + b2 * mPositions[t[2]];
    s.uv = b0 * mUvs[t[0]] + b1 * mUvs[t[1]] + b2 * mUvs[t[2]];
    const glm::vec3 n = b0 * mNormals[t[0]] + b1 * mNormals[t[1]] + b2 * mNormals[t[2]];
    const float length = glm::length(n);
    s.normal = (length > 1e-6f && std::isfinite(length)) ? n / length : faceNormal(triangle);
    return s;
}

void SurfaceSampler::buildNeighbourhoodIndex() {
    if (!mBvh.empty() || mTriangles.empty())
        return;
    // The build sorts these compact boxes in place rather than chasing indices into the
    // vertex arrays at every comparison.
    std::vector<BvhItem> items(mTriangles.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        const auto t = static_cast<std::uint32_t>(i);
        items[i].min = glm::min(glm::min(point(t, 0), point(t, 1)), point(t, 2));
        items[i].max = glm::max(glm::max(point(t, 0), point(t, 1)), point(t, 2));
        items[i].triangle = t;
    }
    mBvh.reserve(2 * items.size() / BVH_LEAF_SIZE + 1);
    buildNode(items, 0, static_cast<std::uint32_t>(items.size()));
    mBvhOrder.resize(items.size());
    for (std::size_t i = 0; i < items.size(); ++i)
        mBvhOrder[i] = items[i].triangle;
}

std::uint32_t SurfaceSampler::buildNode(std::vector<BvhItem>& items, std::uint32_t first,
                                        std::uint32_t count) {
    const auto nodeIndex = static_cast<std::uint32_t>(mBvh.size());
    mBvh.push_back({});
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    glm::vec3 centroidLo = lo, centroidHi = hi;
    for (std::uint32_t i = first; i < first + count; ++i) {
        lo = glm::min(lo, items[i].min);
        hi = glm::max(hi, items[i].max);
        const glm::vec3 c = items[i].min + items[i].max;  // twice the centre: same order
        centroidLo = glm::min(centroidLo, c);
        centroidHi = glm::max(centroidHi, c);
    }
    mBvh[nodeIndex].min = lo;
    mBvh[nodeIndex].max = hi;
    if (count <= BVH_LEAF_SIZE) {
        mBvh[nodeIndex].first = first;
        mBvh[nodeIndex].count = count;
        return nodeIndex;
    }
    const glm::vec3 extent = centroidHi - centroidLo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t half = count / 2;
    const auto begin = items.begin() + first;
    // Ties broken by index: the tree is the same on every standard library.
    std::nth_element(begin, begin + half, begin + count,
                     [axis](const BvhItem& l, const BvhItem& r) {
                         const float kl = l.min[axis] + l.max[axis], kr = r.min[axis] + r.max[axis];
                         return kl < kr || (kl == kr && l.triangle < r.triangle);
                     });
    buildNode(items, first, half);
    const std::uint32_t right = buildNode(items, first + half, count - half);
    mBvh[nodeIndex].first = right;
    mBvh[nodeIndex].count = 0;
    return nodeIndex;
}

void SurfaceSampler::trianglesNear(glm::vec3 centre, float radius,
                                   std::vector<std::uint32_t>& out) const {
    GRASS_ASSERT(hasNeighbourhoodIndex());
    out.clear();
    if (mBvh.empty() || !(radius >= 0.0f))
        return;
    const float r2 = radius * radius;
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const std::uint32_t nodeIndex = stack.back();
        stack.pop_back();
        const BvhNode& node = mBvh[nodeIndex];
        if (squaredDistanceToBox(centre, node.min, node.max) > r2)
            continue;
        if (node.count == 0) {
            stack.push_back(node.first);
            stack.push_back(nodeIndex + 1);
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            const std::uint32_t t = mBvhOrder[i];
            const glm::vec3 q =
                closestPointOnTriangle(centre, point(t, 0), point(t, 1), point(t, 2));
            if (glm::dot(q - centre, q - centre) <= r2)
                out.push_back(t);
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
        glm::vec3 normal;
        glm::vec3 discCentre;
        float discRadius;
    };
    std::vector<Domain> domains;
    std::vector<double> cumulative;
    double total = 0.0;
    for (const std::uint32_t index : near) {
        const double area = static_cast<double>(mArea[index]);
        if (!(area > 0.0))
            continue;
        const glm::vec3 normal = faceNormal(index);
        const float planeDistance = glm::dot(centre - point(index, 0), normal);
        const float discRadius2 = std::max(radius * radius - planeDistance * planeDistance, 0.0f);
        const double discArea = static_cast<double>(PI * discRadius2);
        Domain d{index, discArea < area, normal, centre - planeDistance * normal,
                 std::sqrt(discRadius2)};
        total += std::min(discArea, area);
        domains.push_back(d);
        cumulative.push_back(total);
    }
    if (!(total > 0.0))
        return 0;
    const float r2 = radius * radius;
    std::size_t added = 0;
    for (std::size_t attempt = 0; attempt < maxAttempts && added < count; ++attempt) {
        const double pick = rng.uniformDouble() * total;
        const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), pick);
        const Domain& d = domains[std::min(static_cast<std::size_t>(it - cumulative.begin()),
                                           domains.size() - 1)];
        const glm::vec3 p0 = point(d.triangle, 0), p1 = point(d.triangle, 1);
        const glm::vec3 p2 = point(d.triangle, 2);
        const float x = rng.uniform(), y = rng.uniform();
        if (!d.disc) {
            float b1 = x, b2 = y;
            if (b1 + b2 > 1.0f) {
                b1 = 1.0f - b1;
                b2 = 1.0f - b2;
            }
            const SurfaceSample s = evaluate(d.triangle, b1, b2);
            if (glm::dot(s.position - centre, s.position - centre) > r2)
                continue;
            out.push_back(s);
            ++added;
            continue;
        }
        // Uniform in the disc: radius ∝ √x.
        const glm::vec3 tangent = glm::normalize(p1 - p0);
        const glm::vec3 bitangent = glm::cross(d.normal, tangent);
        const float rho = d.discRadius * std::sqrt(x), angle = TWO_PI * y;
        const glm::vec3 q =
            d.discCentre + rho * (std::cos(angle) * tangent + std::sin(angle) * bitangent);
        // Barycentrics of q (Ericson §3.4).
        const glm::vec3 e1 = p1 - p0, e2 = p2 - p0, e = q - p0;
        const float d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
        const float de1 = glm::dot(e, e1), de2 = glm::dot(e, e2);
        const float denom = d11 * d22 - d12 * d12;
        if (!(denom > 0.0f))
            continue;
        const float b1 = (d22 * de1 - d12 * de2) / denom;
        const float b2 = (d11 * de2 - d12 * de1) / denom;
        if (b1 < 0.0f || b2 < 0.0f || b1 + b2 > 1.0f)
            continue;
        out.push_back(evaluate(d.triangle, b1, b2));
        ++added;
    }
    return added;
}

}  // namespace grass::core
