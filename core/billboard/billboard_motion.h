// How a star billboard's vertices move (SPEC §8, GPU Gems 1 ch. 7, listing 7-1), with the scene's
// own wind sources (SPEC §4) added to the book's sine sway, so a far field of billboards moves
// with the helicopter and the tornado as the blades in front of it do. The CPU side of
// shaders/include/billboard_wind.glsl: the per-cluster mode computes its cluster's values here,
// and tests hold the shader to these functions. World space, metres, seconds.
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "billboard/star_billboards.h"
#include "physics/wind.h"

namespace grass::core {

// How the scene's wind bends a tuft of height h: as it bends a blade of stiffness s rooted at
// the same spot. A blade's tip settles where recovery balances the wind force, Δ = w⊥/s
// (physics.cpp's step at equilibrium, with fd = fr = 1 for wind across an upright blade); w⊥ is
// the wind across `up`. The tuft's top moves by Δ while that is small, and never by h or more:
// |offset| = h·x/(1 + x), x = |Δ|/h; it sinks to keep its length h, as the blades' length
// correction keeps theirs (SPEC §3): bend = offset − up·(h − √(h² − |offset|²)). Zero without
// wind, height or stiffness.
glm::vec3 billboardWindBend(glm::vec3 wind, glm::vec3 up, float heightM, float stiffness);

// The scene's wind as billboards feel it, and what resists it.
struct BillboardSceneWind {
    std::span<const WindSource> sources;
    float stiffness = 0.0f;  // the near field's mean blade stiffness s (scene/billboard_follow.h)
};

// Where an upper vertex's animation is computed in each mode (BillboardWindMode): the cluster's
// centre (per cluster), the vertex's rest position (per vertex), the object's centre (per object).
glm::vec3 billboardPhasePoint(const StarVertex& vertex, BillboardWindMode mode,
                              glm::vec3 clusterCentre);

// The translation of an upper vertex: GPU Gems' sway (billboardWindOffset) at the phase point
// plus the scene wind's bend (windAt at the phase point and time, billboardWindBend with the
// vertex's object height and normal). The per-cluster mode hands the shader the sway and the
// wind at its cluster's centre; the bend is the vertex shader's in every mode.
glm::vec3 billboardTranslation(const StarVertex& vertex, glm::vec3 phasePoint, float timeS,
                               const BillboardWind& sway, glm::vec3 sceneWindAtPhasePoint,
                               float stiffness);

struct StarVertexMotion {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
};

// Listing 7-1 of the chapter: the upper vertices (sway 1) move by `translation` and their normal
// turns with them, normalize(N·h + translation), h the object's height; the roots keep both.
StarVertexMotion animateStarVertex(const StarVertex& vertex, glm::vec3 translation);

// Everything above for one vertex in `mode`: what shaders/billboard.vert computes.
StarVertexMotion billboardVertexMotion(const StarVertex& vertex, BillboardWindMode mode,
                                       glm::vec3 clusterCentre, float timeS,
                                       const BillboardWind& sway,
                                       const BillboardSceneWind& scene);

}  // namespace grass::core
