// Charts of the UV atlas (atlas::makeCharts): region growing by normal cone over welded
// connectivity, orthographic flattening onto each chart's mean plane, and removal of the faces
// that keep a flattening from being one-to-one.
#include "mesh/uv_atlas_detail.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>

#include "mesh/uv_atlas.h"

namespace grass::core::atlas {

namespace {

constexpr double PI = 3.14159265358979323846;
// Faces this close to edge-on are never kept in a chart, whatever the cone: their projection
// would lose most of their area (cos 85° = 0.09).
constexpr double TILT_MAX_DEG = 85.0;
// Overlap tolerance inside a chart, relative to its extent. Packing scales a chart to at most
// the unit square, so this is at most 1e-7 in UV: every overlap findUvOverlaps would count
// (over 1e-6) is caught here first.
constexpr double CHART_EPSILON = 1e-7;
// Faces whose flattened doubled area is below this fraction of the chart's squared extent have
// no interior to overlap with; findUvOverlaps leaves out the same faces (1e-12 of its extent).
constexpr double CHART_DEGENERATE_AREA = 1e-12;

double cosDeg(double deg) {
    return std::cos(deg * PI / 180.0);
}

// The chart grower's per-face state.
enum class FaceState : char { Free, Taken };

struct Candidate {
    double deviation = 0.0;  // 1 − cos of the angle to the chart normal when queued
    std::uint32_t face = 0;
    bool operator>(const Candidate& o) const {
        return std::tie(deviation, face) > std::tie(o.deviation, o.face);
    }
};

// The chart normal: area-weighted mean of its faces' normals, else any face's, else +Z.
glm::dvec3 chartNormal(const WeldedMesh& mesh, const std::vector<std::uint32_t>& faces) {
    glm::dvec3 sum(0.0);
    for (const std::uint32_t f : faces)
        sum += mesh.normals[f] * mesh.areas[f];
    const double length = glm::length(sum);
    if (length > 0.0 && std::isfinite(length))
        return sum / length;
    for (const std::uint32_t f : faces) {
        if (mesh.normals[f] != glm::dvec3(0.0))
            return mesh.normals[f];
    }
    return {0.0, 0.0, 1.0};
}

// Grows one chart from `seed` over free faces, best-aligned neighbour first. With a `fixed`
// normal a face joins while within the cone around it; without, around the running
// area-weighted mean. Faces without a normal (zero area) join any chart that reaches them.
std::vector<std::uint32_t> growFrom(const WeldedMesh& mesh, std::uint32_t seed, double cosAngle,
                                    const glm::dvec3* fixed, std::vector<FaceState>& state) {
    std::vector<std::uint32_t> chart;
    glm::dvec3 sum(0.0);
    const auto centre = [&] {
        if (fixed)
            return *fixed;
        const double length = glm::length(sum);
        return length > 0.0 ? sum / length : glm::dvec3(0.0);
    };
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> queue;
    queue.push({0.0, seed});
    while (!queue.empty()) {
        const std::uint32_t f = queue.top().face;
        queue.pop();
        if (state[f] != FaceState::Free)
            continue;
        const glm::dvec3 axis = centre();
        const bool anyCone = mesh.normals[f] == glm::dvec3(0.0) || axis == glm::dvec3(0.0);
        if (f != seed && !anyCone && glm::dot(mesh.normals[f], axis) < cosAngle)
            continue;
        state[f] = FaceState::Taken;
        chart.push_back(f);
        sum += mesh.normals[f] * mesh.areas[f];
        const glm::dvec3 next = centre();
        for (std::uint32_t i = mesh.neighbourStart[f]; i < mesh.neighbourStart[f + 1]; ++i) {
            const std::uint32_t g = mesh.neighbours[i];
            if (state[g] == FaceState::Free)
                queue.push({1.0 - glm::dot(mesh.normals[g], next), g});
        }
    }
    std::sort(chart.begin(), chart.end());
    return chart;
}

// Orthographic projection of `faces` onto the plane of their mean normal. The tangent frame
// (t, b, normal) is right-handed, so faces facing the normal stay counter-clockwise.
FlatChart flatten(const WeldedMesh& mesh, const std::vector<std::uint32_t>& faces,
                  glm::dvec3 normal) {
    const glm::dvec3 axis = std::abs(normal.x) < 0.6   ? glm::dvec3(1, 0, 0)
                            : std::abs(normal.y) < 0.6 ? glm::dvec3(0, 1, 0)
                                                       : glm::dvec3(0, 0, 1);
    const glm::dvec3 t = glm::normalize(glm::cross(normal, axis));
    const glm::dvec3 b = glm::cross(normal, t);
    // Each welded vertex is projected once, so its corners in this chart are bitwise equal and
    // faces sharing it touch exactly (findUvOverlaps relies on that for shared edges).
    std::vector<std::uint32_t> welds;
    welds.reserve(3 * faces.size());
    for (const std::uint32_t f : faces)
        welds.insert(welds.end(), mesh.corners[f].begin(), mesh.corners[f].end());
    std::sort(welds.begin(), welds.end());
    welds.erase(std::unique(welds.begin(), welds.end()), welds.end());
    // Relative to one of its vertices, so a chart far from the origin keeps its precision.
    const glm::dvec3 origin = mesh.positions[welds.front()];
    std::vector<glm::dvec2> flat(welds.size());
    for (std::size_t i = 0; i < welds.size(); ++i) {
        const glm::dvec3 p = mesh.positions[welds[i]] - origin;
        flat[i] = {glm::dot(p, t), glm::dot(p, b)};
    }
    FlatChart chart;
    chart.faces = faces;
    chart.corners.resize(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
            const auto at = std::lower_bound(welds.begin(), welds.end(), mesh.corners[faces[i]][k]);
            chart.corners[i][k] = flat[static_cast<std::size_t>(at - welds.begin())];
        }
        chart.area3d += mesh.areas[faces[i]];
        chart.areaFlat += 0.5 * std::abs(doubledArea(chart.corners[i]));
    }
    return chart;
}

// The faces (indices into chart.faces) that keep the flattening from being one-to-one: faces
// tilted past `cosLimit` or turned over, and the later face of every overlapping pair.
std::vector<std::size_t> facesAtFault(const WeldedMesh& mesh, const FlatChart& chart,
                                      glm::dvec3 normal, double cosLimit) {
    std::vector<std::size_t> fault;
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (const Triangle2& t : chart.corners) {
        for (const glm::dvec2& p : t) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    std::vector<char> active(chart.faces.size(), 0);
    for (std::size_t i = 0; i < chart.faces.size(); ++i) {
        const glm::dvec3 n = mesh.normals[chart.faces[i]];
        const double doubled = doubledArea(chart.corners[i]);
        const bool hasNormal = n != glm::dvec3(0.0);
        if (hasNormal && (glm::dot(n, normal) < cosLimit || !(doubled > 0.0)))
            fault.push_back(i);
        active[i] = std::abs(doubled) > CHART_DEGENERATE_AREA * extent * extent ? 1 : 0;
    }
    if (chart.faces.size() > 1) {
        std::vector<OverlapPair> pairs;
        countOverlaps(chart.corners, active, CHART_EPSILON * extent, UV_OVERLAP_CAP, &pairs);
        for (const OverlapPair& p : pairs)
            fault.push_back(p.b);
    }
    std::sort(fault.begin(), fault.end());
    fault.erase(std::unique(fault.begin(), fault.end()), fault.end());
    return fault;
}

// The chart's faces without those at `fault` (ascending indices into chart.faces). The rest keep
// their flattened corners as they are: removing faces cannot create an overlap.
FlatChart withoutFaces(const WeldedMesh& mesh, const FlatChart& chart,
                       const std::vector<std::size_t>& fault) {
    FlatChart kept;
    std::size_t next = 0;
    for (std::size_t i = 0; i < chart.faces.size(); ++i) {
        if (next < fault.size() && fault[next] == i) {
            ++next;
            continue;
        }
        kept.faces.push_back(chart.faces[i]);
        kept.corners.push_back(chart.corners[i]);
        kept.area3d += mesh.areas[chart.faces[i]];
        kept.areaFlat += 0.5 * std::abs(doubledArea(chart.corners[i]));
    }
    return kept;
}

}  // namespace

std::vector<FlatChart> makeCharts(const WeldedMesh& mesh, double chartAngleDeg) {
    const double cosAngle = cosDeg(chartAngleDeg);
    const double cosLimit = cosDeg(std::min(chartAngleDeg, TILT_MAX_DEG));
    std::vector<FaceState> state(mesh.corners.size(), FaceState::Free);
    std::vector<FlatChart> charts;
    for (std::uint32_t seed = 0; seed < mesh.corners.size(); ++seed) {
        // Every face before the seed is taken, so each chart takes faces from the seed on, and
        // a seed left free (by the second growth or as a fault) starts the next chart.
        while (state[seed] == FaceState::Free) {
            // A chart grown around its running mean drifts: faces taken early can end up far
            // from the final mean. So it is grown twice: once to find where its mean settles,
            // then from the face nearest that mean with the mean fixed, which keeps every face
            // within the cone of the normal it is projected along.
            const std::vector<std::uint32_t> trial = growFrom(mesh, seed, cosAngle, nullptr, state);
            const glm::dvec3 normal = chartNormal(mesh, trial);
            std::uint32_t centre = seed;
            double best = -INFINITY;
            for (const std::uint32_t f : trial) {
                state[f] = FaceState::Free;
                const double alignment = glm::dot(mesh.normals[f], normal);
                if (mesh.normals[f] != glm::dvec3(0.0) && alignment > best) {
                    best = alignment;
                    centre = f;
                }
            }
            const std::vector<std::uint32_t> faces =
                growFrom(mesh, centre, cosAngle, &normal, state);
            FlatChart chart = flatten(mesh, faces, normal);
            // Faces at fault go back to be taken by later charts. A face that is its own chart
            // flattens one-to-one onto its own plane.
            const std::vector<std::size_t> fault = facesAtFault(mesh, chart, normal, cosLimit);
            if (!fault.empty()) {
                for (const std::size_t i : fault)
                    state[chart.faces[i]] = FaceState::Free;
                chart = withoutFaces(mesh, chart, fault);
                if (chart.faces.empty()) {
                    const std::vector<std::uint32_t> single{centre};
                    state[centre] = FaceState::Taken;
                    chart = flatten(mesh, single, chartNormal(mesh, single));
                }
            }
            charts.push_back(std::move(chart));
        }
    }
    return charts;
}

}  // namespace grass::core::atlas
