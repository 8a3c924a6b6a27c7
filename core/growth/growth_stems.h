// Kim & Cho growth geometry (SPEC §9): a set of 6 stems, each grown over 1–4 levels from the
// growth parameters α (width), β (height) and θ (bend). Level i of a stem sits at
//   x_i = s_x·α/2 + spreadX_k,
//   y_i = (y_{i−1} + β^i)·cos θ − z_{i−1}·sin θ,
//   z_i = (y_{i−1} + β^i)·sin θ + z_{i−1}·cos θ + spreadZ_k,
// starting from the root (0, 0, 0); the root and the level points are the control points of a
// clamped uniform B-spline of degree min(3, points − 1) (1 level: a line, 2 levels: a quadratic),
// sampled at even parameter steps. Units: the set's own frame, y up, β = 1 is one unit per level.
// A stem is a ribbon: STEM_SAMPLES_PER_LEVEL samples per level, two vertices per sample, so a
// level-4 stem has 40 vertices and a set of 6 stems 240 (the paper's counts).
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace grass::core {

inline constexpr int STEMS_PER_SET = 6;
inline constexpr int MAX_STEM_LEVELS = 4;
inline constexpr int STEM_SAMPLES_PER_LEVEL = 5;

struct StemSetParams {
    float alpha = 0.1f;  // width, [0, 0.25]
    float beta = 0.7f;   // height per level, [0, 1]
    float theta = 0.0f;  // bend, radians
    int levels = 4;      // 1..4 (clamped)
    float spreadX = 0.05f;
    float spreadZ = 0.05f;
};

// Root + one point per level, for stem k of the set (0..5): the sign of the α/2 term and the
// spreads alternate between stems so the six fan out around the set's centre.
std::vector<glm::vec3> stemLevelPoints(const StemSetParams& params, int stem);

// De Boor evaluation of the clamped uniform B-spline of degree min(3, n − 1) through the control
// points (endpoints interpolated), at u in [0, 1]. One point: that point.
glm::vec3 clampedBSpline(const std::vector<glm::vec3>& controls, float u);

// The ribbon of one stem: 2 · STEM_SAMPLES_PER_LEVEL · levels vertices, pairs (left, right) of
// half-width halfWidth·(1 − (1 − tipWidth)·u) across x at each sample u from root (0) to tip
// (1): tipWidth 0 narrows it to a point, as a grass stem does; 1 is the paper's constant-width
// quad (Kim & Cho draw each stem as a strip of width α).
std::vector<glm::vec3> stemRibbon(const StemSetParams& params, int stem, float halfWidth,
                                  float tipWidth = 0.0f);

// All six ribbons, stem after stem (240 vertices at 4 levels).
std::vector<glm::vec3> stemSetVertices(const StemSetParams& params, float halfWidth,
                                       float tipWidth = 0.0f);

// One stem set placed on the surface, the per-instance data of Kim & Cho's instanced technique
// (`--technique growth`): four vec4, 64 bytes, std430. The set's model frame (y up, x across, z
// the bend direction) is rotated by `yaw` about `up` and scaled by `metresPerUnit`; levels come
// from the draw (1..4), the rest from here.
struct StemSetInstance {
    glm::vec4 rootMetresPerUnit{0.0f, 0.0f, 0.0f, 1.0f};  // root position (world, m), scale
    glm::vec4 upYaw{0.0f, 1.0f, 0.0f, 0.0f};               // unit surface normal, yaw (radians)
    glm::vec4 alphaBetaThetaB{0.1f, 0.7f, 0.0f, 1.0f};     // growth parameters (SPEC §9)
    // Ribbon half width, spreadX, spreadZ, the ribbon's width at the tip as a share of its root
    // width (stemRibbon's tipWidth).
    glm::vec4 halfWidthSpread{0.02f, 0.05f, 0.05f, 0.0f};
};
static_assert(sizeof(StemSetInstance) == 64, "StemSetInstance must be four vec4 (std430)");

}  // namespace grass::core
