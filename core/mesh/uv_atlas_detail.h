// The parts of the UV atlas (uv_atlas.h) its .cpp files share: the 2D triangle overlap search,
// chart growing and flattening, and packing. Not for use outside core/mesh/uv_atlas*.cpp.
// Chart coordinates are in file units on each chart's projection plane; packing maps them to UV.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <stop_token>
#include <vector>

#include "mesh/surface_mesh.h"

namespace grass::core::atlas {

using Triangle2 = std::array<glm::dvec2, 3>;

// Twice the signed area (positive when counter-clockwise).
inline double doubledArea(const Triangle2& t) {
    const glm::dvec2 e1 = t[1] - t[0], e2 = t[2] - t[0];
    return e1.x * e2.y - e1.y * e2.x;
}

struct OverlapPair {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
};

// Pairs of `triangles` whose interiors overlap by more than `epsilon` along every separating
// axis (so shared edges and vertices do not count); triangles with active[i] == 0 are left
// out. Counting stops at `cap`. When `pairs` is given, the pairs found are appended (a < b).
// A request on `stop` ends the search early: the count is then short, for a caller that checks
// the token to throw away.
std::size_t countOverlaps(const std::vector<Triangle2>& triangles, const std::vector<char>& active,
                          double epsilon, std::size_t cap, std::vector<OverlapPair>* pairs,
                          const std::stop_token& stop = {});

// The mesh as chart growing sees it: corners welded by position, face normals and areas, and
// which faces share a welded edge.
struct WeldedMesh {
    std::vector<glm::dvec3> positions;                  // per welded vertex
    std::vector<std::array<std::uint32_t, 3>> corners;  // per face, welded vertex ids
    std::vector<glm::dvec3> normals;                    // per face, unit; zero when degenerate
    std::vector<double> areas;                          // per face, in squared file units
    std::vector<std::uint32_t> neighbourStart;          // CSR offsets, faces + 1 entries
    std::vector<std::uint32_t> neighbours;
};

WeldedMesh weldMesh(const SurfaceMesh& mesh);

// One chart, flattened: its faces (mesh face ids) and their corners on the chart plane, in the
// order of each face's corners. Corners of one welded vertex are bitwise equal within a chart.
struct FlatChart {
    std::vector<std::uint32_t> faces;
    std::vector<Triangle2> corners;
    double area3d = 0.0;    // sum of the faces' 3D areas
    double areaFlat = 0.0;  // sum of the faces' projected areas
};

// Charts of every face, deterministic: see generateUvAtlas.
std::vector<FlatChart> makeCharts(const WeldedMesh& mesh, double chartAngleDeg);

// Rotates a chart to its smallest-area bounding rectangle (found among its convex hull's edge
// directions), wider than tall, with the rectangle's minimum at the origin; returns its size.
glm::dvec2 orientChart(FlatChart& chart);

// The chart as connected pieces, each oriented (orientChart); a piece filling too little of its
// rectangle (a ring, a long arc) is cut in two across its long side at the median face, again
// until every piece fills enough. Pieces keep their flattened corners: a subset of a one-to-one
// chart stays one. `faceAreas`: 3D area per mesh face.
std::vector<FlatChart> splitForPacking(FlatChart chart, const std::vector<double>& faceAreas);

struct Packing {
    double scale = 0.0;               // UV units per chart unit, the same for every chart
    std::vector<glm::dvec2> offsets;  // per chart, UV of its rectangle's minimum
    double gutterUv = 0.0;            // the gutter kept between charts, in UV
};

// Places rectangles of `sizes` (chart units) scaled by one common factor, as large as fits,
// into [0, 1]² with `gutterUv` between them and half of it at the border: tallest first, on
// shelves or a skyline, whichever fits the larger scale. When even scale 0 does not fit, the
// gutter is halved until it does.
Packing packCharts(const std::vector<glm::dvec2>& sizes, double gutterUv);

}  // namespace grass::core::atlas
