// Snow over a whole scene (SPEC §11, issue 9): the orthographic view along the snowfall that
// covers the terrain and the props where they stand, the CPU depth map of that view, and the
// snow load each blade carries into the physics. The renderer's depth pass uses the same view,
// so the CPU and GPU maps cover the same ground texel for texel.
#pragma once

#include <span>
#include <vector>

#include "physics/physics.h"
#include "scene/scene.h"
#include "snow/snow.h"
#include "snow/snow_drift.h"

namespace grass::core {

// The view along params.fallDirection over the scene's bounds and every prop at timeS, with a
// 2 % margin so the map's edge never shelters the scene's edge.
OrthoSnowView sceneSnowView(const Scene& scene, const SnowParams& params, float timeS);
// core::renderSnowDepthMap of the terrain and the props at timeS over sceneSnowView.
SnowDepthMap sceneSnowDepthMap(const Scene& scene, const SnowParams& params, float timeS);

// Snow load per blade per metre of As: snowLoadGravity at As = 1 m, that is
// loadGravity·Fe_boundary(root)·Zn(root)·Fe(tip), the tip where the blade stands now (at
// rest, when a simulation starts). The load at time t is
// snowAmountAt(params, t) times this (GravityLoad::scale), so accumulation and melt need no
// new exposures. Exposures come from `map` as the scene stood when it was taken: a prop that
// moves later does not move the load (the load changes slowly next to the wind; the shading and
// burial follow the prop every frame). Empty when snow is off or loadGravity is 0.
std::vector<float> snowLoadPerMetre(std::span<const Blade> blades, const SnowDepthMap& map,
                                    const SnowParams& params);

// snowLoadPerMetre blade by blade, keeping its map (and the drift map made from it): the
// editor weighs the blades a brush re-grows with the map the field was weighed with, instead of
// rendering the snow map again (~0.5 s for projects/winter's 1024² map on 2 cores).
class SnowWeigher {
public:
    SnowWeigher(SnowDepthMap map, const SnowParams& params);
    // The load per metre of snow on `blade` (0 for an empty slot, or when the snow loads
    // nothing).
    float loadPerMetre(const Blade& blade) const;
    // Each blade's (snowLoadPerMetre: empty when the snow loads nothing).
    std::vector<float> loadsPerMetre(std::span<const Blade> blades) const;

private:
    SnowDepthMap mMap;
    SnowDriftMap mDrift;
    SnowParams mParams;
    SnowParams mPerMetre;  // mParams at 1 m of snow
    bool mLoads = false;
};

// True when snow puts a load on blades at all (on, load gravity > 0, some amount at some time).
bool snowLoadsBlades(const SnowParams& params);

}  // namespace grass::core
