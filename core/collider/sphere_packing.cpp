#include "collider/sphere_packing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>

#include "util/rng.h"

namespace grass::core {

namespace {

using Triangle = std::array<glm::vec3, 3>;

constexpr double PI = 3.14159265358979323846;
// Half the diagonal of a unit voxel: every voxel centre owns a unit cube that lies within
// this distance of it, which turns ball volumes into bounds on voxel counts.
constexpr double HALF_DIAGONAL = 0.86602540378443865;
// Six rays (both ways along three lines) vote; four agree → inside. A hole or a flipped face
// misleads only the rays that pass through it.
constexpr int VOTES_FOR_INSIDE = 4;
constexpr std::uint32_t MEASURE_SAMPLES = 32768;
constexpr std::uint64_t MEASURE_SEED = 0x5350484552455321ULL;  // "SPHERES!"
constexpr std::uint32_t BVH_LEAF_SIZE = 4;
constexpr std::uint32_t NONE = std::numeric_limits<std::uint32_t>::max();
// A ball that sticks out of a neighbour's ball by less than this share of a voxel counts as
// inside it (float rounding of the two distances).
constexpr float DOMINANCE_SLACK = 1e-4f;
// Big balls barely change when their centre moves by a voxel, and counting their gain costs
// their cross-section: candidates of radius ρ voxels are kept only on a lattice of step
// ⌊ρ / THINNING_RADIUS⌋ voxels, plus every local maximum of the radius (the medial ridge,
// where the best big balls are).
constexpr double THINNING_RADIUS = 4.0;
// Steps of the chosen candidate's climb to a better neighbour: more than the thinning stride
// at the radii that occur (ρ < 64 voxels at resolution 256).
constexpr int MAX_CLIMB_STEPS = 16;

// ---- Inside votes ------------------------------------------------------------------------

// The crossings on one side of a point along a line: how many, and their signed sum (+1 where
// the face normal points along the ray).
struct RaySide {
    int count = 0;
    int sum = 0;
};

// The two rays of a line through a point, as inside votes. Winding number (nonzero sum) is the
// rule, so overlapping closed parts stay inside; but a line whose total is even and nonzero
// crosses a face wound the wrong way, and there parity is the right rule.
int lineVotes(RaySide before, RaySide after, int total) {
    const bool parity = total != 0 && total % 2 == 0;
    const auto vote = [parity](RaySide side) {
        return parity ? side.count % 2 == 1 : side.sum != 0;
    };
    return (vote(before) ? 1 : 0) + (vote(after) ? 1 : 0);
}

// ---- Triangle BVH: nearest-triangle distance ---------------------------------------------

float pointTriangleDistanceSq(glm::vec3 p, const Triangle& t) {
    // Ericson, Real-Time Collision Detection §5.1.5: the Voronoi region of p.
    const glm::vec3 a = t[0], b = t[1], c = t[2];
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const auto lengthSq = [](glm::vec3 v) { return glm::dot(v, v); };
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f)
        return lengthSq(ap);
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3)
        return lengthSq(bp);
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f)
        return lengthSq(ap - ab * (d1 / (d1 - d3)));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6)
        return lengthSq(cp);
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f)
        return lengthSq(ap - ac * (d2 / (d2 - d6)));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && d4 - d3 >= 0.0f && d5 - d6 >= 0.0f)
        return lengthSq(bp - (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const float denom = 1.0f / (va + vb + vc);
    return lengthSq(ap - ab * (vb * denom) - ac * (vc * denom));
}

struct BvhNode {
    glm::vec3 lo{0.0f};
    glm::vec3 hi{0.0f};
    std::uint32_t start = 0;  // leaf: first triangle; inner: the second child (first: next)
    std::uint32_t count = 0;  // triangles in a leaf; 0 for an inner node
};

class TriangleBvh {
public:
    explicit TriangleBvh(std::vector<Triangle> triangles) : mTriangles(std::move(triangles)) {
        std::vector<std::uint32_t> order(mTriangles.size());
        std::iota(order.begin(), order.end(), 0u);
        std::vector<glm::vec3> centroids(mTriangles.size());
        for (std::size_t i = 0; i < mTriangles.size(); ++i)
            centroids[i] = (mTriangles[i][0] + mTriangles[i][1] + mTriangles[i][2]) / 3.0f;
        mNodes.reserve(2 * mTriangles.size() / BVH_LEAF_SIZE + 2);
        build(order, centroids, 0, static_cast<std::uint32_t>(order.size()));
        std::vector<Triangle> sorted(mTriangles.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            sorted[i] = mTriangles[order[i]];
        mTriangles = std::move(sorted);
    }

    // In tree order: the indices the queries return.
    const std::vector<Triangle>& triangles() const { return mTriangles; }

    float distanceSqTo(glm::vec3 p, std::uint32_t triangle) const {
        return pointTriangleDistanceSq(p, mTriangles[triangle]);
    }

    // The squared distance from p to the nearest triangle when below bestSq (else bestSq), and
    // that triangle in `nearest`. A tight starting bound prunes most of the tree.
    float nearestSq(glm::vec3 p, float bestSq, std::uint32_t& nearest) const {
        std::array<std::uint32_t, 128> stack{};
        std::size_t top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const std::uint32_t index = stack[--top];
            const BvhNode& node = mNodes[index];
            if (boxDistanceSq(node, p) >= bestSq)
                continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.start; i < node.start + node.count; ++i) {
                    const float d = pointTriangleDistanceSq(p, mTriangles[i]);
                    if (d < bestSq) {
                        bestSq = d;
                        nearest = i;
                    }
                }
                continue;
            }
            const std::uint32_t first = index + 1, second = node.start;
            const bool firstNearer =
                boxDistanceSq(mNodes[first], p) <= boxDistanceSq(mNodes[second], p);
            stack[top++] = firstNearer ? second : first;
            stack[top++] = firstNearer ? first : second;
        }
        return bestSq;
    }

private:
    std::uint32_t build(std::vector<std::uint32_t>& order, const std::vector<glm::vec3>& centroids,
                        std::uint32_t begin, std::uint32_t end) {
        const auto index = static_cast<std::uint32_t>(mNodes.size());
        mNodes.emplace_back();
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        glm::vec3 cLo = lo, cHi = hi;
        for (std::uint32_t i = begin; i < end; ++i) {
            for (const glm::vec3& p : mTriangles[order[i]]) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            cLo = glm::min(cLo, centroids[order[i]]);
            cHi = glm::max(cHi, centroids[order[i]]);
        }
        mNodes[index].lo = lo;
        mNodes[index].hi = hi;
        if (end - begin <= BVH_LEAF_SIZE) {
            mNodes[index].start = begin;
            mNodes[index].count = end - begin;
            return index;
        }
        const glm::vec3 extent = cHi - cLo;
        const int axis =
            extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const std::uint32_t mid = begin + (end - begin) / 2;
        // Ties broken by index: a strict total order, so the split is the same on every run.
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             const float ca = centroids[a][axis], cb = centroids[b][axis];
                             return ca < cb || (ca == cb && a < b);
                         });
        build(order, centroids, begin, mid);
        const std::uint32_t second = build(order, centroids, mid, end);
        mNodes[index].start = second;
        return index;
    }

    static float boxDistanceSq(const BvhNode& node, glm::vec3 p) {
        const glm::vec3 d = glm::max(glm::max(node.lo - p, p - node.hi), glm::vec3(0.0f));
        return glm::dot(d, d);
    }

    std::vector<Triangle> mTriangles;
    std::vector<BvhNode> mNodes;
};

// ---- Voxel grid ----------------------------------------------------------------------------

struct VoxelGrid {
    float h = 0.0f;                           // voxel edge
    std::array<int, 3> n{1, 1, 1};            // voxels per axis
    std::array<std::vector<float>, 3> coord;  // voxel centre coordinates per axis

    std::size_t size() const {
        return static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) *
               static_cast<std::size_t>(n[2]);
    }
    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * static_cast<std::size_t>(n[1]) +
                static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(n[0]) +
               static_cast<std::size_t>(x);
    }
    glm::vec3 centre(int x, int y, int z) const {
        return {coord[0][static_cast<std::size_t>(x)], coord[1][static_cast<std::size_t>(y)],
                coord[2][static_cast<std::size_t>(z)]};
    }
};

// Centred on the bounds, so symmetric meshes get symmetric grids.
VoxelGrid makeGrid(const Bounds& bounds, std::uint32_t resolution) {
    VoxelGrid grid;
    const glm::vec3 size = bounds.size();
    grid.h = std::max({size.x, size.y, size.z}) / static_cast<float>(resolution);
    for (int a = 0; a < 3; ++a) {
        // The 1e-4 keeps the longest side at `resolution` voxels despite rounding.
        const double cells = std::ceil(static_cast<double>(size[a] / grid.h) - 1e-4);
        grid.n[a] = std::clamp(static_cast<int>(cells), 1, static_cast<int>(resolution));
        const float first = bounds.centre()[a] - 0.5f * grid.h * static_cast<float>(grid.n[a] - 1);
        auto& axis = grid.coord[static_cast<std::size_t>(a)];
        axis.resize(static_cast<std::size_t>(grid.n[a]));
        for (int i = 0; i < grid.n[a]; ++i)
            axis[static_cast<std::size_t>(i)] = first + grid.h * static_cast<float>(i);
    }
    return grid;
}

// Grid indices whose coordinate may lie in [lo, hi] along `axis` (one index of slack; callers
// measure exactly), clamped to the grid; empty when i0 > i1.
std::array<int, 2> indexRange(const VoxelGrid& grid, int axis, double lo, double hi) {
    const double first = grid.coord[static_cast<std::size_t>(axis)][0];
    const double last = static_cast<double>(grid.n[axis] - 1);
    const double i0 = std::max(0.0, std::floor((lo - first) / grid.h) - 1.0);
    const double i1 = std::min(last, std::ceil((hi - first) / grid.h) + 1.0);
    return {static_cast<int>(std::min(i0, last + 1.0)), static_cast<int>(std::max(i1, -1.0))};
}

// orient2d in double. For float inputs of like magnitude the differences and products are
// exact, so the sign is; edgeSide keeps it antisymmetric in any case.
double orient(glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) {
    return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
}

// The side of edge a→b that q lies on, as if q were moved by ε·(1, δ), 0 < δ ≪ ε: never 0,
// and opposite for b→a. Triangles sharing an edge or a vertex therefore count a grid line
// through it exactly once (or, on a fold, zero or two times), which keeps parity exact.
int edgeSide(glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) {
    const bool swapped = b.x < a.x || (b.x == a.x && b.y < a.y);
    const glm::dvec2 c0 = swapped ? b : a, c1 = swapped ? a : b;
    const double w = orient(c0, c1, q);
    int side = w > 0.0 ? 1 : (w < 0.0 ? -1 : 0);
    if (side == 0) {
        const double dx = c1.x - c0.x, dy = c1.y - c0.y;
        side = dy != 0.0 ? (dy > 0.0 ? -1 : 1) : (dx > 0.0 ? 1 : -1);
    }
    return swapped ? -side : side;
}

struct AxisCrossing {
    std::uint32_t line = 0;
    double t = 0.0;
    int sign = 0;
    bool operator<(const AxisCrossing& o) const {
        return line != o.line ? line < o.line : (t != o.t ? t < o.t : sign < o.sign);
    }
};

// Votes of the two rays along `axis` through every voxel centre: each triangle is rasterised
// onto the grid lines it covers (exact predicates above), then each line is walked in order.
void voteAlongAxis(const std::vector<Triangle>& triangles, const VoxelGrid& grid, int axis,
                   std::vector<std::uint8_t>& votes) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const auto& coordU = grid.coord[static_cast<std::size_t>(u)];
    const auto& coordV = grid.coord[static_cast<std::size_t>(v)];
    std::vector<AxisCrossing> crossings;
    for (const Triangle& tri : triangles) {
        const std::array<glm::dvec2, 3> p{glm::dvec2(tri[0][u], tri[0][v]),
                                          glm::dvec2(tri[1][u], tri[1][v]),
                                          glm::dvec2(tri[2][u], tri[2][v])};
        const double area = orient(p[0], p[1], p[2]);
        if (area == 0.0)
            continue;
        const int sign = area > 0.0 ? 1 : -1;
        const auto ru = indexRange(grid, u, std::min({p[0].x, p[1].x, p[2].x}),
                                   std::max({p[0].x, p[1].x, p[2].x}));
        const auto rv = indexRange(grid, v, std::min({p[0].y, p[1].y, p[2].y}),
                                   std::max({p[0].y, p[1].y, p[2].y}));
        const double tLo = std::min({tri[0][axis], tri[1][axis], tri[2][axis]});
        const double tHi = std::max({tri[0][axis], tri[1][axis], tri[2][axis]});
        for (int iv = rv[0]; iv <= rv[1]; ++iv) {
            for (int iu = ru[0]; iu <= ru[1]; ++iu) {
                const glm::dvec2 q(coordU[static_cast<std::size_t>(iu)],
                                   coordV[static_cast<std::size_t>(iv)]);
                if (edgeSide(p[0], p[1], q) != sign || edgeSide(p[1], p[2], q) != sign ||
                    edgeSide(p[2], p[0], q) != sign)
                    continue;
                const double t =
                    (orient(p[1], p[2], q) * tri[0][axis] + orient(p[2], p[0], q) * tri[1][axis] +
                     orient(p[0], p[1], q) * tri[2][axis]) /
                    area;
                // The normal's component along the axis is the projected area (right-handed).
                crossings.push_back({static_cast<std::uint32_t>(iv * grid.n[u] + iu),
                                     std::clamp(t, tLo, tHi), sign});
            }
        }
    }
    std::sort(crossings.begin(), crossings.end());
    std::vector<int> prefix;
    for (std::size_t begin = 0; begin < crossings.size();) {
        std::size_t end = begin;
        while (end < crossings.size() && crossings[end].line == crossings[begin].line)
            ++end;
        prefix.assign(1, 0);
        for (std::size_t k = begin; k < end; ++k)
            prefix.push_back(prefix.back() + crossings[k].sign);
        const int total = prefix.back(), m = static_cast<int>(end - begin);
        const int iu = static_cast<int>(crossings[begin].line) % grid.n[u];
        const int iv = static_cast<int>(crossings[begin].line) / grid.n[u];
        std::array<int, 3> cell{};
        cell[static_cast<std::size_t>(u)] = iu;
        cell[static_cast<std::size_t>(v)] = iv;
        int less = 0, lessOrEqual = 0;
        for (int i = 0; i < grid.n[axis]; ++i) {
            const double x =
                grid.coord[static_cast<std::size_t>(axis)][static_cast<std::size_t>(i)];
            while (less < m && crossings[begin + static_cast<std::size_t>(less)].t < x)
                ++less;
            lessOrEqual = std::max(lessOrEqual, less);
            while (lessOrEqual < m &&
                   crossings[begin + static_cast<std::size_t>(lessOrEqual)].t <= x)
                ++lessOrEqual;
            const RaySide before{less, -prefix[static_cast<std::size_t>(less)]};
            const RaySide after{m - lessOrEqual,
                                total - prefix[static_cast<std::size_t>(lessOrEqual)]};
            cell[static_cast<std::size_t>(axis)] = i;
            votes[grid.index(cell[0], cell[1], cell[2])] +=
                static_cast<std::uint8_t>(lineVotes(before, after, total));
        }
        begin = end;
    }
}

// ---- Distance to the surface ---------------------------------------------------------------

// Voxel states, in the array that first counts the inside votes.
constexpr std::uint8_t OUTSIDE = 0;
constexpr std::uint8_t UNCOVERED = 1;  // inside, in no chosen ball yet
constexpr std::uint8_t COVERED = 2;

// The nearest triangle of every inside voxel centre and its squared distance. Exact in a band
// about the surface, then carried inward by sweeps in which each voxel tries its neighbours'
// nearest triangles (a closest-point transform, as in Batty's SDFGen). Each value is the
// distance to a real triangle, so it is never below the true distance; where the sweeps miss
// the nearest triangle it is above it, and the greedy re-measures every chosen sphere exactly.
struct DistanceField {
    std::vector<std::uint32_t> nearest;
    std::vector<float> distanceSq;

    void offer(std::size_t voxel, std::uint32_t triangle, float dSq) {
        if (dSq < distanceSq[voxel] || (dSq == distanceSq[voxel] && triangle < nearest[voxel])) {
            distanceSq[voxel] = dSq;
            nearest[voxel] = triangle;
        }
    }
};

// Exact distances for the inside voxels within `band` of each triangle: the voxels of its
// bounding box (grown by the band) that lie in the slab about its plane, walked along the
// axis the normal is closest to, so a large triangle costs its area, not its box's volume.
void seedBand(const std::vector<Triangle>& triangles, const VoxelGrid& grid,
              const std::vector<std::uint8_t>& state, float band, DistanceField& field) {
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        const Triangle& tri = triangles[t];
        const glm::dvec3 n = glm::cross(glm::dvec3(tri[1] - tri[0]), glm::dvec3(tri[2] - tri[0]));
        const glm::dvec3 absN = glm::abs(n);
        const int a = absN.x >= absN.y && absN.x >= absN.z ? 0 : (absN.y >= absN.z ? 1 : 2);
        const int u = (a + 1) % 3, v = (a + 2) % 3;
        const glm::vec3 lo = glm::min(glm::min(tri[0], tri[1]), tri[2]) - band;
        const glm::vec3 hi = glm::max(glm::max(tri[0], tri[1]), tri[2]) + band;
        const double planeOffset = glm::dot(n, glm::dvec3(tri[0]));
        const double halfSlab = static_cast<double>(band) * glm::length(n) / absN[a];
        const auto ru = indexRange(grid, u, lo[u], hi[u]);
        const auto rv = indexRange(grid, v, lo[v], hi[v]);
        std::array<int, 3> cell{};
        for (int iv = rv[0]; iv <= rv[1]; ++iv) {
            for (int iu = ru[0]; iu <= ru[1]; ++iu) {
                const double qu =
                    grid.coord[static_cast<std::size_t>(u)][static_cast<std::size_t>(iu)];
                const double qv =
                    grid.coord[static_cast<std::size_t>(v)][static_cast<std::size_t>(iv)];
                const double onPlane = (planeOffset - n[u] * qu - n[v] * qv) / n[a];
                const auto ra = indexRange(grid, a, std::max<double>(onPlane - halfSlab, lo[a]),
                                           std::min<double>(onPlane + halfSlab, hi[a]));
                cell[static_cast<std::size_t>(u)] = iu;
                cell[static_cast<std::size_t>(v)] = iv;
                for (int ia = ra[0]; ia <= ra[1]; ++ia) {
                    cell[static_cast<std::size_t>(a)] = ia;
                    const std::size_t voxel = grid.index(cell[0], cell[1], cell[2]);
                    if (state[voxel] == OUTSIDE)
                        continue;
                    field.offer(
                        voxel, t,
                        pointTriangleDistanceSq(grid.centre(cell[0], cell[1], cell[2]), tri));
                }
            }
        }
    }
}

DistanceField distanceField(const TriangleBvh& bvh, const VoxelGrid& grid,
                            const std::vector<std::uint8_t>& state) {
    DistanceField field{std::vector<std::uint32_t>(grid.size(), NONE),
                        std::vector<float>(grid.size(), std::numeric_limits<float>::infinity())};
    // 1.5 voxels: every voxel whose nearest surface point is within a voxel is seeded exactly.
    seedBand(bvh.triangles(), grid, state, 1.5f * grid.h, field);
    // The eight sweep directions; each voxel looks at the seven neighbours the sweep has
    // already passed. A second round (SDFGen does two) fixed under 0.5 % of the voxels and left
    // the largest error, 0.06 voxel, as it was (sphere and torus, 10k triangles, resolution 64).
    for (int octant = 0; octant < 8; ++octant) {
        const std::array<int, 3> step{(octant & 1) ? -1 : 1, (octant & 2) ? -1 : 1,
                                      (octant & 4) ? -1 : 1};
        for (int k = 0; k < grid.n[2]; ++k) {
            const int z = step[2] > 0 ? k : grid.n[2] - 1 - k;
            for (int j = 0; j < grid.n[1]; ++j) {
                const int y = step[1] > 0 ? j : grid.n[1] - 1 - j;
                for (int i = 0; i < grid.n[0]; ++i) {
                    const int x = step[0] > 0 ? i : grid.n[0] - 1 - i;
                    const std::size_t voxel = grid.index(x, y, z);
                    if (state[voxel] == OUTSIDE)
                        continue;
                    const glm::vec3 p = grid.centre(x, y, z);
                    for (int behind = 1; behind < 8; ++behind) {
                        const int nx = x - ((behind & 1) ? step[0] : 0);
                        const int ny = y - ((behind & 2) ? step[1] : 0);
                        const int nz = z - ((behind & 4) ? step[2] : 0);
                        if (nx < 0 || ny < 0 || nz < 0 || nx >= grid.n[0] || ny >= grid.n[1] ||
                            nz >= grid.n[2])
                            continue;
                        const std::uint32_t t = field.nearest[grid.index(nx, ny, nz)];
                        if (t != NONE && t != field.nearest[voxel])
                            field.offer(voxel, t, bvh.distanceSqTo(p, t));
                    }
                }
            }
        }
    }
    // Inside voxels no sweep reached (none are expected): ask the tree.
    for (int z = 0; z < grid.n[2]; ++z)
        for (int y = 0; y < grid.n[1]; ++y)
            for (int x = 0; x < grid.n[0]; ++x) {
                const std::size_t voxel = grid.index(x, y, z);
                if (state[voxel] != OUTSIDE && field.nearest[voxel] == NONE)
                    field.distanceSq[voxel] =
                        bvh.nearestSq(grid.centre(x, y, z), std::numeric_limits<float>::infinity(),
                                      field.nearest[voxel]);
            }
    return field;
}

// Squared distance, in voxels², from every voxel centre to the nearest outside voxel centre or
// centre beyond the grid (Felzenszwalb & Huttenlocher's separable exact transform). For a
// closed mesh the surface lies between, so this never caps a radius; for an open one (a rock
// scanned without its base) it keeps spheres from reaching out through the opening, which no
// triangle bounds.
std::vector<float> outsideDistanceSq(const VoxelGrid& grid,
                                     const std::vector<std::uint8_t>& state) {
    constexpr double FAR = 1e20;
    std::vector<float> d(grid.size());
    for (std::size_t v = 0; v < grid.size(); ++v)
        d[v] = state[v] == OUTSIDE ? 0.0f : static_cast<float>(FAR);
    std::vector<double> f, out, z;
    std::vector<int> hull;
    for (int axis = 0; axis < 3; ++axis) {
        const int n = grid.n[axis], u = (axis + 1) % 3, v = (axis + 2) % 3;
        f.resize(static_cast<std::size_t>(n));
        out.resize(static_cast<std::size_t>(n));
        hull.resize(static_cast<std::size_t>(n));
        z.resize(static_cast<std::size_t>(n) + 1);
        std::array<int, 3> cell{};
        for (int iv = 0; iv < grid.n[v]; ++iv) {
            for (int iu = 0; iu < grid.n[u]; ++iu) {
                cell[static_cast<std::size_t>(u)] = iu;
                cell[static_cast<std::size_t>(v)] = iv;
                const auto at = [&](int i) {
                    cell[static_cast<std::size_t>(axis)] = i;
                    return grid.index(cell[0], cell[1], cell[2]);
                };
                for (int i = 0; i < n; ++i)
                    f[static_cast<std::size_t>(i)] = d[at(i)];
                // Lower envelope of the parabolas (i − q)² + f(q).
                const auto meet = [&](int q, int r) {
                    return ((f[static_cast<std::size_t>(q)] + q * q) -
                            (f[static_cast<std::size_t>(r)] + r * r)) /
                           (2.0 * (q - r));
                };
                std::size_t k = 0;
                hull[0] = 0;
                z[0] = -FAR;
                z[1] = FAR;
                for (int q = 1; q < n; ++q) {
                    double s = meet(q, hull[k]);
                    while (k > 0 && s <= z[k]) {
                        --k;
                        s = meet(q, hull[k]);
                    }
                    ++k;
                    hull[k] = q;
                    z[k] = s;
                    z[k + 1] = FAR;
                }
                k = 0;
                for (int q = 0; q < n; ++q) {
                    while (z[k + 1] < q)
                        ++k;
                    const double dq = q - hull[k];
                    out[static_cast<std::size_t>(q)] =
                        dq * dq + f[static_cast<std::size_t>(hull[k])];
                }
                for (int i = 0; i < n; ++i)
                    d[at(i)] = static_cast<float>(out[static_cast<std::size_t>(i)]);
            }
        }
    }
    for (int z1 = 0; z1 < grid.n[2]; ++z1)
        for (int y = 0; y < grid.n[1]; ++y)
            for (int x = 0; x < grid.n[0]; ++x) {
                const int edge =
                    std::min({x + 1, grid.n[0] - x, y + 1, grid.n[1] - y, z1 + 1, grid.n[2] - z1});
                float& value = d[grid.index(x, y, z1)];
                value = std::min(value, static_cast<float>(edge * edge));
            }
    return d;
}

// ---- Greedy cover --------------------------------------------------------------------------

// A ball of voxel centres: centred on a voxel, radius its distance to the surface.
struct Ball {
    std::size_t voxel = 0;
    std::array<int, 3> cell{};
    float radius = 0.0f;
    double radiusSq = 0.0;  // (radius / h)², in voxel units
};

Ball ballAt(const VoxelGrid& grid, const std::vector<float>& radius, int x, int y, int z) {
    const std::size_t voxel = grid.index(x, y, z);
    const double rho = static_cast<double>(radius[voxel]) / static_cast<double>(grid.h);
    return {voxel, {x, y, z}, radius[voxel], rho * rho};
}

// Calls visit(x, y, z) for the inside voxels among the 26 neighbours of `cell`.
template <class Visit>
void forEachInsideNeighbour(const VoxelGrid& grid, const std::vector<std::uint8_t>& state,
                            std::array<int, 3> cell, Visit&& visit) {
    for (int k = 0; k < 27; ++k) {
        const int x = cell[0] + k % 3 - 1, y = cell[1] + k / 3 % 3 - 1, z = cell[2] + k / 9 - 1;
        if (k == 13 || x < 0 || y < 0 || z < 0 || x >= grid.n[0] || y >= grid.n[1] ||
            z >= grid.n[2] || state[grid.index(x, y, z)] == OUTSIDE)
            continue;
        visit(x, y, z);
    }
}

// Candidates: inside voxels whose ball is not inside a neighbour's ball (a contained ball never
// covers more), thinned where balls are big (THINNING_RADIUS) except on the medial ridge.
std::vector<Ball> findCandidates(const VoxelGrid& grid, const std::vector<std::uint8_t>& state,
                                 const std::vector<float>& radius) {
    std::vector<Ball> candidates;
    for (int z = 0; z < grid.n[2]; ++z) {
        for (int y = 0; y < grid.n[1]; ++y) {
            for (int x = 0; x < grid.n[0]; ++x) {
                const std::size_t v = grid.index(x, y, z);
                if (state[v] == OUTSIDE || !(radius[v] > 0.0f))
                    continue;
                bool dominated = false, ridge = true;
                forEachInsideNeighbour(grid, state, {x, y, z}, [&](int nx, int ny, int nz) {
                    const std::size_t w = grid.index(nx, ny, nz);
                    const int dx = nx - x, dy = ny - y, dz = nz - z;
                    const float step =
                        grid.h * std::sqrt(static_cast<float>(dx * dx + dy * dy + dz * dz));
                    dominated =
                        dominated || radius[w] >= radius[v] + step - DOMINANCE_SLACK * grid.h;
                    ridge = ridge && radius[w] <= radius[v];
                });
                const Ball ball = ballAt(grid, radius, x, y, z);
                const int stride =
                    std::max(1, static_cast<int>(std::sqrt(ball.radiusSq) / THINNING_RADIUS));
                if (dominated ||
                    (!ridge && (x % stride != 0 || y % stride != 0 || z % stride != 0)))
                    continue;
                candidates.push_back(ball);
            }
        }
    }
    return candidates;
}

double ballVolume(double r) {
    return r > 0.0 ? 4.0 / 3.0 * PI * r * r * r : 0.0;
}

// Volume of the intersection of two balls of radii a and b whose centres are d apart.
double lensVolume(double a, double b, double d) {
    if (a <= 0.0 || b <= 0.0 || d >= a + b)
        return 0.0;
    if (d <= std::abs(a - b))
        return ballVolume(std::min(a, b));
    const double s = a + b - d;
    return PI * s * s * (d * d + 2.0 * d * (a + b) - 3.0 * (a - b) * (a - b)) / (12.0 * d);
}

// Half the length, in voxels, of the row of a ball's voxel centres at offsets (dy, dz) from its
// centre; -1 when the row misses the ball. Counting and marking both use it, so they agree.
int rowHalfWidth(double radiusSq, int dy, int dz) {
    const double rest = radiusSq - static_cast<double>(dy * dy + dz * dz);
    if (rest < 0.0)
        return -1;
    // sqrt is correctly rounded, so it never falls below an integer root; it may round up to one.
    const int dx = static_cast<int>(std::sqrt(rest));
    return static_cast<double>(dx) * static_cast<double>(dx) > rest ? dx - 1 : dx;
}

// Calls visit(rowStart, y, z, x0, x1) for each grid row of voxel centres in the ball.
template <class Visit>
void forEachBallRow(const VoxelGrid& grid, const Ball& c, Visit&& visit) {
    const int reach = rowHalfWidth(c.radiusSq, 0, 0);
    const int z0 = std::max(0, c.cell[2] - reach), z1 = std::min(grid.n[2] - 1, c.cell[2] + reach);
    for (int z = z0; z <= z1; ++z) {
        const int reachY = rowHalfWidth(c.radiusSq, 0, z - c.cell[2]);
        const int y0 = std::max(0, c.cell[1] - reachY);
        const int y1 = std::min(grid.n[1] - 1, c.cell[1] + reachY);
        for (int y = y0; y <= y1; ++y) {
            const int dx = rowHalfWidth(c.radiusSq, y - c.cell[1], z - c.cell[2]);
            const int x0 = std::max(0, c.cell[0] - dx);
            const int x1 = std::min(grid.n[0] - 1, c.cell[0] + dx);
            if (dx >= 0 && x0 <= x1)
                visit(grid.index(0, y, z), y, z, x0, x1);
        }
    }
}

// Uncovered voxels in c's ball. Voxels in `container` (a chosen ball) are all covered, so on
// each row its span is skipped: a ball mostly inside a chosen one costs its rows, not its volume.
double uncoveredInBall(const VoxelGrid& grid, const std::vector<std::uint8_t>& state, const Ball& c,
                       const Ball* container) {
    const std::uint8_t* cells = state.data();
    const auto uncovered = [cells](std::size_t row, int x0, int x1) {
        std::uint32_t n = 0;
        for (int x = x0; x <= x1; ++x)
            n += cells[row + static_cast<std::size_t>(x)] == UNCOVERED ? 1u : 0u;
        return n;
    };
    std::size_t count = 0;
    forEachBallRow(grid, c, [&](std::size_t row, int y, int z, int x0, int x1) {
        const int w =
            container == nullptr
                ? -1
                : rowHalfWidth(container->radiusSq, y - container->cell[1], z - container->cell[2]);
        if (w < 0) {
            count += uncovered(row, x0, x1);
            return;
        }
        count += uncovered(row, x0, std::min(x1, container->cell[0] - w - 1));
        count += uncovered(row, std::max(x0, container->cell[0] + w + 1), x1);
    });
    return static_cast<double>(count);
}

struct HeapEntry {
    double bound = 0.0;
    std::uint32_t candidate = 0;
    // Largest bound on top; equal bounds: the lower index, so the order is total.
    bool operator<(const HeapEntry& o) const {
        return bound != o.bound ? bound < o.bound : candidate > o.candidate;
    }
};

// Greedy maximum coverage, evaluated lazily (gains only shrink, so a stale gain is an upper
// bound: Minoux's accelerated greedy). When a ball is chosen, candidates centred inside it get
// the analytic bound: their uncovered voxels own disjoint unit cubes inside their ball grown
// by HALF_DIAGONAL and outside the chosen ball shrunk by it. The best candidate then climbs to
// the neighbouring voxel with the larger gain while there is one (undoing the thinning), and
// its radius is measured exactly against every triangle before it is taken.
std::vector<Ball> greedyCover(const TriangleBvh& bvh, const VoxelGrid& grid,
                              std::vector<std::uint8_t>& state, const std::vector<float>& radius,
                              const std::vector<Ball>& candidates, std::uint32_t sphereCount) {
    std::vector<double> bound(candidates.size());
    std::vector<std::uint32_t> exactAfter(candidates.size(), NONE);
    // The chosen ball that overlaps each candidate most: its voxels are skipped when counting.
    std::vector<std::uint32_t> container(candidates.size(), NONE);
    std::vector<double> containerLens(candidates.size(), 0.0);
    std::priority_queue<HeapEntry> heap;
    for (std::uint32_t i = 0; i < candidates.size(); ++i) {
        bound[i] = ballVolume(std::sqrt(candidates[i].radiusSq) + HALF_DIAGONAL);
        heap.push({bound[i], i});
    }
    std::vector<Ball> chosen;
    const auto gainOf = [&](const Ball& ball, std::uint32_t inside) {
        return uncoveredInBall(grid, state, ball, inside == NONE ? nullptr : &chosen[inside]);
    };
    while (chosen.size() < sphereCount && !heap.empty()) {
        const HeapEntry top = heap.top();
        heap.pop();
        const std::uint32_t i = top.candidate;
        if (top.bound != bound[i])
            continue;
        if (top.bound <= 0.0)
            break;
        const auto selections = static_cast<std::uint32_t>(chosen.size());
        if (exactAfter[i] != selections) {
            bound[i] = gainOf(candidates[i], container[i]);
            exactAfter[i] = selections;
            heap.push({bound[i], i});
            continue;
        }
        Ball ball = candidates[i];
        double gain = bound[i];
        for (int step = 0; step < MAX_CLIMB_STEPS; ++step) {
            const Ball from = ball;
            forEachInsideNeighbour(grid, state, from.cell, [&](int x, int y, int z) {
                const Ball next = ballAt(grid, radius, x, y, z);
                const double nextGain = next.radius > 0.0f ? gainOf(next, container[i]) : 0.0;
                if (nextGain > gain) {
                    ball = next;
                    gain = nextGain;
                }
            });
            if (ball.voxel == from.voxel)
                break;
        }
        const glm::vec3 p = grid.centre(ball.cell[0], ball.cell[1], ball.cell[2]);
        // The radius (propagated, or the cap by the outside voxels) is never below the true
        // distance to the triangles, so a bound a little above it still finds the nearest one
        // while pruning the tree as tightly; finding none means the cap is the smaller.
        std::uint32_t nearest = NONE;
        const float propagatedSq = ball.radius * ball.radius;
        const float exactSq = bvh.nearestSq(p, propagatedSq * 1.0001f + 1e-30f, nearest);
        if (exactSq < propagatedSq) {
            ball.radius = std::sqrt(exactSq);
            const double rho = static_cast<double>(ball.radius) / static_cast<double>(grid.h);
            ball.radiusSq = rho * rho;
            if (!(ball.radius > 0.0f) || gainOf(ball, container[i]) <= 0.0) {
                bound[i] = 0.0;
                continue;
            }
        }
        chosen.push_back(ball);
        const auto chosenIndex = static_cast<std::uint32_t>(chosen.size() - 1);
        const double shrunk = std::sqrt(ball.radiusSq) - HALF_DIAGONAL;
        forEachBallRow(grid, ball, [&](std::size_t row, int, int, int x0, int x1) {
            for (int x = x0; x <= x1; ++x) {
                if (state[row + static_cast<std::size_t>(x)] == UNCOVERED)
                    state[row + static_cast<std::size_t>(x)] = COVERED;
            }
            // Candidates are sorted by voxel index: those on this row are one range.
            const auto first = std::lower_bound(
                candidates.begin(), candidates.end(), row + static_cast<std::size_t>(x0),
                [](const Ball& a, std::size_t voxel) { return a.voxel < voxel; });
            for (auto it = first;
                 it != candidates.end() && it->voxel <= row + static_cast<std::size_t>(x1); ++it) {
                const auto j = static_cast<std::uint32_t>(it - candidates.begin());
                const glm::dvec3 offset(it->cell[0] - ball.cell[0], it->cell[1] - ball.cell[1],
                                        it->cell[2] - ball.cell[2]);
                const double grown = std::sqrt(it->radiusSq) + HALF_DIAGONAL;
                const double lens = lensVolume(grown, shrunk, glm::length(offset));
                if (lens > containerLens[j]) {
                    containerLens[j] = lens;
                    container[j] = chosenIndex;
                }
                const double limit = std::max(0.0, ballVolume(grown) - lens);
                if (limit < bound[j]) {
                    bound[j] = limit;
                    heap.push({limit, j});
                }
            }
        });
    }
    return chosen;
}

// ---- Measures ------------------------------------------------------------------------------

// Inside votes for arbitrary points: the triangles projected along a fixed direction onto a
// 2D grid of buckets, so a line through a point meets only its bucket's triangles, with the
// same exact edge rule as the voxel lines. Per-vertex projections are computed identically
// for every triangle sharing the vertex, so shared edges stay watertight (and along an axis
// the projection is exact).
class LineCaster {
public:
    LineCaster(const std::vector<Triangle>& triangles, glm::dvec3 dir) : mDir(glm::normalize(dir)) {
        const glm::dvec3 helper =
            std::abs(mDir.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        // (u, v, dir) right-handed: a projected area is the normal's component along dir.
        mU = glm::normalize(glm::cross(mDir, helper));
        mV = glm::cross(mDir, mU);
        glm::dvec2 lo(std::numeric_limits<double>::max()),
            hi(std::numeric_limits<double>::lowest());
        for (const Triangle& t : triangles) {
            Projected q;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec3 p = t[k];
                q.corner[k] = {glm::dot(p, mU), glm::dot(p, mV)};
                q.depth[k] = glm::dot(p, mDir);
                lo = glm::min(lo, q.corner[k]);
                hi = glm::max(hi, q.corner[k]);
            }
            q.area = orient(q.corner[0], q.corner[1], q.corner[2]);
            if (q.area != 0.0)
                mProjected.push_back(q);
        }
        // About √T buckets along each side, so a line meets a handful of triangles; fewer
        // when long thin triangles would each fill a whole row of buckets (at most 16 bucket
        // entries per triangle).
        const double side = std::max(hi.x - lo.x, hi.y - lo.y);
        const auto entries = [&](int cells) {
            double sum = 0.0;
            for (const Projected& t : mProjected) {
                const glm::dvec2 extent =
                    glm::max(glm::max(t.corner[0], t.corner[1]), t.corner[2]) -
                    glm::min(glm::min(t.corner[0], t.corner[1]), t.corner[2]);
                sum += (extent.x / side * cells + 1.0) * (extent.y / side * cells + 1.0);
            }
            return sum;
        };
        mCells =
            std::clamp(static_cast<int>(std::sqrt(static_cast<double>(mProjected.size()))), 1, 512);
        while (mCells > 1 && side > 0.0 &&
               entries(mCells) > 16.0 * static_cast<double>(mProjected.size()))
            mCells /= 2;
        mLo = lo;
        mCellSize = side > 0.0 ? side / mCells : 1.0;
        std::vector<std::array<int, 4>> ranges(mProjected.size());
        std::vector<std::uint32_t> counts(static_cast<std::size_t>(mCells * mCells) + 1, 0);
        for (std::size_t i = 0; i < mProjected.size(); ++i) {
            const auto& q = mProjected[i].corner;
            const glm::ivec2 c0 = cellOf(glm::min(glm::min(q[0], q[1]), q[2]));
            const glm::ivec2 c1 = cellOf(glm::max(glm::max(q[0], q[1]), q[2]));
            ranges[i] = {c0.x, c0.y, c1.x, c1.y};
            for (int y = c0.y; y <= c1.y; ++y)
                for (int x = c0.x; x <= c1.x; ++x)
                    ++counts[static_cast<std::size_t>(y * mCells + x)];
        }
        mStart.assign(counts.size(), 0);
        for (std::size_t c = 1; c < counts.size(); ++c)
            mStart[c] = mStart[c - 1] + counts[c - 1];
        mItems.resize(mStart.back());
        std::vector<std::uint32_t> fill(mStart.begin(), mStart.end() - 1);
        for (std::size_t i = 0; i < mProjected.size(); ++i) {
            for (int y = ranges[i][1]; y <= ranges[i][3]; ++y)
                for (int x = ranges[i][0]; x <= ranges[i][2]; ++x)
                    mItems[fill[static_cast<std::size_t>(y * mCells + x)]++] =
                        static_cast<std::uint32_t>(i);
        }
    }

    // Votes (0..2) of the two rays from p along ±dir.
    int votes(glm::dvec3 p) const {
        const glm::dvec2 q(glm::dot(p, mU), glm::dot(p, mV));
        const double depth = glm::dot(p, mDir);
        const glm::dvec2 rel = (q - mLo) / mCellSize;
        if (rel.x < 0.0 || rel.y < 0.0 || rel.x >= mCells + 1.0 || rel.y >= mCells + 1.0)
            return 0;
        const glm::ivec2 c = cellOf(q);
        const std::size_t cell = static_cast<std::size_t>(c.y * mCells + c.x);
        RaySide before, after;
        int total = 0;
        for (std::uint32_t k = mStart[cell]; k < mStart[cell + 1]; ++k) {
            const Projected& tri = mProjected[mItems[k]];
            const auto& t = tri.corner;
            const int sign = tri.area > 0.0 ? 1 : -1;
            if (edgeSide(t[0], t[1], q) != sign || edgeSide(t[1], t[2], q) != sign ||
                edgeSide(t[2], t[0], q) != sign)
                continue;
            const double hit =
                (orient(t[1], t[2], q) * tri.depth[0] + orient(t[2], t[0], q) * tri.depth[1] +
                 orient(t[0], t[1], q) * tri.depth[2]) /
                tri.area;
            total += sign;
            if (hit < depth) {
                ++before.count;
                before.sum -= sign;
            } else if (hit > depth) {
                ++after.count;
                after.sum += sign;
            }
        }
        return lineVotes(before, after, total);
    }

private:
    glm::ivec2 cellOf(glm::dvec2 q) const {
        const glm::dvec2 rel = glm::floor((q - mLo) / mCellSize);
        return glm::clamp(glm::ivec2(rel), glm::ivec2(0), glm::ivec2(mCells - 1));
    }

    struct Projected {
        std::array<glm::dvec2, 3> corner;  // (u, v)
        std::array<double, 3> depth{};     // along dir
        double area = 0.0;                 // signed, in the (u, v) plane
    };

    glm::dvec3 mDir, mU{0.0}, mV{0.0};
    std::vector<Projected> mProjected;
    glm::dvec2 mLo{0.0};
    double mCellSize = 1.0;
    int mCells = 1;
    std::vector<std::uint32_t> mStart, mItems;  // triangles of each bucket
};

// The axes, as for the voxels, so a sample is inside by the same rule at any position. Tilted
// directions would judge open shapes differently: from inside a rock scanned without its base,
// only the downward one of the six axis rays escapes, but three of six tilted rays would.
std::array<LineCaster, 3> sampleCasters(const std::vector<Triangle>& triangles) {
    return {LineCaster(triangles, {1.0, 0.0, 0.0}), LineCaster(triangles, {0.0, 1.0, 0.0}),
            LineCaster(triangles, {0.0, 0.0, 1.0})};
}

void measure(const std::vector<Triangle>& triangles, const Bounds& meshBox,
             SpherePacking& packing) {
    const std::array<LineCaster, 3> casters = sampleCasters(triangles);
    Bounds box = meshBox;
    for (const PackedSphere& s : packing.spheres) {
        box.min = glm::min(box.min, s.centre - s.radiusM);
        box.max = glm::max(box.max, s.centre + s.radiusM);
    }
    // Spheres bucketed in a coarse grid so each sample tests only its cell's spheres.
    constexpr int CELLS = 16;
    const glm::vec3 cellSize = glm::max(box.size() / static_cast<float>(CELLS), glm::vec3(1e-30f));
    const auto cellOf = [&](glm::vec3 p) {
        const glm::ivec3 c((p - box.min) / cellSize);
        return glm::clamp(c, glm::ivec3(0), glm::ivec3(CELLS - 1));
    };
    const auto cellIndex = [](glm::ivec3 c) {
        return static_cast<std::size_t>((c.z * CELLS + c.y) * CELLS + c.x);
    };
    std::vector<std::vector<std::uint32_t>> cells(CELLS * CELLS * CELLS);
    for (std::uint32_t i = 0; i < packing.spheres.size(); ++i) {
        const PackedSphere& s = packing.spheres[i];
        const glm::ivec3 lo = cellOf(s.centre - s.radiusM), hi = cellOf(s.centre + s.radiusM);
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    cells[cellIndex({x, y, z})].push_back(i);
    }
    Rng rng(MEASURE_SEED);
    std::uint32_t inUnion = 0, inMesh = 0, inBoth = 0;
    for (std::uint32_t k = 0; k < MEASURE_SAMPLES; ++k) {
        const float fx = rng.uniform(), fy = rng.uniform(), fz = rng.uniform();
        const glm::vec3 p = box.min + box.size() * glm::vec3(fx, fy, fz);
        bool covered = false;
        for (const std::uint32_t i : cells[cellIndex(cellOf(p))]) {
            const glm::vec3 d = p - packing.spheres[i].centre;
            if (glm::dot(d, d) <= packing.spheres[i].radiusM * packing.spheres[i].radiusM) {
                covered = true;
                break;
            }
        }
        int votes = 0;
        for (const LineCaster& caster : casters)
            votes += caster.votes(p);
        const bool inside = votes >= VOTES_FOR_INSIDE;
        inUnion += covered ? 1u : 0u;
        inMesh += inside ? 1u : 0u;
        inBoth += covered && inside ? 1u : 0u;
    }
    packing.samples = MEASURE_SAMPLES;
    packing.insideShare =
        inUnion > 0 ? static_cast<float>(inBoth) / static_cast<float>(inUnion) : 0.0f;
    packing.coverage = inMesh > 0 ? static_cast<float>(inBoth) / static_cast<float>(inMesh) : 0.0f;
}

Result<void> checkParams(const SpherePackingParams& params) {
    if (params.sphereCount == 0)
        return makeError("", "sphere count must be at least 1");
    if (params.sphereCount > MAX_PACKED_SPHERES)
        return makeError("", "sphere count " + std::to_string(params.sphereCount) +
                                 " is more than the maximum of " +
                                 std::to_string(MAX_PACKED_SPHERES));
    if (params.resolution < MIN_PACKING_RESOLUTION || params.resolution > MAX_PACKING_RESOLUTION)
        return makeError("", "packing resolution " + std::to_string(params.resolution) +
                                 " is outside [" + std::to_string(MIN_PACKING_RESOLUTION) + ", " +
                                 std::to_string(MAX_PACKING_RESOLUTION) + "]");
    return {};
}

}  // namespace

Result<SpherePacking> packSpheres(const SurfaceMesh& mesh, const SpherePackingParams& params) {
    if (auto checked = checkParams(params); !checked)
        return checked.error();
    if (mesh.n_faces() == 0)
        return makeError("", "mesh has no triangles to pack into spheres");
    std::vector<Triangle> triangles;
    triangles.reserve(mesh.n_faces());
    Bounds bounds{glm::vec3(std::numeric_limits<float>::max()),
                  glm::vec3(std::numeric_limits<float>::lowest())};
    for (const auto fh : mesh.faces()) {
        const Triangle t = facePositions(mesh, fh);
        for (const glm::vec3& p : t) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                return makeError("", "mesh has a vertex position that is not a finite number");
            bounds.min = glm::min(bounds.min, p);
            bounds.max = glm::max(bounds.max, p);
        }
        // Zero-area triangles bound no volume, and the distance code divides by their area.
        const glm::vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
        if (glm::dot(n, n) > 0.0f)
            triangles.push_back(t);
    }
    const Error noVolume =
        makeError("", "mesh has no enclosed volume to pack into spheres (is it a closed surface?)");
    const glm::vec3 size = bounds.size();
    if (triangles.empty() || std::max({size.x, size.y, size.z}) <= 0.0f)
        return noVolume;

    const VoxelGrid grid = makeGrid(bounds, params.resolution);
    std::vector<std::uint8_t> state(grid.size(), 0);
    for (int axis = 0; axis < 3; ++axis)
        voteAlongAxis(triangles, grid, axis, state);
    for (std::uint8_t& s : state)
        s = s >= VOTES_FOR_INSIDE ? UNCOVERED : OUTSIDE;

    const TriangleBvh bvh(std::move(triangles));
    // The distances become radii in place (the nearest triangles are no longer needed), capped
    // by the distance to the outside voxels.
    std::vector<float> radius = std::move(distanceField(bvh, grid, state).distanceSq);
    {
        const std::vector<float> outside = outsideDistanceSq(grid, state);
        for (std::size_t v = 0; v < grid.size(); ++v)
            radius[v] = state[v] == OUTSIDE
                            ? 0.0f
                            : std::min(std::sqrt(radius[v]), grid.h * std::sqrt(outside[v]));
    }
    const std::vector<Ball> candidates = findCandidates(grid, state, radius);
    SpherePacking packing;
    packing.voxelSize = grid.h;
    for (const Ball& ball : greedyCover(bvh, grid, state, radius, candidates, params.sphereCount))
        packing.spheres.push_back(
            {grid.centre(ball.cell[0], ball.cell[1], ball.cell[2]), ball.radius});
    if (packing.spheres.empty())
        return noVolume;
    measure(bvh.triangles(), bounds, packing);
    return packing;
}

}  // namespace grass::core
