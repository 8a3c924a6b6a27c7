#include "scene/blade_shading.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <utility>

#include "util/assert.h"
#include "util/rng.h"

namespace grass::core {
namespace {

// The kernel is cut at 3σ, where exp(-r²/2σ²) = exp(-4.5); subtracting that value makes it reach
// zero continuously, so a blade moving across the cutoff changes nothing by a jump.
constexpr float CUTOFF_SIGMAS = 3.0f;
constexpr float CUTOFF_EXPONENT = 0.5f * CUTOFF_SIGMAS * CUTOFF_SIGMAS;
// ∫ over the plane of the shifted, cut kernel divided by 2πσ²: 1 - exp(-4.5)·(1 + 4.5).
constexpr double KERNEL_MASS = 1.0 - 0.011108996538242306 * 5.5;

// Blades are summed one by one within their own cell while it holds at most this many (cheap:
// cells are σ/2 wide), which keeps the nearest, heaviest terms exact where it matters, in sparse
// grass; beyond it the AO sits near its floor and the cell's clusters are good enough.
constexpr std::uint32_t EXACT_CELL_MAX = 64;
// Other cells are summed per cluster at its centroid. Cells of σ/2 (the default of
// BladeShadingParams::cellSigmas) keep that error small: for blades spread uniformly over a cell
// of side a the kernel errs by (a/σ)²/24·(r²/σ² - 2) relative, -2% at the centre to +7% at the
// 3σ rim, and over a uniform field the errors integrate to zero. Smaller cells cost more
// entries per blade (their number grows as 1/a²).
constexpr float MIN_CELL_SIGMAS = 0.05f;
constexpr float MAX_CELL_SIGMAS = 4.0f;
constexpr float CLUSTER_CONE_COS = 0.9659258f;  // cos 15°, see Cluster
// Cell coordinates are packed 21 bits per axis into a 64-bit key.
constexpr std::uint32_t MAX_CELL_COORD = (1u << 21) - 1;
constexpr unsigned MAX_THREADS = 64;
constexpr std::size_t MIN_CELLS_PER_CHUNK = 64;

// Radii beyond 100 km are typos; they would also push σ² out of float range.
constexpr float MIN_RADIUS_M = MIN_KERNEL_RADIUS_M;
constexpr float MAX_RADIUS_M = 1e5f;

bool isFinite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isLive(const Blade& b) {
    const float h = b.h();
    return h > 0.0f && std::isfinite(h) && isFinite(b.v0()) && isFinite(b.up()) &&
           glm::dot(b.up(), b.up()) > 0.0f;
}

std::string number(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%g", static_cast<double>(v));
    return buffer;
}

Result<void> checkRadius(const char* name, float radius) {
    if (radius == 0.0f || (radius >= MIN_RADIUS_M && radius <= MAX_RADIUS_M))
        return {};
    return makeError(name, "must be 0 (off) or between " + number(MIN_RADIUS_M) + " and " +
                               number(MAX_RADIUS_M) + " metres, got " + number(radius));
}

Result<void> checkUnit(const char* name, float v) {
    if (v >= 0.0f && v <= 1.0f)
        return {};
    return makeError(name, "must be between 0 and 1, got " + number(v));
}

Result<void> validate(const BladeShadingParams& p) {
    for (Result<void> r : {checkRadius("/lighting/ao_radius", p.aoRadiusM),
                           checkRadius("/lighting/normal_blur_radius", p.normalBlurRadiusM),
                           checkUnit("/lighting/ao_floor", p.aoFloor),
                           checkUnit("/lighting/water/0", p.waterRange.x),
                           checkUnit("/lighting/water/1", p.waterRange.y)}) {
        if (!r)
            return r.error();
    }
    if (!(p.cellSigmas == 0.0f ||
          (p.cellSigmas >= MIN_CELL_SIGMAS && p.cellSigmas <= MAX_CELL_SIGMAS)))
        return makeError(
            "/lighting/ao_cell",
            "must be 0 (exact) or in [0.05, 4] kernel sigmas, got " + number(p.cellSigmas));
    if (!(p.aoStrength >= 0.0f) || !std::isfinite(p.aoStrength))
        return makeError(
            "/lighting/ao_strength",
            "must be a finite number >= 0 (m² per blade), got " + number(p.aoStrength));
    return {};
}

std::uint32_t cellCoord(float offset, float cellSize) {
    const float c = std::floor(offset / cellSize);
    return static_cast<std::uint32_t>(std::clamp(c, 0.0f, static_cast<float>(MAX_CELL_COORD)));
}

std::uint64_t packKey(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return std::uint64_t(x) | (std::uint64_t(y) << 21u) | (std::uint64_t(z) << 42u);
}

std::uint64_t keyOf(glm::vec3 offset, float cellSize) {
    return packKey(cellCoord(offset.x, cellSize), cellCoord(offset.y, cellSize),
                   cellCoord(offset.z, cellSize));
}

// The blades of one fine cell whose up vectors lie within 15° of the cluster's first one (cells
// split greedily in blade order). Coherent normals keep the two faces of a thin sheet, a Möbius
// seam or a crease from cancelling or blurring inside one sum, and let the facing weight of the
// cluster's mean up stand for each member's. 30° cones erred by up to 3° against the exact sums
// on a sphere smaller than the blur (the facing weight varies fast there); 15° cones by 0.7°.
// Flat ground keeps one cluster per cell either way.
struct Cluster {
    glm::vec3 centroid{0.0f};
    float count = 0.0f;
    glm::vec3 sumUp{0.0f};
    glm::vec3 meanUp{0.0f};  // unit direction of sumUp (zero if it cancels)
};

struct Cell {
    std::uint32_t first = 0;  // into ClusterGrid::pos and ::up
    std::uint32_t count = 0;
    std::uint32_t firstCluster = 0;
    std::uint32_t clusterCount = 0;
    glm::vec3 lo{0.0f};  // bounds of the member roots
    glm::vec3 hi{0.0f};
};

// Live blades bucketed in fine cells (sorted by cell key, then blade index, so the layout and
// every sum order depend on the input only), their clusters, and a coarse grid of 3σ cells
// over the cluster centroids to find the clusters near a cell.
struct ClusterGrid {
    float sigma = 0.0f;
    glm::vec3 origin{0.0f};
    float coarseSize = 0.0f;
    float exponentLimit = 80.0f;       // see sumEntries
    std::vector<std::uint32_t> order;  // live blade indices, cell by cell
    std::vector<glm::vec3> pos;        // their roots and unit ups, in the same order
    std::vector<glm::vec3> up;
    std::vector<Cell> cells;
    std::vector<Cluster> clusters;
    std::vector<std::uint64_t> coarseKeys;      // sorted, unique
    std::vector<std::uint32_t> coarseFirst;     // coarseKeys[c]'s clusters start here...
    std::vector<std::uint32_t> coarseClusters;  // ...in this list of cluster indices
};

// cellSigmas 0: the smallest cells the key can hold, so that every blade is its own cluster.
ClusterGrid buildGrid(const std::vector<Blade>& blades, const std::vector<std::uint32_t>& live,
                      float sigma, float cellSigmas) {
    ClusterGrid g;
    g.sigma = sigma;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (std::uint32_t i : live) {
        lo = glm::min(lo, blades[i].v0());
        hi = glm::max(hi, blades[i].v0());
    }
    g.origin = lo;
    const glm::vec3 extent = hi - lo;
    const float maxExtent = std::max({extent.x, extent.y, extent.z});
    // A field so large that σ/2 cells overflow the key gets coarser cells: less accurate, still
    // correct (every blade within 3σ is still found).
    const float keyLimit = maxExtent / static_cast<float>(MAX_CELL_COORD - 1);
    const float cellSize = std::max(cellSigmas * sigma, keyLimit);
    g.coarseSize = std::max(CUTOFF_SIGMAS * sigma, keyLimit);

    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(live.size());
    for (std::size_t k = 0; k < live.size(); ++k)
        keyed[k] = {keyOf(blades[live[k]].v0() - lo, cellSize), live[k]};
    std::sort(keyed.begin(), keyed.end());

    g.order.resize(keyed.size());
    g.pos.resize(keyed.size());
    g.up.resize(keyed.size());
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        g.order[k] = keyed[k].second;
        g.pos[k] = blades[g.order[k]].v0();
        g.up[k] = glm::normalize(blades[g.order[k]].up());
    }

    std::vector<glm::vec3> references;
    for (std::size_t begin = 0; begin < keyed.size();) {
        std::size_t end = begin + 1;
        while (end < keyed.size() && keyed[end].first == keyed[begin].first)
            ++end;
        Cell cell;
        cell.first = static_cast<std::uint32_t>(begin);
        cell.count = static_cast<std::uint32_t>(end - begin);
        cell.firstCluster = static_cast<std::uint32_t>(g.clusters.size());
        cell.lo = cell.hi = g.pos[begin];
        // Summed relative to the cell's first root, so fields far from the origin keep precision.
        const glm::vec3 base = g.pos[begin];
        references.clear();
        for (std::size_t k = begin; k < end; ++k) {
            std::size_t c = 0;
            while (c < references.size() && glm::dot(g.up[k], references[c]) < CLUSTER_CONE_COS)
                ++c;
            if (c == references.size()) {
                references.push_back(g.up[k]);
                g.clusters.emplace_back();
            }
            Cluster& cluster = g.clusters[cell.firstCluster + c];
            cluster.centroid += g.pos[k] - base;
            cluster.count += 1.0f;
            cluster.sumUp += g.up[k];
            cell.lo = glm::min(cell.lo, g.pos[k]);
            cell.hi = glm::max(cell.hi, g.pos[k]);
        }
        cell.clusterCount = static_cast<std::uint32_t>(references.size());
        for (std::size_t c = cell.firstCluster; c < g.clusters.size(); ++c) {
            Cluster& cluster = g.clusters[c];
            cluster.centroid = base + cluster.centroid / cluster.count;
            const float len = glm::length(cluster.sumUp);
            if (len > 0.0f)
                cluster.meanUp = cluster.sumUp / len;
        }
        g.cells.push_back(cell);
        begin = end;
    }

    std::vector<std::pair<std::uint64_t, std::uint32_t>> coarse(g.clusters.size());
    for (std::size_t c = 0; c < g.clusters.size(); ++c)
        coarse[c] = {keyOf(g.clusters[c].centroid - lo, g.coarseSize),
                     static_cast<std::uint32_t>(c)};
    std::sort(coarse.begin(), coarse.end());
    g.coarseClusters.resize(coarse.size());
    for (std::size_t c = 0; c < coarse.size(); ++c) {
        if (c == 0 || coarse[c].first != coarse[c - 1].first) {
            g.coarseKeys.push_back(coarse[c].first);
            g.coarseFirst.push_back(static_cast<std::uint32_t>(c));
        }
        g.coarseClusters[c] = coarse[c].second;
    }
    g.coarseFirst.push_back(static_cast<std::uint32_t>(coarse.size()));
    return g;
}

// The sums run over LANES independent accumulators, entry k feeding lane k % LANES, and the
// lanes are added in a fixed order at the end: the compiler can then vectorise the loop without
// reassociating float additions (which it may not do without -ffast-math), and every blade's
// sum has one order whatever the thread count.
constexpr std::size_t LANES = 8;

// What one cell's blades sum over, structure of arrays, padded to a multiple of LANES with
// zero-count entries: clusters of nearby cells and, for a small cell, its own blades one by one.
struct Entries {
    std::vector<float> x, y, z, count, upX, upY, upZ, dirX, dirY, dirZ;

    void clear() {
        for (std::vector<float>* v : {&x, &y, &z, &count, &upX, &upY, &upZ, &dirX, &dirY, &dirZ})
            v->clear();
    }
    void push(glm::vec3 p, float n, glm::vec3 sumUp, glm::vec3 dir) {
        x.push_back(p.x);
        y.push_back(p.y);
        z.push_back(p.z);
        count.push_back(n);
        upX.push_back(sumUp.x);
        upY.push_back(sumUp.y);
        upZ.push_back(sumUp.z);
        dirX.push_back(dir.x);
        dirY.push_back(dir.y);
        dirZ.push_back(dir.z);
    }
    void pad() {
        while (x.size() % LANES != 0)
            push(glm::vec3(0.0f), 0.0f, glm::vec3(0.0f), glm::vec3(0.0f));
    }
    std::size_t size() const { return x.size(); }
};

// The entries any blade of the cell can reach: clusters whose centroid lies within 3σ of the
// cell's bounds, in a fixed order (coarse key, then cluster index); the cell's own clusters are
// replaced by its blades while it holds few.
void gatherEntries(const ClusterGrid& g, const Cell& cell, Entries& out) {
    out.clear();
    const bool exactOwn = cell.count <= EXACT_CELL_MAX;
    if (exactOwn) {
        for (std::uint32_t k = cell.first; k < cell.first + cell.count; ++k)
            out.push(g.pos[k], 1.0f, g.up[k], g.up[k]);
    }
    const float reach = CUTOFF_SIGMAS * g.sigma;
    const float reach2 = reach * reach;
    const glm::vec3 lo = cell.lo - glm::vec3(reach) - g.origin;
    const glm::vec3 hi = cell.hi + glm::vec3(reach) - g.origin;
    const std::uint32_t x0 = cellCoord(lo.x, g.coarseSize), x1 = cellCoord(hi.x, g.coarseSize);
    const std::uint32_t y0 = cellCoord(lo.y, g.coarseSize), y1 = cellCoord(hi.y, g.coarseSize);
    const std::uint32_t z0 = cellCoord(lo.z, g.coarseSize), z1 = cellCoord(hi.z, g.coarseSize);
    for (std::uint32_t z = z0; z <= z1; ++z) {
        for (std::uint32_t y = y0; y <= y1; ++y) {
            for (std::uint32_t x = x0; x <= x1; ++x) {
                const std::uint64_t key = packKey(x, y, z);
                const auto it = std::lower_bound(g.coarseKeys.begin(), g.coarseKeys.end(), key);
                if (it == g.coarseKeys.end() || *it != key)
                    continue;
                const auto c = static_cast<std::size_t>(it - g.coarseKeys.begin());
                for (std::uint32_t k = g.coarseFirst[c]; k < g.coarseFirst[c + 1]; ++k) {
                    const std::uint32_t id = g.coarseClusters[k];
                    if (exactOwn && id >= cell.firstCluster &&
                        id < cell.firstCluster + cell.clusterCount)
                        continue;
                    const Cluster& cl = g.clusters[id];
                    const glm::vec3 d = glm::max(
                        glm::max(cell.lo - cl.centroid, cl.centroid - cell.hi), glm::vec3(0.0f));
                    if (glm::dot(d, d) <= reach2)
                        out.push(cl.centroid, cl.count, cl.sumUp, cl.meanUp);
                }
            }
        }
    }
    out.pad();
}

// exp(x) for x in [-87, 0] to ~2e-7 relative, branch-free so that the entry loop vectorises (a
// call to expf does not): 2^(x·log2 e) split into a rounded integer, put into the exponent bits,
// and a degree-6 Taylor polynomial of the remaining 2^f, |f| <= 1/2. exp(0) is exactly 1, so a
// blade's own term cancels exactly.
constexpr float expNonPositive(float x) {
    // 1.5·2^23: adding it rounds y to an integer held in the low mantissa bits.
    constexpr float ROUND = 12582912.0f;
    const float y = x * 1.44269504f;
    const float shifted = y + ROUND;
    const float f = y - (shifted - ROUND);
    constexpr float C1 = 0.693147181f, C2 = 0.240226507f, C3 = 0.0555041087f, C4 = 0.00961812911f,
                    C5 = 0.00133335581f, C6 = 0.000154035304f;
    const float p = 1.0f + f * (C1 + f * (C2 + f * (C3 + f * (C4 + f * (C5 + f * C6)))));
    const std::int32_t exponent =
        std::bit_cast<std::int32_t>(shifted) - std::bit_cast<std::int32_t>(ROUND);
    return std::bit_cast<float>(std::bit_cast<std::int32_t>(p) + exponent * (1 << 23));
}

// The kernel value at the 3σ cutoff as the loop computes it, so the kernel reaches exactly 0.
constexpr float KERNEL_AT_CUTOFF = expNonPositive(-CUTOFF_EXPONENT);

// Kernel sums at one blade: the weight of the other blades (for the density) and the weighted
// up vectors, the blade's own included (for the blurred normal). Each entry counts by its
// facing weight: smoothstep of the cosine between its mean up and the blade's, from -0.5 (120°,
// nothing) to 0 (90°, fully); see the header for why.
struct KernelSums {
    float weight = 0.0f;
    glm::vec3 up{0.0f};
};

// exponentLimit is a run-time value on purpose: with a literal bound GCC splits the loop on the
// comparison (the bounded path folds to a constant) and then cannot vectorise it.
KernelSums sumEntries(const Entries& e, glm::vec3 p, glm::vec3 n, float inv2s2,
                      float exponentLimit) {
    float w[LANES] = {}, ux[LANES] = {}, uy[LANES] = {}, uz[LANES] = {};
    for (std::size_t b = 0; b < e.size(); b += LANES) {
        for (std::size_t j = 0; j < LANES; ++j) {
            const std::size_t k = b + j;
            const float dx = e.x[k] - p.x, dy = e.y[k] - p.y, dz = e.z[k] - p.z;
            const float d2 = dx * dx + dy * dy + dz * dz;
            const float c = e.dirX[k] * n.x + e.dirY[k] * n.y + e.dirZ[k] * n.z;
            // clamp(2c + 1, 0, 1) written with abs: a min/max against literals folds the
            // smoothstep to constants on the clamped paths and GCC then branches instead of
            // vectorising.
            const float a = 2.0f * c + 1.0f;
            const float t = 0.5f * (std::abs(a) - std::abs(a - 1.0f) + 1.0f);
            const float facingWeight = t * t * (3.0f - 2.0f * t);
            // Past the cutoff exp(-q) < exp(-4.5) and the kernel clamps to 0; the bound on q only
            // keeps expNonPositive in its range.
            const float q = std::min(d2 * inv2s2, exponentLimit);
            const float kernel =
                std::max(expNonPositive(-q) - KERNEL_AT_CUTOFF, 0.0f) * facingWeight;
            w[j] += kernel * e.count[k];
            ux[j] += kernel * e.upX[k];
            uy[j] += kernel * e.upY[k];
            uz[j] += kernel * e.upZ[k];
        }
    }
    KernelSums s;
    for (std::size_t j = 0; j < LANES; ++j) {
        s.weight += w[j];
        s.up += glm::vec3(ux[j], uy[j], uz[j]);
    }
    // The blade itself is among the entries (alone or in its cluster, facing weight 1, kernel
    // 1 - exp(-4.5) at distance 0): take it out of the density.
    s.weight = std::max(s.weight - (1.0f - KERNEL_AT_CUTOFF), 0.0f);
    return s;
}

// Calls write(bladeIndex, unit up, sums) for every live blade that wanted(bladeIndex) accepts,
// cells split over threads by an atomic chunk counter; each blade's sums depend on its cell
// alone, so any split gives the same bits. A cell with no wanted blade is skipped whole: a
// re-bake sums only its targets, not the neighbours the grid holds for them.
template <class Wanted, class Write>
void forEachBladeSums(const ClusterGrid& g, unsigned threads, Wanted&& wanted, Write&& write) {
    const float inv2s2 = 1.0f / (2.0f * g.sigma * g.sigma);
    const std::size_t cellCount = g.cells.size();
    const std::size_t chunk =
        std::max(MIN_CELLS_PER_CHUNK, cellCount / (std::size_t(threads) * 16));
    std::atomic<std::size_t> next{0};

    auto worker = [&] {
        Entries entries;
        for (;;) {
            const std::size_t begin = next.fetch_add(chunk);
            if (begin >= cellCount)
                return;
            const std::size_t end = std::min(cellCount, begin + chunk);
            for (std::size_t c = begin; c < end; ++c) {
                const Cell& cell = g.cells[c];
                const std::uint32_t cellEnd = cell.first + cell.count;
                bool any = false;
                for (std::uint32_t k = cell.first; k < cellEnd && !any; ++k)
                    any = wanted(g.order[k]);
                if (!any)
                    continue;
                gatherEntries(g, cell, entries);
                for (std::uint32_t k = cell.first; k < cellEnd; ++k)
                    if (wanted(g.order[k]))
                        write(g.order[k], g.up[k],
                              sumEntries(entries, g.pos[k], g.up[k], inv2s2, g.exponentLimit));
            }
        }
    };

    const std::size_t chunks = (cellCount + chunk - 1) / chunk;
    const auto extra = static_cast<unsigned>(std::min<std::size_t>(threads, chunks) - 1);
    std::vector<std::thread> workers;
    workers.reserve(extra);
    for (unsigned t = 0; t < extra; ++t)
        workers.emplace_back(worker);
    worker();
    for (std::thread& t : workers)
        t.join();
}

}  // namespace

namespace {

// The bake of the blades marked in `target` (all live ones when null), summing over `live`
// neighbours; entries not targeted are left as they are.
void bakeInto(const std::vector<Blade>& blades, const std::vector<std::uint32_t>& live,
              const std::vector<bool>* target, const BladeShadingParams& params, std::uint64_t seed,
              unsigned threadCount, std::vector<BladeShading>& out) {
    const auto targeted = [&](std::uint32_t i) { return target == nullptr || (*target)[i]; };
    for (std::uint32_t i : live) {
        if (!targeted(i))
            continue;
        // Age from the blade's slot: deterministic per seed and free of any thread order.
        Rng rng(seed, i);
        const float age = rng.uniform();
        const float water = params.waterRange.y + (params.waterRange.x - params.waterRange.y) * age;
        out[i].blurredNormalAo = glm::vec4(glm::normalize(blades[i].up()), 1.0f);
        out[i].waterAge = glm::vec4(water, age, 0.0f, 0.0f);
    }
    if (live.empty())
        return;

    unsigned threads = threadCount > 0 ? threadCount : std::thread::hardware_concurrency();
    threads = std::clamp(threads, 1u, MAX_THREADS);

    // Neighbours count by number, not weighted by height: within one layer heights vary only
    // over the layer's random range, and a pure density keeps aoStrength calibrated in blades
    // per m² (SPEC §10 "from the density of surrounding grass").
    if (params.aoRadiusM > 0.0f) {
        const ClusterGrid grid = buildGrid(blades, live, params.aoRadiusM, params.cellSigmas);
        const double norm = 2.0 * std::numbers::pi * double(params.aoRadiusM) *
                            double(params.aoRadiusM) * KERNEL_MASS;
        const float perWeight = static_cast<float>(1.0 / norm);
        forEachBladeSums(grid, threads, targeted, [&](std::uint32_t i, glm::vec3, const KernelSums& s) {
            const float density = s.weight * perWeight;
            // Clamped because floor + (1 - floor)·1 can round a hair above 1.
            const float ao =
                params.aoFloor + (1.0f - params.aoFloor) * std::exp(-density * params.aoStrength);
            out[i].blurredNormalAo.w = std::clamp(ao, params.aoFloor, 1.0f);
        });
    }
    if (params.normalBlurRadiusM > 0.0f) {
        const ClusterGrid grid =
            buildGrid(blades, live, params.normalBlurRadiusM, params.cellSigmas);
        forEachBladeSums(grid, threads, targeted, [&](std::uint32_t i, glm::vec3 up, const KernelSums& s) {
            const float len = glm::length(s.up);
            // Neighbours within 90° count fully and those beyond 120° not at all, so the sum
            // only vanishes or turns away from the blade's own up on folds sharper than a right
            // angle crowded from one side (or when nothing was summed); own up is then the best
            // guess.
            if (len > 1e-12f && std::isfinite(len) && glm::dot(s.up, up) > 0.0f)
                out[i].blurredNormalAo = glm::vec4(s.up / len, out[i].blurredNormalAo.w);
        });
    }
}

}  // namespace

Result<std::vector<BladeShading>> bakeBladeShading(const std::vector<Blade>& blades,
                                                   const BladeShadingParams& params,
                                                   std::uint64_t seed, unsigned threadCount) {
    if (Result<void> valid = validate(params); !valid)
        return valid.error();
    GRASS_ASSERT(blades.size() < std::numeric_limits<std::uint32_t>::max());

    std::vector<BladeShading> out(blades.size());
    std::vector<std::uint32_t> live;
    live.reserve(blades.size());
    for (std::size_t i = 0; i < blades.size(); ++i)
        if (isLive(blades[i]))
            live.push_back(static_cast<std::uint32_t>(i));
    bakeInto(blades, live, nullptr, params, seed, threadCount, out);
    return out;
}

Result<std::size_t> rebakeBladeShading(const std::vector<Blade>& blades,
                                       const BladeShadingParams& params, std::uint64_t seed,
                                       const Bounds& region, std::vector<BladeShading>& shading,
                                       unsigned threadCount) {
    GRASS_ASSERT(blades.size() < std::numeric_limits<std::uint32_t>::max());
    return rebakeBladeShading(blades, params, seed, region,
                              {SlotRange{0, static_cast<std::uint32_t>(blades.size())}}, shading,
                              threadCount);
}

namespace {

// The re-bake of the live blades in `slots` whose root is in `region` and whose slot lies in
// `targetSlots` (all of `slots` when null), summing over the live blades of `slots` within 3σ
// of the region.
Result<std::size_t> rebakeSlots(const std::vector<Blade>& blades, const BladeShadingParams& params,
                                std::uint64_t seed, const Bounds& region,
                                const std::vector<SlotRange>& slots,
                                const std::vector<SlotRange>* targetSlots,
                                std::vector<BladeShading>& shading, unsigned threadCount) {
    if (Result<void> valid = validate(params); !valid)
        return valid.error();
    GRASS_ASSERT(blades.size() < std::numeric_limits<std::uint32_t>::max());
    if (shading.size() != blades.size())
        return makeError("shading", "has " + std::to_string(shading.size()) + " entries for " +
                                        std::to_string(blades.size()) + " blades");
    std::vector<bool> eligible;
    if (targetSlots != nullptr) {
        eligible.assign(blades.size(), false);
        for (const SlotRange& range : *targetSlots) {
            GRASS_ASSERT(range.first <= range.end && range.end <= blades.size());
            std::fill(eligible.begin() + range.first, eligible.begin() + range.end, true);
        }
    }
    // Every neighbour a targeted blade's kernels reach lies within 3σ of it.
    const float reach = CUTOFF_SIGMAS * std::max(params.aoRadiusM, params.normalBlurRadiusM);
    const Bounds near{region.min - glm::vec3(reach), region.max + glm::vec3(reach)};
    std::vector<std::uint32_t> nearBlades;
    std::vector<bool> target(blades.size(), false);
    std::size_t targets = 0;
    for (const SlotRange& range : slots) {
        GRASS_ASSERT(range.first <= range.end && range.end <= blades.size());
        for (std::uint32_t i = range.first; i < range.end; ++i) {
            const bool live = isLive(blades[i]);
            if ((eligible.empty() || eligible[i]) && region.contains(blades[i].v0())) {
                // A slot that is padding now gets the padding's entry, as the full bake gives it.
                if (!live)
                    shading[i] = BladeShading{};
                target[i] = live;
                targets += live ? 1 : 0;
            }
            if (live && near.contains(blades[i].v0()))
                nearBlades.push_back(i);
        }
    }
    if (targets > 0)
        bakeInto(blades, nearBlades, &target, params, seed, threadCount, shading);
    return targets;
}

}  // namespace

Result<std::size_t> rebakeBladeShading(const std::vector<Blade>& blades,
                                       const BladeShadingParams& params, std::uint64_t seed,
                                       const Bounds& region, const std::vector<SlotRange>& slots,
                                       std::vector<BladeShading>& shading, unsigned threadCount) {
    return rebakeSlots(blades, params, seed, region, slots, nullptr, shading, threadCount);
}

Result<std::size_t> rebakeBladeShading(const std::vector<Blade>& blades,
                                       const BladeShadingParams& params, std::uint64_t seed,
                                       const std::vector<SlotRange>& targets,
                                       const std::vector<SlotRange>& slots,
                                       std::vector<BladeShading>& shading, unsigned threadCount) {
    // The targets' roots bound the region; a target slot that is padding keeps its entry
    // reset below, as the region-based re-bake resets padding inside its region.
    Bounds region{glm::vec3(std::numeric_limits<float>::max()),
                  glm::vec3(-std::numeric_limits<float>::max())};
    bool any = false;
    for (const SlotRange& range : targets) {
        GRASS_ASSERT(range.first <= range.end && range.end <= blades.size());
        for (std::uint32_t i = range.first; i < range.end; ++i) {
            if (!isLive(blades[i])) {
                if (i < shading.size())
                    shading[i] = BladeShading{};
                continue;
            }
            region.min = glm::min(region.min, blades[i].v0());
            region.max = glm::max(region.max, blades[i].v0());
            any = true;
        }
    }
    if (!any)
        return std::size_t{0};
    return rebakeSlots(blades, params, seed, region, slots, &targets, shading, threadCount);
}

}  // namespace grass::core
