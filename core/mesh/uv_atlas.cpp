#include "mesh/uv_atlas.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "mesh/uv_atlas_detail.h"
#include "util/assert.h"

namespace grass::core {

namespace {

// Charts under this share of the surface are left out of the texel density ratio: a sliver
// chart of a few faces at a crease says nothing about the distortion anyone would see.
constexpr double DENSITY_CHART_SHARE_MIN = 0.01;

double densityRatio(const std::vector<atlas::FlatChart>& charts) {
    double total = 0.0;
    for (const atlas::FlatChart& c : charts)
        total += c.area3d;
    double lo = INFINITY, hi = 0.0;
    for (const atlas::FlatChart& c : charts) {
        if (c.area3d > 0.0 && c.area3d >= DENSITY_CHART_SHARE_MIN * total) {
            const double density = c.areaFlat / c.area3d;
            lo = std::min(lo, density);
            hi = std::max(hi, density);
        }
    }
    return lo > 0.0 && hi >= lo && std::isfinite(lo) ? hi / lo : 1.0;
}

}  // namespace

CornerUvs generateUvAtlas(const SurfaceMesh& mesh, const AtlasParams& params, AtlasStats* stats) {
    GRASS_ASSERT(params.chartAngleDeg > 0.0f && params.resolution > 0 && params.gutterTexels >= 0);
    CornerUvs uvs(mesh.n_faces(), {glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f)});
    if (stats)
        *stats = AtlasStats{};
    if (mesh.n_faces() == 0)
        return uvs;

    const atlas::WeldedMesh welded = atlas::weldMesh(mesh);
    std::vector<atlas::FlatChart> charts;
    for (atlas::FlatChart& chart :
         atlas::makeCharts(welded, static_cast<double>(params.chartAngleDeg))) {
        for (atlas::FlatChart& piece : atlas::splitForPacking(std::move(chart), welded.areas))
            charts.push_back(std::move(piece));
    }
    // Oriented charts start at the origin: their size is their largest corner.
    std::vector<glm::dvec2> sizes(charts.size(), glm::dvec2(0.0));
    for (std::size_t c = 0; c < charts.size(); ++c) {
        for (const atlas::Triangle2& t : charts[c].corners)
            sizes[c] = glm::max(sizes[c], glm::max(glm::max(t[0], t[1]), t[2]));
    }
    const double gutterUv =
        static_cast<double>(params.gutterTexels) / static_cast<double>(params.resolution);
    const atlas::Packing packing = atlas::packCharts(sizes, gutterUv);

    double covered = 0.0;
    for (std::size_t c = 0; c < charts.size(); ++c) {
        const atlas::FlatChart& chart = charts[c];
        for (std::size_t i = 0; i < chart.faces.size(); ++i) {
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::dvec2 uv = packing.offsets[c] + packing.scale * chart.corners[i][k];
                uvs[chart.faces[i]][k] = glm::vec2(uv);
            }
        }
        covered += chart.areaFlat * packing.scale * packing.scale;
    }
    if (stats) {
        stats->charts = charts.size();
        stats->texelDensityRatio = densityRatio(charts);
        stats->gutterTexels = packing.gutterUv * static_cast<double>(params.resolution);
        stats->uvCoverage = covered;
    }
    return uvs;
}

MovableSurfaceMesh withCornerUvs(const SurfaceMesh& mesh, const CornerUvs& uvs) {
    GRASS_ASSERT(uvs.size() == mesh.n_faces());
    constexpr std::uint32_t NONE = UINT32_MAX;
    SurfaceMeshBuilder builder;
    // Copies of each source vertex as a linked list: firstCopy[source] -> nextCopy[copy] ...;
    // most vertices have one or two UVs, so a walk is shorter than any hash lookup.
    std::vector<std::uint32_t> firstCopy(mesh.n_vertices(), NONE);
    std::vector<std::uint32_t> nextCopy;
    std::vector<glm::vec2> copyUv;
    std::vector<std::uint32_t> copyIndex;  // the builder's vertex index of each copy
    for (const auto fh : mesh.faces()) {
        const auto& corner = uvs[static_cast<std::size_t>(fh.idx())];
        std::array<std::uint32_t, 3> index{};
        std::size_t k = 0;
        for (const auto vh : mesh.fv_range(fh)) {
            const glm::vec2 uv = corner[k];
            const auto source = static_cast<std::size_t>(vh.idx());
            std::uint32_t copy = firstCopy[source];
            while (copy != NONE && copyUv[copy] != uv)
                copy = nextCopy[copy];
            if (copy == NONE) {
                copy = static_cast<std::uint32_t>(copyUv.size());
                copyUv.push_back(uv);
                nextCopy.push_back(firstCopy[source]);
                firstCopy[source] = copy;
                copyIndex.push_back(
                    builder.addVertex(toGlm(mesh.point(vh)), toGlm(mesh.normal(vh)), uv));
            }
            index[k++] = copyIndex[copy];
        }
        builder.addTriangle(index[0], index[1], index[2]);
    }
    MovableSurfaceMesh out = builder.take();
    // The builder gives a refused face its own vertices rather than dropping it, and source
    // faces never repeat a vertex, so every face arrives, in order.
    GRASS_ASSERT(out->n_faces() == mesh.n_faces());
    return out;
}

}  // namespace grass::core
