// UV atlas: a non-overlapping UV0 parameterisation for meshes whose UVs are missing or overlap.
// Grass maps (density, soil, light) are painted in UV0 space, so two surfaces sharing texels
// would be painted together (a planar projection puts a floating sphere on the ground under
// it). Debian has no atlas library; this is our own, kept simple: charts grown over welded
// connectivity by a normal cone, each flattened orthographically onto its mean plane (faces that
// would fold leave it for other charts), packed into [0, 1]² at one common texel density with
// gutters.
// UVs are unitless in [0, 1]²; 3D areas are in squared file units.
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <stop_token>
#include <vector>

#include "mesh/surface_mesh.h"

namespace grass::core {

// Per face, the UVs of its three corners in the order mesh.fv_range(face) gives the vertices.
using CornerUvs = std::vector<std::array<glm::vec2, 3>>;

// The mesh's current UV0 per corner.
CornerUvs cornerUvsOf(const SurfaceMesh& mesh);

struct UvOverlapReport {
    // Pairs of faces whose UV triangles' interiors overlap (shared edges/vertices do not
    // count); counting stops at UV_OVERLAP_CAP.
    std::size_t overlappingPairs = 0;
    // Faces with (near) zero UV area while their 3D area is not zero: a face whose share of the
    // UV area is under 1/1000 of its share of the 3D area (it would get no texels to paint).
    std::size_t degenerateFaces = 0;
    // Faces with a corner outside [0, 1]² (tiling UVs), beyond 1e-6 of float rounding.
    std::size_t outsideUnitSquare = 0;
    bool paintable() const {
        return overlappingPairs == 0 && degenerateFaces == 0 && outsideUnitSquare == 0;
    }
    bool operator==(const UvOverlapReport&) const = default;
};

// Overlap counting stops here so a badly overlapping mesh (every face on one spot) stays
// bounded in time.
constexpr std::size_t UV_OVERLAP_CAP = 1'000'000;

// Broad phase: a uniform grid over the UVs' bounds, each triangle entered in the cells it
// covers; narrow phase: separating axes on the 2D edges, where an overlap must exceed 1e-6 of the
// UV extent (at least 1e-6) along every axis, so triangles that only touch do not count. Faces with
// (near) zero UV area have no interior and are left out of the pairs. `uvs` has one entry per face
// of `mesh`.
// A request on `stop` ends the search early with a report that is not to be trusted (the caller
// checks the token): a large mesh's search takes a second or two.
UvOverlapReport findUvOverlaps(const CornerUvs& uvs, const SurfaceMesh& mesh,
                               const std::stop_token& stop = {});

struct AtlasParams {
    float chartAngleDeg = 60.0f;  // a face joins a neighbour's chart while its normal is within
                                  // this of the chart's mean normal
    int resolution = 1024;        // the map resolution the packing keeps gutters for
    int gutterTexels = 2;         // empty texels between charts (bilinear sampling must not bleed)
    bool operator==(const AtlasParams&) const = default;
};

struct AtlasStats {
    std::size_t charts = 0;  // as packed: connected, and cut where they filled their box poorly
    // Texel density (UV area / 3D area) of the charts: max over min, among charts holding at
    // least 1% of the surface; 1 is perfectly even. Packing scales all charts by one factor, so
    // this only measures the flattening's distortion per chart.
    double texelDensityRatio = 1.0;
    // The gutter the packing kept, in texels: gutterTexels unless the charts were too many to
    // fit with it at `resolution` (then halved until they fit).
    double gutterTexels = 0.0;
    // UV area covered by triangles, in [0, 1]: how much of the map is paintable.
    double uvCoverage = 0.0;
    bool operator==(const AtlasStats&) const = default;
};

// Deterministic. Charts: region growing over welded connectivity (positions equal to 1e-6 of the
// bounds) by normal cone, grown once around the running mean normal and again around the mean
// it settled on, fixed; each chart is projected orthographically onto the plane of that normal,
// so every face keeps between cos(chartAngleDeg) and all of its area. Faces that keep the
// projection from being one-to-one (overlapping another face of the chart, or past 85° from
// the normal) leave the chart for later ones; a face alone always projects one-to-one.
// Packing: charts split into connected pieces, pieces filling under 35% of their smallest
// bounding rectangle (rings, long arcs) cut in two, rotated to that rectangle; one common scale
// (equal texel density), as large as fits (binary search), placed on shelves or on a skyline
// by decreasing height, whichever fits the larger scale, with gutters between charts and half
// a gutter at the border. Face order and count unchanged. Measured on 500k faces (one core,
// -O2): 1.2 s (sphere) to 2.3 s (torus).
CornerUvs generateUvAtlas(const SurfaceMesh& mesh, const AtlasParams& params,
                          AtlasStats* stats = nullptr);

// A copy of `mesh` whose UV0 is `uvs`: a vertex used by corners with different UVs is split into
// copies (position and normal kept); face i of the result is face i of `mesh`, which other
// per-face data relies on. Vertices no face uses are left out.
MovableSurfaceMesh withCornerUvs(const SurfaceMesh& mesh, const CornerUvs& uvs);

}  // namespace grass::core
