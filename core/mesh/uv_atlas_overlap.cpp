// The UV overlap search (findUvOverlaps, atlas::countOverlaps): a uniform grid as broad phase,
// separating axes on the triangles' edges as narrow phase.
#include "mesh/uv_atlas.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "mesh/uv_atlas_detail.h"
#include "util/assert.h"
#include "util/thread_pool.h"

namespace grass::core {

namespace atlas {

namespace {

struct Box {
    glm::dvec2 min{0.0};
    glm::dvec2 max{0.0};
};

Box boxOf(const Triangle2& t) {
    return {glm::min(glm::min(t[0], t[1]), t[2]), glm::max(glm::max(t[0], t[1]), t[2])};
}

// True when one of `a`'s edge normals separates the triangles, or they overlap along it by at
// most `epsilon`. Shared vertices are bitwise equal and project to equal values, so triangles
// sharing an edge overlap by exactly 0 along it.
bool separatedByEdgeOf(const Triangle2& a, const Triangle2& b, double epsilon) {
    for (int i = 0; i < 3; ++i) {
        const glm::dvec2 edge =
            a[static_cast<std::size_t>((i + 1) % 3)] - a[static_cast<std::size_t>(i)];
        const double length = glm::length(edge);
        if (!(length > 0.0))
            continue;
        const glm::dvec2 axis = glm::dvec2(-edge.y, edge.x) / length;
        double minA = glm::dot(axis, a[0]), maxA = minA;
        double minB = glm::dot(axis, b[0]), maxB = minB;
        for (std::size_t k = 1; k < 3; ++k) {
            const double pa = glm::dot(axis, a[k]), pb = glm::dot(axis, b[k]);
            minA = std::min(minA, pa);
            maxA = std::max(maxA, pa);
            minB = std::min(minB, pb);
            maxB = std::max(maxB, pb);
        }
        if (std::min(maxA, maxB) - std::max(minA, minB) <= epsilon)
            return true;
    }
    return false;
}

// For convex polygons the smallest penetration over all directions is along an edge normal,
// so boxes overlapping by at most epsilon on x or y imply separatedByEdgeOf: the box test only
// saves time, it never changes an answer.
bool boxesOverlap(const Box& a, const Box& b, double epsilon) {
    return std::min(a.max.x, b.max.x) - std::max(a.min.x, b.min.x) > epsilon &&
           std::min(a.max.y, b.max.y) - std::max(a.min.y, b.min.y) > epsilon;
}

bool interiorsOverlap(const Triangle2& a, const Triangle2& b, double epsilon) {
    return !separatedByEdgeOf(a, b, epsilon) && !separatedByEdgeOf(b, a, epsilon);
}

// Below this many triangles every pair is tested: a grid would cost more than it saves (most
// charts are small).
constexpr std::size_t BRUTE_FORCE_MAX = 24;
// A grid side stops growing here, and the grid at 8 cells per triangle: memory stays linear.
constexpr std::size_t GRID_SIDE_MAX = 4096;
constexpr double CELLS_PER_TRIANGLE_MAX = 8.0;
// Grid entries per triangle on average before the grid is coarsened: large triangles each
// cover many cells, and the entries must stay within memory.
constexpr std::size_t ENTRIES_PER_TRIANGLE_MAX = 48;
// From this many triangles the search runs on the shared pool's threads: below it a chart's
// search takes well under a millisecond and each run's `seenBy` would cost more than it saves.
constexpr std::size_t PARALLEL_MIN_TRIANGLES = 200'000;
// Triangles a search run takes between two looks at the stop token (a few milliseconds).
constexpr std::size_t TRIANGLES_PER_STOP_CHECK = 16384;

struct Grid {
    glm::dvec2 origin{0.0};
    glm::dvec2 cellSize{1.0};
    std::size_t nx = 1, ny = 1;

    std::size_t column(double x) const {
        const double c = std::floor((x - origin.x) / cellSize.x);
        return static_cast<std::size_t>(std::clamp(c, 0.0, static_cast<double>(nx - 1)));
    }
    std::size_t row(double y) const {
        const double r = std::floor((y - origin.y) / cellSize.y);
        return static_cast<std::size_t>(std::clamp(r, 0.0, static_cast<double>(ny - 1)));
    }

    // Visits the cells the triangle covers, row by row: the triangle clipped to each row's band
    // spans an x range from its corners in the band and its edges' crossings of the band's
    // sides. A thin triangle lying diagonally covers a few cells per row, not its whole box.
    template <class Visit>
    void forCells(const Triangle2& t, const Box& box, Visit&& visit) const {
        const std::size_t r0 = row(box.min.y), r1 = row(box.max.y);
        // Rounding must never drop a cell a triangle overlaps: widen each range a little.
        const double pad = 1e-6 * cellSize.x;
        for (std::size_t r = r0; r <= r1; ++r) {
            const double lo = r == r0 ? box.min.y : origin.y + static_cast<double>(r) * cellSize.y;
            const double hi =
                r == r1 ? box.max.y : origin.y + static_cast<double>(r + 1) * cellSize.y;
            double xMin = INFINITY, xMax = -INFINITY;
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec2 p = t[k], q = t[(k + 1) % 3];
                if (p.y >= lo && p.y <= hi) {
                    xMin = std::min(xMin, p.x);
                    xMax = std::max(xMax, p.x);
                }
                for (const double y : {lo, hi}) {
                    if ((p.y - y) * (q.y - y) < 0.0) {
                        const double x = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
                        xMin = std::min(xMin, x);
                        xMax = std::max(xMax, x);
                    }
                }
            }
            if (!(xMin <= xMax)) {
                xMin = box.min.x;
                xMax = box.max.x;
            }
            const std::size_t c0 = column(std::max(xMin - pad, box.min.x));
            const std::size_t c1 = column(std::min(xMax + pad, box.max.x));
            for (std::size_t c = c0; c <= c1; ++c)
                visit(r * nx + c);
        }
    }
};

}  // namespace

std::size_t countOverlaps(const std::vector<Triangle2>& triangles, const std::vector<char>& active,
                          double epsilon, std::size_t cap, std::vector<OverlapPair>* pairs,
                          const std::stop_token& stop) {
    GRASS_ASSERT(active.size() == triangles.size());
    std::vector<std::uint32_t> live;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        if (active[i])
            live.push_back(static_cast<std::uint32_t>(i));
    }
    std::vector<Box> boxes(triangles.size());
    Box all{glm::dvec2(INFINITY), glm::dvec2(-INFINITY)};
    double area = 0.0;
    for (const std::uint32_t i : live) {
        boxes[i] = boxOf(triangles[i]);
        all.min = glm::min(all.min, boxes[i].min);
        all.max = glm::max(all.max, boxes[i].max);
        area += 0.5 * std::abs(doubledArea(triangles[i]));
    }
    std::size_t count = 0;
    // A pair whose interiors overlap: counted, and listed when asked for.
    const auto test = [&](std::uint32_t a, std::uint32_t b, std::size_t& found,
                          std::vector<OverlapPair>* list) {
        if (!boxesOverlap(boxes[a], boxes[b], epsilon) ||
            !interiorsOverlap(triangles[a], triangles[b], epsilon))
            return;
        ++found;
        if (list)
            list->push_back({std::min(a, b), std::max(a, b)});
    };
    if (live.size() <= BRUTE_FORCE_MAX) {
        for (std::size_t i = 0; i < live.size() && count < cap; ++i) {
            for (std::size_t j = i + 1; j < live.size() && count < cap; ++j)
                test(live[i], live[j], count, pairs);
        }
        return count;
    }

    // Square cells of twice the mean triangle area: where triangles tile the plane a cell holds
    // a few, however little of the bounds they fill (an atlas of thin charts).
    const double n = static_cast<double>(live.size());
    const glm::dvec2 extent = glm::max(all.max - all.min, glm::dvec2(1e-300));
    const double side = std::max(std::sqrt(2.0 * area / n),
                                 std::sqrt(extent.x * extent.y / (CELLS_PER_TRIANGLE_MAX * n)));
    Grid grid;
    grid.origin = all.min;
    const auto sideCells = [&](double e) {
        const double cells = std::ceil(e / std::max(side, 1e-300));
        return static_cast<std::size_t>(std::clamp(cells, 1.0, double(GRID_SIDE_MAX)));
    };
    grid.nx = sideCells(extent.x);
    grid.ny = sideCells(extent.y);
    // Large inputs build the grid and search it on the shared pool (a 2048² grid ground's 8.4 M
    // triangles: 0.85 s of building and ~2 s of searching on one core): `runs` contiguous runs
    // of the triangles. The grid's counts and slots are taken atomically and each cell sorted
    // after, so the grid is the serial one whatever the threads' order.
    ThreadPool& pool = ThreadPool::shared();
    const std::size_t runs =
        live.size() >= PARALLEL_MIN_TRIANGLES ? std::size_t(pool.workerCount()) + 1 : 1;
    const auto inRuns = [&](std::size_t items,
                            const std::function<void(std::size_t, std::size_t)>& each) {
        pool.run(items, runs, each);
    };
    // Whether a run at its k-th triangle (from `begin`) should end for a stop request.
    const auto stopAt = [&](std::size_t k, std::size_t begin) {
        return (k - begin) % TRIANGLES_PER_STOP_CHECK == 0 && stop.stop_requested();
    };
    // Compressed rows: cellStart[c] .. cellStart[c + 1] index `entries`.
    std::vector<std::uint32_t> cellStart;
    for (;;) {
        grid.cellSize = extent / glm::dvec2(grid.nx, grid.ny);
        cellStart.assign(grid.nx * grid.ny + 1, 0);
        std::atomic<std::size_t> total{0};
        inRuns(live.size(), [&](std::size_t begin, std::size_t end) {
            std::size_t counted = 0;
            for (std::size_t k = begin; k < end && !stopAt(k, begin); ++k)
                grid.forCells(triangles[live[k]], boxes[live[k]], [&](std::size_t cell) {
                    std::atomic_ref(cellStart[cell + 1]).fetch_add(1, std::memory_order_relaxed);
                    ++counted;
                });
            total += counted;
        });
        if (stop.stop_requested())
            return 0;
        if ((grid.nx == 1 && grid.ny == 1) || total <= ENTRIES_PER_TRIANGLE_MAX * live.size())
            break;
        grid.nx = std::max<std::size_t>(1, grid.nx / 2);
        grid.ny = std::max<std::size_t>(1, grid.ny / 2);
    }
    for (std::size_t c = 0; c + 1 < cellStart.size(); ++c)
        cellStart[c + 1] += cellStart[c];
    std::vector<std::uint32_t> entries(cellStart.back());
    std::vector<std::uint32_t> fill(cellStart.begin(), cellStart.end() - 1);
    inRuns(live.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end && !stopAt(k, begin); ++k)
            grid.forCells(triangles[live[k]], boxes[live[k]], [&](std::size_t cell) {
                entries[std::atomic_ref(fill[cell]).fetch_add(1, std::memory_order_relaxed)] =
                    live[k];
            });
    });
    if (stop.stop_requested())
        return 0;  // the cells are not all filled
    if (runs > 1)  // one run fills each cell in ascending order already
        inRuns(fill.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t c = begin; c < end; ++c)
                std::sort(entries.begin() + cellStart[c], entries.begin() + cellStart[c + 1]);
        });

    // Each triangle meets the later triangles of its cells; `seenBy` keeps a pair sharing
    // several cells from being tested twice. Cells list triangles in ascending order. Each run
    // counts and lists its own pairs up to the cap, in the order one thread meets them, so the
    // runs joined in order and cut at the cap are the serial answer.
    struct Run {
        std::size_t count = 0;
        std::vector<OverlapPair> pairs;
    };
    const auto search = [&](std::size_t begin, std::size_t end, Run& run) {
        std::vector<std::uint32_t> seenBy(triangles.size(), UINT32_MAX);
        for (std::size_t k = begin; k < end && run.count < cap && !stopAt(k, begin); ++k) {
            const std::uint32_t a = live[k];
            grid.forCells(triangles[a], boxes[a], [&](std::size_t cell) {
                const auto first = entries.begin() + cellStart[cell];
                const auto last = entries.begin() + cellStart[cell + 1];
                for (auto it = std::upper_bound(first, last, a); it != last && run.count < cap;
                     ++it) {
                    if (seenBy[*it] != a) {
                        seenBy[*it] = a;
                        test(a, *it, run.count, pairs ? &run.pairs : nullptr);
                    }
                }
            });
        }
    };
    std::vector<Run> found(runs);
    pool.run(runs, runs, [&](std::size_t first, std::size_t last) {
        for (std::size_t r = first; r < last; ++r)
            search(r * live.size() / runs, (r + 1) * live.size() / runs, found[r]);
    });
    for (Run& run : found) {
        const std::size_t taken = std::min(run.count, cap - count);
        count += taken;
        if (pairs)
            pairs->insert(pairs->end(), run.pairs.begin(),
                          run.pairs.begin() + static_cast<std::ptrdiff_t>(taken));
    }
    return count;
}

}  // namespace atlas

CornerUvs cornerUvsOf(const SurfaceMesh& mesh) {
    CornerUvs uvs;
    uvs.reserve(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        std::array<glm::vec2, 3> corner{};
        std::size_t i = 0;
        for (const auto vh : mesh.fv_range(fh))
            corner[i++] = toGlm(mesh.texcoord2D(vh));
        uvs.push_back(corner);
    }
    return uvs;
}

namespace {

// Float UVs near 1 are exact to 6e-8; 1e-6 lets UVs computed as exactly 0 or 1 round either way.
constexpr double UV_TOLERANCE = 1e-6;
// A face is degenerate when its share of the UV area is under this fraction of its share of the
// 3D area: it would get (almost) no texels. Atlas charts keep every face's share within a small
// factor (projection within the normal cone), far above this.
constexpr double DEGENERATE_SHARE = 1e-3;
// Faces whose expected UV area (their 3D share of the UV area) is below this are too small for
// float UVs to keep their shape (a texel of a 32k map is 1e-9): they are not called degenerate.
constexpr double MIN_EXPECTED_UV_AREA = 1e-10;
// Faces per block of findUvOverlaps' first pass.
constexpr std::size_t FACE_BLOCK = 65536;

}  // namespace

UvOverlapReport findUvOverlaps(const CornerUvs& uvs, const SurfaceMesh& mesh,
                               const std::stop_token& stop) {
    GRASS_ASSERT(uvs.size() == mesh.n_faces());
    UvOverlapReport report;
    std::vector<atlas::Triangle2> triangles(uvs.size());
    std::vector<double> areas3d(uvs.size(), 0.0);
    std::vector<char> finite(uvs.size(), 1);
    // In blocks of faces on the shared pool (half a second on one core for 8.4 M faces), each
    // block's sums kept apart and added in block order: the same sums whatever the threads.
    struct Block {
        glm::dvec2 lo{INFINITY}, hi{-INFINITY};
        double total3d = 0.0, totalUv = 0.0;
        std::size_t outside = 0;
    };
    std::vector<Block> blocks((uvs.size() + FACE_BLOCK - 1) / FACE_BLOCK);
    ThreadPool::shared().run(
        blocks.size(), blocks.size(), [&](std::size_t first, std::size_t last) {
            for (std::size_t block = first; block < last && !stop.stop_requested(); ++block) {
                Block& sums = blocks[block];
                const std::size_t end = std::min(uvs.size(), (block + 1) * FACE_BLOCK);
                for (std::size_t f = block * FACE_BLOCK; f < end; ++f) {
                    const auto p = facePositions(mesh, mesh.face_handle(static_cast<int>(f)));
                    const glm::dvec3 a = p[0], b = p[1], c = p[2];
                    areas3d[f] = 0.5 * glm::length(glm::cross(b - a, c - a));
                    sums.total3d += areas3d[f];
                    bool outside = false;
                    for (std::size_t k = 0; k < 3; ++k) {
                        const glm::dvec2 uv = uvs[f][k];
                        triangles[f][k] = uv;
                        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
                            finite[f] = 0;
                            continue;
                        }
                        sums.lo = glm::min(sums.lo, uv);
                        sums.hi = glm::max(sums.hi, uv);
                        outside =
                            outside || !(uv.x >= -UV_TOLERANCE && uv.y >= -UV_TOLERANCE &&
                                         uv.x <= 1.0 + UV_TOLERANCE && uv.y <= 1.0 + UV_TOLERANCE);
                    }
                    sums.outside += outside ? 1 : 0;
                    if (finite[f])
                        sums.totalUv += 0.5 * std::abs(atlas::doubledArea(triangles[f]));
                }
            }
        });
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    double total3d = 0.0, totalUv = 0.0;
    for (const Block& sums : blocks) {
        lo = glm::min(lo, sums.lo);
        hi = glm::max(hi, sums.hi);
        total3d += sums.total3d;
        totalUv += sums.totalUv;
        report.outsideUnitSquare += sums.outside;
    }
    if (uvs.empty() || stop.stop_requested())
        return report;

    const double extent = hi.x >= lo.x ? std::max({1.0, hi.x - lo.x, hi.y - lo.y}) : 1.0;
    std::vector<char> active(uvs.size(), 0);
    for (std::size_t f = 0; f < uvs.size(); ++f) {
        const double areaUv = 0.5 * std::abs(atlas::doubledArea(triangles[f]));
        // Zero-area UV triangles have no interior to overlap with; non-finite ones are counted
        // outside the unit square already.
        active[f] = finite[f] && areaUv > 0.5e-12 * extent * extent ? 1 : 0;
        const double expected = total3d > 0.0 ? areas3d[f] / total3d * totalUv : 0.0;
        if (areas3d[f] > 0.0 && std::isfinite(areaUv) &&
            (totalUv <= 0.0 ||
             (expected >= MIN_EXPECTED_UV_AREA && areaUv < DEGENERATE_SHARE * expected)))
            ++report.degenerateFaces;
    }
    report.overlappingPairs =
        atlas::countOverlaps(triangles, active, 1e-6 * extent, UV_OVERLAP_CAP, nullptr, stop);
    return report;
}

}  // namespace grass::core
