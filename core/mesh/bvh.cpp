#include "mesh/bvh.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mesh/ray_triangle.h"
#include "util/assert.h"

namespace grass::core {

namespace {

using namespace raytri;

// Binned SAH (Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", 2007):
// 16 bins per axis find splits within a few percent of the full sweep at a fraction of its cost.
constexpr int BIN_COUNT = 16;
// Below this many triangles a leaf is cheaper than a split whatever the SAH says.
constexpr std::uint32_t MIN_SPLIT = 3;
// SAH leaves with more triangles than this are split anyway: a pick must stay cheap.
constexpr std::uint32_t MAX_LEAF = 8;
// Cost of visiting a node relative to one ray–triangle test.
constexpr float TRAVERSAL_COST = 1.0f;
// Past this depth splits are by object median, which bounds the depth by log2 of the count.
constexpr int MAX_SAH_DEPTH = 48;
// Traversal stack: MAX_SAH_DEPTH plus log2(2^32) median levels, with room to spare.
constexpr int STACK_SIZE = 96;

struct Box {
    glm::vec3 min{INF};
    glm::vec3 max{-INF};
    void grow(glm::vec3 p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Box& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    float halfArea() const {
        const glm::vec3 e = glm::max(max - min, glm::vec3(0.0f));
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

struct BuildItem {
    Box box;
    glm::vec3 centroid{0.0f};
    std::uint32_t triangle = 0;
};

// The closest hit so far; equal t goes to the lower source triangle (see intersect()).
struct Best {
    TriangleHit hit;
    std::uint32_t source = 0;
    bool found = false;
    void offer(const TriangleHit& h, std::uint32_t triangle) {
        if (!found || h.t < hit.t || (h.t == hit.t && triangle < source)) {
            hit = h;
            source = triangle;
            found = true;
        }
    }
};

}  // namespace

struct TriangleBvh::Candidate {
    TriangleHit hit;
    std::uint32_t source = 0;
};

TriangleSoup triangleSoupOf(const SurfaceMesh& mesh) {
    TriangleSoup soup;
    soup.positions.reserve(mesh.n_vertices());
    soup.normals.reserve(mesh.n_vertices());
    soup.uvs.reserve(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) {
        soup.positions.push_back(toGlm(mesh.point(vh)));
        soup.normals.push_back(toGlm(mesh.normal(vh)));
        soup.uvs.push_back(toGlm(mesh.texcoord2D(vh)));
    }
    soup.triangles = triangleIndices(mesh);
    return soup;
}

TriangleBvh::TriangleBvh(const SurfaceMesh& mesh) : mSoup(triangleSoupOf(mesh)) {
    build();
}

TriangleBvh::TriangleBvh(TriangleSoup soup) : mSoup(std::move(soup)) {
    GRASS_ASSERT(mSoup.normals.empty() || mSoup.normals.size() == mSoup.positions.size());
    GRASS_ASSERT(mSoup.uvs.empty() || mSoup.uvs.size() == mSoup.positions.size());
    for (const auto& tri : mSoup.triangles)
        for (const std::uint32_t index : tri)
            GRASS_ASSERT(index < mSoup.positions.size());
    build();
}

Bounds TriangleBvh::bounds() const {
    if (mNodes.empty())
        return Bounds{};
    return Bounds{mNodes[0].boundsMin, mNodes[0].boundsMax};
}

void TriangleBvh::build() {
    const auto& triangles = mSoup.triangles;
    std::vector<BuildItem> items(triangles.size());
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        for (const std::uint32_t index : triangles[i])
            items[i].box.grow(mSoup.positions[index]);
        items[i].centroid = 0.5f * (items[i].box.min + items[i].box.max);
        items[i].triangle = i;
    }
    mNodes.clear();
    mLeafTriangles.clear();
    if (items.empty())
        return;
    mNodes.reserve(2 * items.size() / MIN_SPLIT + 1);
    mLeafTriangles.reserve(items.size());

    const auto emitLeaf = [&](Node& node, std::size_t begin, std::size_t end) {
        node.offset = static_cast<std::uint32_t>(mLeafTriangles.size());
        node.count = static_cast<std::uint32_t>(end - begin);
        for (std::size_t i = begin; i < end; ++i) {
            const auto& tri = triangles[items[i].triangle];
            mLeafTriangles.push_back(
                {{mSoup.positions[tri[0]], mSoup.positions[tri[1]], mSoup.positions[tri[2]]},
                 items[i].triangle});
        }
    };

    // Depth-first with an explicit stack so the left child always follows its parent.
    struct Task {
        std::size_t begin, end;
        int depth;
        std::uint32_t parent;  // whose `offset` becomes this node (right children), or ~0
    };
    std::vector<Task> tasks{{0, items.size(), 0, ~0u}};
    while (!tasks.empty()) {
        const Task task = tasks.back();
        tasks.pop_back();
        const auto nodeIndex = static_cast<std::uint32_t>(mNodes.size());
        if (task.parent != ~0u)
            mNodes[task.parent].offset = nodeIndex;
        mNodes.emplace_back();
        Box box, centroids;
        for (std::size_t i = task.begin; i < task.end; ++i) {
            box.grow(items[i].box);
            centroids.grow(items[i].centroid);
        }
        // A hair of padding (relative to the coordinates' magnitude) covers the rounding of
        // the slab test against the triangle test at grazing angles.
        const float magnitude =
            std::max(glm::length(box.min), glm::length(box.max)) + glm::length(box.max - box.min);
        const glm::vec3 pad(1e-6f * magnitude);
        mNodes[nodeIndex].boundsMin = box.min - pad;
        mNodes[nodeIndex].boundsMax = box.max + pad;
        const std::size_t count = task.end - task.begin;
        if (count <= MIN_SPLIT) {
            emitLeaf(mNodes[nodeIndex], task.begin, task.end);
            continue;
        }

        // Best binned SAH split over the three axes.
        const glm::vec3 extent = centroids.max - centroids.min;
        float bestCost = INF;
        int bestAxis = -1, bestSplit = 0;
        for (int axis = 0; axis < 3 && task.depth < MAX_SAH_DEPTH; ++axis) {
            if (!(extent[axis] > 0.0f))
                continue;
            const float scale = float(BIN_COUNT) / extent[axis];
            Box bins[BIN_COUNT];
            std::uint32_t counts[BIN_COUNT] = {};
            for (std::size_t i = task.begin; i < task.end; ++i) {
                const int bin = std::min(
                    BIN_COUNT - 1, int((items[i].centroid[axis] - centroids.min[axis]) * scale));
                bins[bin].grow(items[i].box);
                ++counts[bin];
            }
            // Sweep from the right for the right-hand areas, then from the left.
            float rightArea[BIN_COUNT];
            std::uint32_t rightCount[BIN_COUNT];
            Box acc;
            std::uint32_t n = 0;
            for (int b = BIN_COUNT - 1; b > 0; --b) {
                acc.grow(bins[b]);
                n += counts[b];
                rightArea[b] = acc.halfArea();
                rightCount[b] = n;
            }
            acc = Box{};
            n = 0;
            for (int b = 1; b < BIN_COUNT; ++b) {
                acc.grow(bins[b - 1]);
                n += counts[b - 1];
                if (n == 0 || rightCount[b] == 0)
                    continue;
                const float cost = acc.halfArea() * float(n) + rightArea[b] * float(rightCount[b]);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = b;
                }
            }
        }

        std::size_t mid = task.begin;
        if (bestAxis >= 0) {
            const float parentArea = box.halfArea();
            const float splitCost =
                TRAVERSAL_COST + (parentArea > 0.0f ? bestCost / parentArea : float(count));
            if (splitCost >= float(count) && count <= MAX_LEAF) {
                emitLeaf(mNodes[nodeIndex], task.begin, task.end);
                continue;
            }
            const float scale = float(BIN_COUNT) / extent[bestAxis];
            const float lo = centroids.min[bestAxis];
            const auto right = std::partition(
                items.begin() + std::ptrdiff_t(task.begin),
                items.begin() + std::ptrdiff_t(task.end), [&](const BuildItem& item) {
                    return std::min(BIN_COUNT - 1, int((item.centroid[bestAxis] - lo) * scale)) <
                           bestSplit;
                });
            mid = std::size_t(right - items.begin());
        }
        if (mid == task.begin || mid == task.end) {
            // No usable SAH split (coincident centroids, or too deep): halve by object median
            // along the widest centroid axis, which always makes progress.
            const int axis = extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2)
                                                  : (extent.y >= extent.z ? 1 : 2);
            mid = task.begin + count / 2;
            std::nth_element(items.begin() + std::ptrdiff_t(task.begin),
                             items.begin() + std::ptrdiff_t(mid),
                             items.begin() + std::ptrdiff_t(task.end),
                             [axis](const BuildItem& a, const BuildItem& b) {
                                 return a.centroid[axis] < b.centroid[axis];
                             });
        }
        // Right first onto the stack, so the left child is built next, at nodeIndex + 1.
        tasks.push_back({mid, task.end, task.depth + 1, nodeIndex});
        tasks.push_back({task.begin, mid, task.depth + 1, ~0u});
    }
}

std::optional<RayHit> TriangleBvh::intersect(const Ray& ray, float maxT) const {
    if (mNodes.empty() || !isUsableRay(ray) || !(maxT >= 0.0f))
        return std::nullopt;
    const RayPrep r = prepareRay(ray);
    Best best;
    float limit = maxT;
    struct Entry {
        std::uint32_t node;
        float tEnter;
    };
    Entry stack[STACK_SIZE];
    int top = 0;
    if (enterBox(r, mNodes[0].boundsMin, mNodes[0].boundsMax, limit) == INF)
        return std::nullopt;
    std::uint32_t nodeIndex = 0;
    while (true) {
        const Node& node = mNodes[nodeIndex];
        bool descend = false;
        if (node.count > 0) {
            for (std::uint32_t i = node.offset; i < node.offset + node.count; ++i) {
                TriangleHit hit;
                if (intersectTriangle(r, mLeafTriangles[i].corners, limit, hit)) {
                    best.offer(hit, mLeafTriangles[i].source);
                    limit = best.hit.t;
                }
            }
        } else {
            const std::uint32_t left = nodeIndex + 1, right = node.offset;
            const float tLeft = enterBox(r, mNodes[left].boundsMin, mNodes[left].boundsMax, limit);
            const float tRight =
                enterBox(r, mNodes[right].boundsMin, mNodes[right].boundsMax, limit);
            if (tLeft != INF && tRight != INF) {
                const bool leftFirst = tLeft <= tRight;
                GRASS_ASSERT(top < STACK_SIZE);
                stack[top++] = leftFirst ? Entry{right, tRight} : Entry{left, tLeft};
                nodeIndex = leftFirst ? left : right;
                descend = true;
            } else if (tLeft != INF || tRight != INF) {
                nodeIndex = tLeft != INF ? left : right;
                descend = true;
            }
        }
        if (descend)
            continue;
        // Pop the next subtree that may still hold something at or before the best hit.
        bool popped = false;
        while (top > 0) {
            const Entry e = stack[--top];
            if (e.tEnter <= limit * BOX_SLACK) {
                nodeIndex = e.node;
                popped = true;
                break;
            }
        }
        if (!popped)
            break;
    }
    if (!best.found)
        return std::nullopt;
    return makeHit(ray, Candidate{best.hit, best.source});
}

RayHit TriangleBvh::makeHit(const Ray& ray, const Candidate& candidate) const {
    const auto& tri = mSoup.triangles[candidate.source];
    const glm::vec3 w = candidate.hit.weights;
    const glm::vec3 p0 = mSoup.positions[tri[0]], p1 = mSoup.positions[tri[1]],
                    p2 = mSoup.positions[tri[2]];
    RayHit hit;
    hit.t = candidate.hit.t;
    hit.triangle = candidate.source;
    hit.barycentric = w;
    // From the weights rather than origin + t·direction: the point then lies on the triangle
    // to rounding, whatever the distance from the ray's origin.
    hit.posWorld = w.x * p0 + w.y * p1 + w.z * p2;
    const glm::vec3 cross = glm::cross(p1 - p0, p2 - p0);
    const float crossLength = glm::length(cross);
    hit.geometricNormal = crossLength > 0.0f ? cross / crossLength : glm::vec3(0, 1, 0);
    hit.normal = hit.geometricNormal;
    if (!mSoup.normals.empty()) {
        const glm::vec3 n =
            w.x * mSoup.normals[tri[0]] + w.y * mSoup.normals[tri[1]] + w.z * mSoup.normals[tri[2]];
        const float length = glm::length(n);
        if (length > 1e-12f && std::isfinite(length))
            hit.normal = n / length;
    }
    if (!mSoup.uvs.empty())
        hit.uv = w.x * mSoup.uvs[tri[0]] + w.y * mSoup.uvs[tri[1]] + w.z * mSoup.uvs[tri[2]];
    hit.frontFace = glm::dot(hit.geometricNormal, ray.direction) <= 0.0f;
    return hit;
}

std::optional<RayHit> bruteForceIntersect(const TriangleBvh& bvh, const Ray& ray, float maxT) {
    if (bvh.mLeafTriangles.empty() || !isUsableRay(ray) || !(maxT >= 0.0f))
        return std::nullopt;
    const RayPrep r = prepareRay(ray);
    Best best;
    float limit = maxT;
    for (const auto& leaf : bvh.mLeafTriangles) {
        TriangleHit hit;
        if (intersectTriangle(r, leaf.corners, limit, hit)) {
            best.offer(hit, leaf.source);
            limit = best.hit.t;
        }
    }
    if (!best.found)
        return std::nullopt;
    return bvh.makeHit(ray, TriangleBvh::Candidate{best.hit, best.source});
}

}  // namespace grass::core
