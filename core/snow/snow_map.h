// The snow depth map and the exposure coefficient Fe (SPEC §11, paper 004 §3.1, §3.4, eq. 1).
// Snow reaches what the sky sees along the fall direction: an orthographic depth map rendered from
// that direction holds, per texel, the surface nearest the sky; a point is exposed where the map
// holds no surface in front of it. Jittered (stochastic) samples around the point turn the
// aliased stair-step at a shelter edge into a fractional Fe (paper §3.4).
//
// Spaces: world (metres, +Y up); map space = (u, v) ∈ [0, 1]² across the map and depth in metres
// along the fall direction from the map's near plane (larger = further from the sky). Texel
// (ix, iy) covers u ∈ [ix, ix + 1)/resolution, v likewise; its depth is stored at depthM[iy·res +
// ix] and was rasterised at its centre. The GPU map stores the same metres (R32F) or depth/
// depthRangeM in a normalised depth buffer.
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/surface_mesh.h"

namespace grass::core {

// Stored where no surface covers a texel: the sky reaches all the way down.
inline constexpr float SNOW_MAP_EMPTY = 3.0e38f;

// The light-space basis of the snowfall: right and up span the map, forward = normalized fall
// direction; origin is the map's (u, v, depth) = (0, 0, 0) corner.
struct OrthoSnowView {
    glm::vec3 origin{0.0f};
    glm::vec3 right{1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 0.0f, 1.0f};
    glm::vec3 forward{0.0f, -1.0f, 0.0f};
    float sizeM = 1.0f;        // side of the square map in metres
    float depthRangeM = 1.0f;  // near plane to far plane
    bool operator==(const OrthoSnowView&) const = default;
};

// A view looking along `fallDirection` (non-zero; normalized here) whose square map and depth
// range cover `bounds` plus `marginM` on every side (room for the jittered samples at the edge).
// The basis is deterministic: right is world X (or Z when falling nearly along X) made
// orthogonal to forward; up = cross(forward, right). Falling straight down: u = x, v = z.
OrthoSnowView makeOrthoSnowView(glm::vec3 fallDirection, const Bounds& bounds, float marginM);

// The texel index holding map coordinate t (in texels): floor(t), t clamped to
// ±SNOW_MAX_TEXEL_COORD first (snow.glsl: snowTexelIndex).
inline constexpr float SNOW_MAX_TEXEL_COORD = 1048576.0f;
int snowTexelIndex(float t);

// World → (u, v, depthM) and back; exact inverses up to rounding.
glm::vec3 snowMapCoords(const OrthoSnowView& view, glm::vec3 posWorld);
glm::vec3 snowMapToWorld(const OrthoSnowView& view, glm::vec3 mapCoords);

struct SnowDepthMap {
    OrthoSnowView view;
    int resolution = 0;
    std::vector<float> depthM;  // resolution² texels, row-major in v
    float texelSizeM() const { return view.sizeM / static_cast<float>(resolution); }
    // SNOW_MAP_EMPTY outside the map: nothing there shelters anything.
    float at(int ix, int iy) const;
};

// CPU reference rasteriser: for every texel, the minimum depth of the triangles covering its
// centre (edges inclusive, so shared edges leave no cracks); SNOW_MAP_EMPTY where none does.
// Triangles seen edge-on (no area in the map) are skipped: a zero-thickness wall shelters nothing.
SnowDepthMap renderSnowDepthMap(std::span<const std::array<glm::vec3, 3>> triangles,
                                const OrthoSnowView& view, int resolution);
std::vector<std::array<glm::vec3, 3>> snowTriangles(const SurfaceMesh& mesh);

// Paper eq. 1: the fraction of `samples` jittered depth-map samples around posWorld whose stored
// depth is not in front of the point: stored ≥ depth(point) − bias. Sample k (0 ≤ k < samples) is
// stratified in a disc of radiusTexels: it lies in the k-th of `samples` equal-area rings,
// r = radiusTexels·√((k + ξ₁)/samples), at the angle 2π·ρ + k·GOLDEN_ANGLE + (ξ₂ − ½)·2π/samples.
// ρ comes from pcg3d(ix, iy, 0) and ξ₁, ξ₂ from pcg3d(ix, iy, k + 1) (.x, .y through
// hashToUnit), (ix, iy) = the texel holding the point: deterministic, identical on the GPU.
// Each sample's texel is floor(position in texels); outside the map it counts as exposed.
// bias = biasM + (r + SNOW_HALF_TEXEL_DIAGONAL)·texelSizeM·min(tan φ, SNOW_MAX_SLOPE_BIAS), φ
// between `normal` and −forward: a sloped surface's own depth changes across the disc (r) and
// within the sampled texel (its depth holds at the centre only), and must not shadow itself.
// Returns a value in [0, 1]; 1 for radiusTexels = 0 on an exposed point.
float exposureCoefficient(const SnowDepthMap& map, glm::vec3 posWorld, glm::vec3 normal,
                          int samples, float radiusTexels, float biasM);

inline constexpr float SNOW_GOLDEN_ANGLE = 2.39996323f;  // π(3 − √5): spreads ring angles evenly
inline constexpr float SNOW_MAX_SLOPE_BIAS = 4.0f;       // tan 76°: steeper faces hardly hold snow
inline constexpr float SNOW_HALF_TEXEL_DIAGONAL = 0.70710678f;  // √2 / 2, in texels

}  // namespace grass::core
