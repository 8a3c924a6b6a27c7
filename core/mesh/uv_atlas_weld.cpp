// Welding for the UV atlas (atlas::weldMesh): SurfaceMesh keeps glTF primitives and
// non-manifold faces on vertices of their own, so connectivity comes from equal positions.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <tuple>

#include "mesh/uv_atlas_detail.h"

namespace grass::core::atlas {

namespace {

// Positions equal to this fraction of the bounds weld: far above float rounding of one
// position written twice, far below any real feature.
constexpr double WELD_TOLERANCE = 1e-6;
// Faces whose doubled area is below this fraction of the squared bounds have no usable normal.
constexpr double DEGENERATE_AREA = 1e-12;
// More faces than this on one edge is a fan of fins (foliage cards glued on a stem): joining
// them all would cost a quadratic number of links for charts that fold anyway.
constexpr std::size_t EDGE_FACES_MAX = 8;

using Key = std::array<std::int64_t, 3>;

struct Edge {
    std::uint32_t lo = 0;
    std::uint32_t hi = 0;
    std::uint32_t face = 0;
    bool operator<(const Edge& o) const {
        return std::tie(lo, hi, face) < std::tie(o.lo, o.hi, o.face);
    }
};

}  // namespace

WeldedMesh weldMesh(const SurfaceMesh& mesh) {
    WeldedMesh out;
    const Bounds bounds = meshBounds(mesh);
    const glm::dvec3 size = bounds.size();
    const double extent = std::max({size.x, size.y, size.z});
    const double quantum = extent > 0.0 && std::isfinite(extent) ? extent * WELD_TOLERANCE : 1.0;

    const std::size_t nv = mesh.n_vertices();
    std::vector<Key> keys(nv);
    for (std::size_t v = 0; v < nv; ++v) {
        const glm::dvec3 p = toGlm(mesh.point(mesh.vertex_handle(static_cast<int>(v))));
        const glm::dvec3 q = (p - glm::dvec3(bounds.min)) / quantum;
        if (std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) &&
            std::abs(q.x) < 9e18 && std::abs(q.y) < 9e18 && std::abs(q.z) < 9e18) {
            keys[v] = {std::llround(q.x), std::llround(q.y), std::llround(q.z)};
        } else {
            // Never welded: a key no finite position rounds to, unique per vertex.
            keys[v] = {INT64_MIN, INT64_MIN, static_cast<std::int64_t>(v)};
        }
    }
    std::vector<std::uint32_t> order(nv);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return std::tie(keys[a], a) < std::tie(keys[b], b);
    });
    // The lowest vertex index of a group gives the welded position, so every corner of a welded
    // vertex flattens from the same numbers.
    std::vector<std::uint32_t> weldOf(nv);
    for (std::size_t i = 0; i < nv; ++i) {
        const std::uint32_t v = order[i];
        if (i == 0 || keys[v] != keys[order[i - 1]]) {
            out.positions.push_back(toGlm(mesh.point(mesh.vertex_handle(static_cast<int>(v)))));
        }
        weldOf[v] = static_cast<std::uint32_t>(out.positions.size() - 1);
    }

    const std::size_t nf = mesh.n_faces();
    out.corners.resize(nf);
    out.normals.assign(nf, glm::dvec3(0.0));
    out.areas.assign(nf, 0.0);
    std::vector<Edge> edges;
    edges.reserve(3 * nf);
    for (const auto fh : mesh.faces()) {
        const auto f = static_cast<std::uint32_t>(fh.idx());
        std::size_t k = 0;
        for (const auto vh : mesh.fv_range(fh))
            out.corners[f][k++] = weldOf[static_cast<std::size_t>(vh.idx())];
        const auto& c = out.corners[f];
        const glm::dvec3 cross = glm::cross(out.positions[c[1]] - out.positions[c[0]],
                                            out.positions[c[2]] - out.positions[c[0]]);
        const double doubled = glm::length(cross);
        if (std::isfinite(doubled)) {
            out.areas[f] = 0.5 * doubled;
            if (doubled > DEGENERATE_AREA * extent * extent)
                out.normals[f] = cross / doubled;
        }
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t a = c[e], b = c[(e + 1) % 3];
            if (a != b)
                edges.push_back({std::min(a, b), std::max(a, b), f});
        }
    }
    std::sort(edges.begin(), edges.end());

    std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi)
            ++j;
        if (j - i <= EDGE_FACES_MAX) {
            for (std::size_t a = i; a < j; ++a) {
                for (std::size_t b = a + 1; b < j; ++b) {
                    if (edges[a].face != edges[b].face) {
                        links.emplace_back(edges[a].face, edges[b].face);
                        links.emplace_back(edges[b].face, edges[a].face);
                    }
                }
            }
        }
        i = j;
    }
    std::sort(links.begin(), links.end());
    links.erase(std::unique(links.begin(), links.end()), links.end());
    out.neighbourStart.assign(nf + 1, 0);
    out.neighbours.reserve(links.size());
    for (const auto& [from, to] : links) {
        ++out.neighbourStart[from + 1];
        out.neighbours.push_back(to);
    }
    for (std::size_t f = 0; f < nf; ++f)
        out.neighbourStart[f + 1] += out.neighbourStart[f];
    return out;
}

}  // namespace grass::core::atlas
