// Bending cues (SPEC §10; article 003, "the bend of grass"): besides the growth model's lean, a
// blade's rest pose leans
//   - downhill on steep ground: lean = slope · φ, φ the ground's angle from level against gravity
//     (placement_rules.h), at most 90°; the blade turns its front downhill (θ + π where its
//     front faced uphill: the same width axis, and front gravity then pulls the way it leans);
//   - sideways among taller, denser neighbours, which take its light (it grows towards the
//     light, the article's second assumption): lean = neighbours · shade, towards its front;
// and a leaning blade sways more easily (the article: the further a blade grows sideways, the
// more it sways): its stiffness becomes s·(1 − sway·sin(total lean)). The total lean, the growth
// model's included, stops at 60° like the growth model's own. The article's third cue, sway
// growing with a vertex's height, is the Bézier blade itself: v0 stays, v2 moves, and a point
// at height t moves with 2t(1 − t)·Δv1 + t²·Δv2 (physics_test pins it).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "blade/blade.h"
#include "project/project.h"
#include "scatter/placement_rules.h"
#include "scatter/scatter.h"

namespace grass::core {

// Where a blade's rest lean stops (the growth model's bound, growth_curves.h).
inline constexpr float MAX_REST_LEAN_RAD = 1.0471975511965976f;  // π/3
// One neighbour's occluding cross-section (m²), as the grass AO's (blade_shading.h): 300 blades
// per m² of equal height shade a blade to 1 − e^−2.1 ≈ 0.88, 100 to 0.50, one alone to 0.
inline constexpr float NEIGHBOUR_CROSS_SECTION_M2 = 0.007f;
// A neighbour counts by its height over the blade's own, up to this: a blade among ones twice
// its height is shaded as by twice as many of its own height.
inline constexpr float MAX_NEIGHBOUR_HEIGHT_RATIO = 2.0f;

// True when `cues` change nothing (the defaults): a layer then grows exactly as without them
// (sway alone still changes the growth model's leaning blades).
bool bendingIsOff(const BendingCues& cues);

// Per candidate, how much taller, denser neighbours shade it, in [0, 1):
//   shade_i = 1 − exp(−A·ρ_i),  ρ_i = Σ_{j≠i} p_j · min(h_j / h_i, 2) · k(|v0_j − v0_i|) / (2πσ²),
// k(r) = exp(−r²/2σ²) out to 3σ, p_j the candidate's placement-rule factor (the chance it lives;
// empty: 1), A = NEIGHBOUR_CROSS_SECTION_M2. The painted density map does not enter, so a
// repaint never changes a blade it does not regrow; distances are 3D, so any mesh works.
std::vector<float> neighbourShade(const ScatterCandidates& candidates,
                                  std::span<const float> ruleFactors, float sigmaM);

// The shade neighbourShade gives, bit for bit, of the candidates whose neighbours include a
// candidate of `changed` (all within 3σ of one): after those candidates' rule factors changed
// (a collider moved), the others keep theirs. Pairs of (candidate, shade), in no order.
std::vector<std::pair<std::uint32_t, float>> neighbourShadeAround(
    const ScatterCandidates& candidates, std::span<const float> ruleFactors, float sigmaM,
    std::span<const std::uint32_t> changed);

// The unit downhill direction in the tangent plane of a surface with unit `normal` at `p`
// (gravity's pull projected onto it); zero on level ground and on overhangs' tops.
glm::vec3 downhillAt(glm::vec3 normal, glm::vec3 p, const RuleWorld& world);

// What the cues do to one candidate, from the ground it stands on and its shade.
struct CandidateBend {
    float leanRad = 0.0f;        // the cues' lean, before the growth model's is added
    glm::vec3 downhill{0.0f};    // zero: the slope cue leaves its front alone
};
CandidateBend candidateBend(const BendingCues& cues, const Blade& candidate, float shade,
                            const RuleWorld& world);
// Every candidate's bend; empty when bendingIsOff(cues).
std::vector<CandidateBend> candidateBends(const BendingCues& cues,
                                          const ScatterCandidates& candidates,
                                          std::span<const float> ruleFactors,
                                          const RuleWorld& world);

// `bends` (candidateBends of the same cues under other rule factors) made what candidateBends
// gives under `ruleFactors`, after only the candidates `changed` took other factors: the bends
// of those within reach of them are made again, the rest cannot have changed. An empty `bends`
// (bending off) stays empty.
void updateCandidateBends(const BendingCues& cues, const ScatterCandidates& candidates,
                          std::span<const float> ruleFactors, const RuleWorld& world,
                          std::span<const std::uint32_t> changed,
                          std::vector<CandidateBend>& bends);

// The rest blade of height h and width w at candidate `c`, leaned `growthLeanRad` by the
// growth model and then by `bend`: θ turned by π when its front faces uphill, the lean summed
// and capped at MAX_REST_LEAN_RAD, the stiffness lowered by `sway`.
Blade bentRestBlade(const Blade& c, float h, float w, float growthLeanRad,
                    const CandidateBend& bend, float sway);

// A rest blade leaned `leanRad` towards its front, its length kept (validation places v1).
void leanTowardsFront(Blade& blade, float leanRad);

}  // namespace grass::core
