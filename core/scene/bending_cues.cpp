#include "scene/bending_cues.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "physics/physics.h"
#include "util/thread_pool.h"

namespace grass::core {

namespace {

constexpr float PI = 3.14159265358979f;
constexpr float RADIANS_PER_DEGREE = PI / 180.0f;
constexpr float KERNEL_REACH_SIGMAS = 3.0f;

// The growable candidates sorted by the cell of a cubic grid of side 3σ, so every neighbour
// within 3σ of a root lies in the 27 cells around its own, and each cell's candidates lie
// together in memory (a blade record is 64 bytes; the shade needs 20 of them).
struct CellGrid {
    struct Root {
        glm::vec3 p;
        float h;
        float rule;
        std::uint32_t index;  // the candidate's
    };
    struct Range {
        std::uint32_t begin, end;
    };
    float cell = 1.0f;
    std::vector<Root> roots;                         // sorted by cell
    std::vector<std::uint64_t> cellKeys;             // one per cell, in the order of `roots`
    std::vector<Range> cellRanges;                   // parallel to cellKeys
    std::unordered_map<std::uint64_t, Range> find;   // key → range

    static std::uint64_t key(glm::ivec3 c) {
        // 21 bits an axis: ±10^6 cells, far beyond any scene a layer can grow in.
        const auto bits = [](int v) { return std::uint64_t(std::uint32_t(v) & 0x1FFFFFu); };
        return bits(c.x) | (bits(c.y) << 21) | (bits(c.z) << 42);
    }
    glm::ivec3 cellOf(glm::vec3 p) const { return glm::ivec3(glm::floor(p / cell)); }
};

bool isGrowable(const Blade& blade) {
    return blade.h() > 0.0f && std::isfinite(blade.h()) && std::isfinite(blade.v0().x) &&
           std::isfinite(blade.v0().y) && std::isfinite(blade.v0().z);
}

}  // namespace

bool bendingIsOff(const BendingCues& cues) {
    return !(cues.slope > 0.0f) && !(cues.neighboursDeg > 0.0f) && !(cues.sway > 0.0f);
}

namespace {

// The grid of `candidates`' growable roots with their rule factors, cells 3σ wide.
CellGrid shadeGrid(const ScatterCandidates& candidates, std::span<const float> ruleFactors,
                   float sigmaM) {
    const std::vector<Blade>& blades = candidates.blades;
    CellGrid grid;
    grid.cell = KERNEL_REACH_SIGMAS * sigmaM;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> byCell;
    byCell.reserve(blades.size());
    for (std::uint32_t i = 0; i < blades.size(); ++i)
        if (isGrowable(blades[i]))
            byCell.emplace_back(CellGrid::key(grid.cellOf(blades[i].v0())), i);
    std::sort(byCell.begin(), byCell.end());
    grid.roots.reserve(byCell.size());
    for (std::size_t k = 0; k < byCell.size(); ++k) {
        const std::uint32_t i = byCell[k].second;
        const float rule = ruleFactors.empty() ? 1.0f : std::clamp(ruleFactors[i], 0.0f, 1.0f);
        grid.roots.push_back({blades[i].v0(), blades[i].h(), rule, i});
        if (k == 0 || byCell[k].first != byCell[k - 1].first) {
            grid.cellKeys.push_back(byCell[k].first);
            grid.cellRanges.push_back({static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k)});
        }
        grid.cellRanges.back().end = static_cast<std::uint32_t>(k + 1);
    }
    grid.find.reserve(grid.cellKeys.size());
    for (std::size_t c = 0; c < grid.cellKeys.size(); ++c)
        grid.find.emplace(grid.cellKeys[c], grid.cellRanges[c]);
    return grid;
}

// The ranges of the 27 cells around grid cell `at` that hold roots, in one fixed order (so a
// root's shade sums its neighbours in the same order whichever cells are shaded).
void rangesAround(const CellGrid& grid, glm::ivec3 at, std::vector<CellGrid::Range>& around) {
    around.clear();
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const auto found = grid.find.find(CellGrid::key(at + glm::ivec3(dx, dy, dz)));
                if (found != grid.find.end())
                    around.push_back(found->second);
            }
}

// The shade of every root of the grid cell holding roots `home`, handed to
// `put(candidate, shade)`.
template <typename Put>
void shadeCell(const CellGrid& grid, CellGrid::Range home, float sigmaM,
               std::vector<CellGrid::Range>& around, const Put& put) {
    const float reach2 = grid.cell * grid.cell;
    const float inv2s2 = 1.0f / (2.0f * sigmaM * sigmaM);
    const float norm = 1.0f / (2.0f * PI * sigmaM * sigmaM);
    // The 27 look-ups of a cell serve every root in it.
    rangesAround(grid, grid.cellOf(grid.roots[home.begin].p), around);
    for (std::uint32_t r = home.begin; r < home.end; ++r) {
        const CellGrid::Root& root = grid.roots[r];
        const float invH = 1.0f / root.h;
        float density = 0.0f;
        for (const CellGrid::Range range : around)
            for (std::uint32_t n = range.begin; n < range.end; ++n) {
                const CellGrid::Root& other = grid.roots[n];
                const glm::vec3 d = other.p - root.p;
                const float r2 = glm::dot(d, d);
                if (r2 >= reach2 || n == r)
                    continue;
                const float taller = std::min(other.h * invH, MAX_NEIGHBOUR_HEIGHT_RATIO);
                density += other.rule * taller * std::exp(-r2 * inv2s2);
            }
        put(root.index, 1.0f - std::exp(-NEIGHBOUR_CROSS_SECTION_M2 * density * norm));
    }
}

}  // namespace

std::vector<float> neighbourShade(const ScatterCandidates& candidates,
                                  std::span<const float> ruleFactors, float sigmaM) {
    std::vector<float> shade(candidates.blades.size(), 0.0f);
    if (!(sigmaM > 0.0f) || candidates.blades.empty())
        return shade;
    const CellGrid grid = shadeGrid(candidates, ruleFactors, sigmaM);
    ThreadPool& pool = ThreadPool::shared();
    pool.run(grid.cellKeys.size(), (pool.workerCount() + 1) * 8,
             [&](std::size_t firstCell, std::size_t endCell) {
                 std::vector<CellGrid::Range> around;
                 for (std::size_t c = firstCell; c < endCell; ++c)
                     shadeCell(grid, grid.cellRanges[c], sigmaM, around,
                               [&](std::uint32_t i, float value) { shade[i] = value; });
             });
    return shade;
}

std::vector<std::pair<std::uint32_t, float>> neighbourShadeAround(
    const ScatterCandidates& candidates, std::span<const float> ruleFactors, float sigmaM,
    std::span<const std::uint32_t> changed) {
    std::vector<std::pair<std::uint32_t, float>> shaded;
    if (!(sigmaM > 0.0f) || candidates.blades.empty() || changed.empty())
        return shaded;
    const CellGrid grid = shadeGrid(candidates, ruleFactors, sigmaM);
    // The cells within one of a changed candidate's: its neighbours lie there (cells are 3σ).
    std::vector<CellGrid::Range> cells;
    std::vector<CellGrid::Range> around;
    for (const std::uint32_t i : changed) {
        rangesAround(grid, grid.cellOf(candidates.blades[i].v0()), around);
        cells.insert(cells.end(), around.begin(), around.end());
    }
    const auto byBegin = [](CellGrid::Range a, CellGrid::Range b) { return a.begin < b.begin; };
    std::sort(cells.begin(), cells.end(), byBegin);
    cells.erase(
        std::unique(cells.begin(), cells.end(),
                    [](CellGrid::Range a, CellGrid::Range b) { return a.begin == b.begin; }),
        cells.end());
    for (const CellGrid::Range home : cells)
        shadeCell(grid, home, sigmaM, around,
                  [&](std::uint32_t i, float value) { shaded.emplace_back(i, value); });
    return shaded;
}

glm::vec3 downhillAt(glm::vec3 normal, glm::vec3 p, const RuleWorld& world) {
    const glm::vec3 down = -upAt(p, world);
    const glm::vec3 along = down - glm::dot(down, normal) * normal;
    const float length = glm::length(along);
    // Below 1e-4 (level ground within 0.006°) the direction is noise.
    return length > 1e-4f && std::isfinite(length) ? along / length : glm::vec3(0.0f);
}

CandidateBend candidateBend(const BendingCues& cues, const Blade& candidate, float shade,
                            const RuleWorld& world) {
    CandidateBend bend;
    const glm::vec3 up = candidate.up();
    if (cues.slope > 0.0f) {
        const float slope = std::min(slopeDeg(up, candidate.v0(), world), 90.0f);
        bend.downhill = downhillAt(up, candidate.v0(), world);
        if (glm::dot(bend.downhill, bend.downhill) > 0.0f)
            bend.leanRad += cues.slope * slope * RADIANS_PER_DEGREE;
    }
    if (cues.neighboursDeg > 0.0f)
        bend.leanRad += cues.neighboursDeg * RADIANS_PER_DEGREE * std::clamp(shade, 0.0f, 1.0f);
    return bend;
}

std::vector<CandidateBend> candidateBends(const BendingCues& cues,
                                          const ScatterCandidates& candidates,
                                          std::span<const float> ruleFactors,
                                          const RuleWorld& world) {
    if (bendingIsOff(cues))
        return {};
    const std::vector<float> shade =
        cues.neighboursDeg > 0.0f ? neighbourShade(candidates, ruleFactors, cues.neighbourRadiusM)
                                  : std::vector<float>(candidates.blades.size(), 0.0f);
    std::vector<CandidateBend> bends(candidates.blades.size());
    for (std::size_t i = 0; i < bends.size(); ++i)
        bends[i] = candidateBend(cues, candidates.blades[i], shade[i], world);
    return bends;
}

void updateCandidateBends(const BendingCues& cues, const ScatterCandidates& candidates,
                          std::span<const float> ruleFactors, const RuleWorld& world,
                          std::span<const std::uint32_t> changed,
                          std::vector<CandidateBend>& bends) {
    // Only the neighbours' shade reads the rule factors.
    if (bendingIsOff(cues) || !(cues.neighboursDeg > 0.0f))
        return;
    for (const auto& [i, shade] :
         neighbourShadeAround(candidates, ruleFactors, cues.neighbourRadiusM, changed))
        bends[i] = candidateBend(cues, candidates.blades[i], shade, world);
}

void leanTowardsFront(Blade& blade, float leanRad) {
    if (!(leanRad > 0.0f))
        return;
    // The up as stored: candidates carry unit normals, and normalising again could move the
    // last bit of every leaned tip.
    const glm::vec3 up = blade.up();
    const glm::vec3 front = glm::normalize(glm::cross(up, widthDirection(up, blade.theta())));
    const glm::vec3 direction = std::cos(leanRad) * up + std::sin(leanRad) * front;
    blade.v2W = glm::vec4(blade.v0() + blade.h() * direction, blade.w());
    validateBlade(blade);
}

Blade bentRestBlade(const Blade& c, float h, float w, float growthLeanRad,
                    const CandidateBend& bend, float sway) {
    const glm::vec3 up = c.up();
    float theta = c.theta();
    if (glm::dot(bend.downhill, bend.downhill) > 0.0f) {
        const glm::vec3 front = glm::cross(up, widthDirection(up, theta));
        if (glm::dot(front, bend.downhill) < 0.0f)
            theta = theta >= PI ? theta - PI : theta + PI;
    }
    const float lean = std::min(std::max(growthLeanRad, 0.0f) + bend.leanRad, MAX_REST_LEAN_RAD);
    const float stiffness = c.s() * (1.0f - std::clamp(sway, 0.0f, 1.0f) * std::sin(lean));
    Blade blade = makeRestBlade(c.v0(), up, h, w, stiffness, theta);
    leanTowardsFront(blade, lean);
    return blade;
}

}  // namespace grass::core
