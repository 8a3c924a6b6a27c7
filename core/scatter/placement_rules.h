// A layer's placement rules (project.h PlacementRules, issue 27) turned into one factor per
// candidate blade: the product of the part rule (include/exclude by name: 0 or 1), the slope and
// altitude windows (1 inside, falling linearly to 0 over their soft widths) and the clearance
// rule (0 near a collider or a chosen part, or under a collider's surface). keepsCandidate
// multiplies the density map by it.
#pragma once

#include <vector>

#include "mesh/surface_mesh.h"
#include "physics/physics.h"
#include "project/project.h"
#include "scatter/clearance_grid.h"
#include "scatter/scatter.h"

namespace grass::core {

// What the rules measure against besides the surface.
struct RuleWorld {
    // "Up" and altitude follow gravity: its direction, or for GravityMode::Centre the way from
    // gravity.xyz (the centre) to the point.
    glm::vec4 gravity{0.0f, -1.0f, 0.0f, 9.81f};
    GravityMode gravityMode = GravityMode::Direction;
    // The colliders' surfaces at time 0, in scene units.
    std::vector<ClearanceGrid::Triangle> colliderTriangles;
    // Where each collider's triangles end in colliderTriangles, so that the clearance rule can
    // tell a root under a collider's surface (collider_interior.h); empty: no collider told
    // apart, only the distance to the surfaces counts.
    std::vector<std::size_t> colliderEnds;
};

// True when `rules` leave every candidate whole (the defaults): no factors are needed.
bool rulesAreOpen(const PlacementRules& rules);

// The factor of every candidate (candidates.faces gives its face). Empty when rulesAreOpen.
std::vector<float> placementFactors(const SurfaceMesh& mesh, const ScatterCandidates& candidates,
                                    const PlacementRules& rules, const RuleWorld& world);

// "Up" at `p` as the rules measure it: against gravity's direction, or away from its centre.
glm::vec3 upAt(glm::vec3 p, const RuleWorld& world);

// The slope in degrees (0 level, 90 a wall, 180 a ceiling) of a surface with normal `normal` at
// `p`, and the altitude of `p`, as the rules measure them.
float slopeDeg(glm::vec3 normal, glm::vec3 p, const RuleWorld& world);
float altitudeM(glm::vec3 p, const RuleWorld& world);

// 1 inside [min, max], falling linearly to 0 over `soft` outside it (0: a hard edge).
float windowFactor(float value, float min, float max, float soft);

}  // namespace grass::core
