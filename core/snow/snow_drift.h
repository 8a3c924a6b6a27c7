// Snow drifting with the wind (issue 30 item 2; SPEC §11, the paper's own future work): wind
// carries falling and fallen snow off the ground that faces it and drops it where the ground
// lies in the lee of what stands upwind. Snow-hydrology models measure that shelter with the
// maximum upwind slope Sx (Winstral, Elder & Davis 2002): the steepest angle, seen from a
// point, to the surface within a reach upwind. Positive Sx (something stands upwind: the lee
// of a rock or a ridge) gathers snow, negative Sx (the ground falls away upwind: a windward
// face, a crest) loses it.
//
// Here Sx is measured over the snow depth map (snow_map.h), so the terrain and the props both
// shelter, per cell of SNOW_DRIFT_CELL_TEXELS² texels, and the depth of the snow is scaled by
//   D = 1 + drift · clamp(Sx / SNOW_DRIFT_REFERENCE_RAD, −1, 1)  ∈ [1 − drift, 1 + drift],
// read between cell centres bilinearly so the snow surface stays smooth (a per-point Sx jumps
// wherever one of its samples crosses an obstacle's edge). The coverage Fp is scaled by min(D, 1):
// scoured ground shows through, a drift is no whiter than full snow.
// The GPU computes the same cells (shaders/snow_drift.comp) and reads them the same way
// (shaders/include/snow.glsl).
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "physics/wind.h"
#include "snow/snow_map.h"
#include "snow/snow_params.h"

namespace grass::core {

// Depth-map texels per side of a drift cell: at 1024² over projects/winter's 19 m a cell is
// 15 cm, finer than any drift and coarse enough that 16 samples a cell cost nothing.
inline constexpr int SNOW_DRIFT_CELL_TEXELS = 8;
// Upwind samples per cell, evenly spaced from reach/16 to the reach.
inline constexpr int SNOW_DRIFT_SAMPLES = 16;
// The shelter angle that doubles the snow at drift 1 (and clears it facing the wind): 20°,
// the upper end of the Sx range Winstral et al. map to the deepest drifts.
inline constexpr float SNOW_DRIFT_REFERENCE_RAD = 0.34906585f;

// The direction the snow drifts to, in world space (not normalized), or zero for none: with
// driftFollowsWind, the strength-weighted sum of the scene's directional winds' directions
// (point sources and vortices blow every way and push no drift); else params.driftDirection.
glm::vec3 snowDriftWorldDirection(const SnowParams& params, std::span<const WindSource> wind);

// `params` with the drift direction resolved: driftDirection = snowDriftWorldDirection and
// driftFollowsWind = 0, what the renderer and the physics load take.
SnowParams snowWithWindDrift(SnowParams params, std::span<const WindSource> wind);

// The drift direction across the depth map (unit, in map texels' (u, v) axes), or zero when the
// wind blows along the fall or there is none.
glm::vec2 snowDriftMapDirection(const OrthoSnowView& view, glm::vec3 worldDirection);

// Whether drift changes anything: snow on, drift > 0, reach > 0 and a direction across the map.
bool snowDrifts(const SnowParams& params, glm::vec2 mapDirection);

struct SnowDriftMap {
    int resolution = 0;         // cells per side: the depth map's / SNOW_DRIFT_CELL_TEXELS
    std::vector<float> factor;  // D per cell, row-major in v; empty: 1 everywhere
};

// The maximum upwind slope Sx (radians) at the centre of cell (cx, cy): over the samples at
// the centre − mapDirection·reach·k/SNOW_DRIFT_SAMPLES texels (k = 1..), each the surface its
// texel holds (the texel's centre at its depth, in world space), the largest atan(rise / run),
// rise along world up (+Y) and run across it from the centre's own surface. Samples without a
// surface (or off the map) are skipped; 0 when the centre has none or no sample counts.
float snowDriftShelterAngle(const SnowDepthMap& map, int cx, int cy, glm::vec2 mapDirection,
                            float reachM);

// D for every cell (the formula above). Empty when !snowDrifts.
SnowDriftMap computeSnowDriftMap(const SnowDepthMap& map, const SnowParams& params,
                                 glm::vec2 mapDirection);

// D at a world point: bilinear between the four nearest cell centres (edges clamped); 1 for an
// empty map.
float snowDriftFactorAt(const SnowDriftMap& drift, const OrthoSnowView& view, glm::vec3 posWorld);

}  // namespace grass::core
