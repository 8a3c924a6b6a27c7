// Blade physics, CPU reference (SPEC §3, §5; Jahrmann §5): forces act on v2 only, then the three
// validation steps, then sphere collisions at v2 and at the curve midpoint, then validation again
// for blades that were hit. World space, metres, seconds. shaders/physics.comp runs the same steps
// in the same order with the same names; PhysicsParams is std430 and mirrored there.
//
// Integration (docs/physics.md): the step Δt is cut into n = min(ceil(Δt / maxSubstepS),
// maxSubsteps) equal substeps. In each, the linear recovery term is integrated exactly together
// with the (frozen) gravity and wind: v2 relaxes towards Iv2 + F/k by the factor exp(−k·τ), with
// k = s·max(1 − η, crushedRecoveryFloor); the displacement is then clamped to maxMovePerSubstep·h.
// Hence no NaN/Inf and no overshoot for any Δt, stiffness or wind; validation keeps the length
// estimate at h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "blade/blade.h"
#include "physics/wind.h"
#include "util/result.h"

namespace grass::core {

enum class GravityMode : std::uint32_t {
    Direction = 0,  // gE = normalize(gravity.xyz) · gravity.w
    Centre = 1,     // gE = normalize(gravity.xyz − v0) · gravity.w (a planet, a torus' core)
};

struct PhysicsParams {
    // xyz: direction (Direction mode) or centre point in world space (Centre mode); w: |gE| (m/s²
    // in the paper's units: a displacement rate per second of step).
    glm::vec4 gravity{0.0f, -1.0f, 0.0f, 9.81f};
    float dtS = 1.0f / 60.0f;
    // Collision strength decay a (1/s): η = max(η − a·τ, 0). A constant, see docs/physics.md.
    float etaDecayPerS = 0.5f;
    // Substep policy: substeps of at most maxSubstepS, but never more than maxSubsteps.
    float maxSubstepS = 1.0f / 120.0f;
    // Cap of |Δv2| from forces in one substep, as a fraction of h.
    float maxMovePerSubstep = 0.25f;
    GravityMode gravityMode = GravityMode::Direction;
    std::uint32_t maxSubsteps = 8;
    // gF = frontGravityScale · |gE| · f (the paper: 0.25).
    float frontGravityScale = 0.25f;
    // Recovery while crushed is s·max(1 − η, crushedRecoveryFloor) (the paper: 0.1). Stiff grass
    // springs back from a crush within 1/(floor·s) seconds; a lower floor keeps trails visible.
    float crushedRecoveryFloor = 0.1f;

    bool operator==(const PhysicsParams&) const = default;
};

static_assert(sizeof(PhysicsParams) == 48, "PhysicsParams must be three vec4 (std430)");
static_assert(offsetof(PhysicsParams, dtS) == 16 && offsetof(PhysicsParams, gravityMode) == 32 &&
                  offsetof(PhysicsParams, frontGravityScale) == 40 &&
                  offsetof(PhysicsParams, crushedRecoveryFloor) == 44,
              "PhysicsParams offsets must match shaders/physics.comp");

// A sphere collider (SPEC §5); `path`, when non-empty, moves the centre over time.
struct SphereCollider {
    glm::vec3 centre{0.0f};
    float radiusM = 0.0f;
    std::vector<PathKey> path;
    // Broad phase for the spheres of a packed mesh, which move together: when groupSize > 1,
    // this sphere and the next groupSize − 1 lie inside the bounding sphere centred at this
    // sphere's (moving) centre + boundOffset with radius boundRadiusM, so one distance test
    // skips them all for a blade out of reach. Bit-identical results either way.
    std::uint32_t groupSize = 1;
    glm::vec3 boundOffset{0.0f};
    float boundRadiusM = 0.0f;
    bool operator==(const SphereCollider&) const = default;
};

// η is capped so that d·d accumulated over many hits stays finite; a trail lasts at most
// ETA_MAX / a seconds.
constexpr float ETA_MAX = 1.0e4f;
// Lowers every η of `eta` above `etaMax` to it; returns how many it lowered (the editor letting
// go of the blades a moved collider held: editor::LivePhysics::releaseHeldBlades).
std::size_t capEta(std::span<float> eta, float etaMax);

// The number of substeps and their length for one step of dtS (≥ 1 substep; 0 for dtS ≤ 0).
std::uint32_t substepCount(const PhysicsParams& params);

// Rest tip Iv2 = v0 + h·up (up normalised; v0 for a degenerate blade).
glm::vec3 restTip(const Blade& blade);
std::vector<glm::vec3> restTips(std::span<const Blade> blades);
// The rest tips of a field as grown (scene/layer_growth.h): its blades stand at rest, upright or
// leaned by the growth model, so each tip v2 is where recovery pulls it back to. Equal to
// restTips for upright blades.
std::vector<glm::vec3> restTipsAsGrown(std::span<const Blade> blades);

// Degenerate input, checked at load: a message naming the first problem of each blade (empty
// when the blade is valid). `checkBlades` reports the first bad blade as "blade N: problem".
std::string checkBlade(const Blade& blade);
Result<void> checkBlades(std::span<const Blade> blades, const std::string& source);

// The documented repair rule, applied by every step so that no input produces NaN/Inf:
// non-finite v0 → origin with h = 0; up not finite or |up| < 1e-6 → (0, 1, 0), else normalised;
// h not finite or < 0 → 0; s not finite or < 0 → 0; v2 not finite → rest tip; then validation.
Blade repairBlade(Blade blade);

// Validation 1–3 of SPEC §3 (ground plane, place v1, length correction), with 2–3 repeated four
// times so the result is a fixed point (docs/physics.md); h = 0 collapses the blade onto v0.
// Precondition: up is unit length (repairBlade).
void validateBlade(Blade& blade);

// Extra gravity per blade (the load snow puts on it, SPEC §11): blade i's |gE| grows by
// scale·perBlade[i] m/s² along the gravity direction. Empty perBlade or scale 0: none.
struct GravityLoad {
    std::span<const float> perBlade;
    float scale = 0.0f;
    float at(std::size_t i) const { return perBlade.empty() ? 0.0f : scale * perBlade[i]; }
};

// One step of dtS for one blade from timeS (the function stepPhysics applies to every blade).
// extraGravity: m/s² added to |gE| (GravityLoad::at); non-finite or negative counts as 0.
void stepBlade(Blade& blade, float& eta, glm::vec3 restTip, const PhysicsParams& params,
               const std::vector<WindSource>& wind, const std::vector<SphereCollider>& colliders,
               float timeS, float extraGravity = 0.0f);

// One step for all blades, split into contiguous ranges over threadCount threads (0: hardware
// concurrency, at most 8). Results do not depend on the thread count. eta and restTips are
// parallel to blades.
void stepPhysics(std::span<Blade> blades, std::span<float> eta, std::span<const glm::vec3> restTips,
                 const PhysicsParams& params, const std::vector<WindSource>& wind,
                 const std::vector<SphereCollider>& colliders, float timeS,
                 unsigned threadCount = 0, GravityLoad load = {});

}  // namespace grass::core
