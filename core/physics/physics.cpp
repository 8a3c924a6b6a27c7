#include "physics/physics.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "util/assert.h"

namespace grass::core {
namespace {

// Below this many blades per thread, starting a thread costs more than it saves.
constexpr std::size_t MIN_BLADES_PER_THREAD = 1024;
constexpr unsigned MAX_THREADS = 8;
// Directions shorter than this are treated as undefined (zero).
constexpr float TINY_LENGTH = 1e-20f;
// The paper runs validation 2–3 once. That pass is not idempotent (v1 is re-placed from the
// rescaled v2 on the next pass), so every substep drifts the blade by a fixed amount and the
// steady state depended on Δt (tip height 0.929 at Δt = 1/60 s, 0.661 at 10 s for h = 1, s = 20).
// Four passes converge to the fixed point: 0.9443 and 0.9439 (docs/physics.md).
constexpr int VALIDATION_ITERATIONS = 4;

bool isFinite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// up as stored when already unit length (so rest blades stay bit-identical), else normalised;
// +y when it has no direction.
glm::vec3 unitUp(glm::vec3 up) {
    const float len2 = glm::dot(up, up);
    if (!std::isfinite(len2) || len2 < 1e-12f)
        return glm::vec3(0.0f, 1.0f, 0.0f);
    return std::abs(len2 - 1.0f) <= 1e-5f ? up : up / std::sqrt(len2);
}

glm::vec3 safeNormalize(glm::vec3 v) {
    const float len = glm::length(v);
    return (len > TINY_LENGTH && std::isfinite(len)) ? v / len : glm::vec3(0.0f);
}

void setPoints(Blade& blade, glm::vec3 v1, glm::vec3 v2) {
    blade.v1H = glm::vec4(v1, blade.h());
    blade.v2W = glm::vec4(v2, blade.w());
}

// Sphere collision at point p (SPEC §3): the correction d = min(|c − p| − ρ, 0)·normalize(c − p),
// pushing p onto the sphere surface. A point exactly at the centre is pushed along up.
glm::vec3 sphereCorrection(glm::vec3 p, glm::vec3 c, float radiusM, glm::vec3 up) {
    const glm::vec3 toCentre = c - p;
    const float dist = glm::length(toCentre);
    if (!(dist < radiusM))
        return glm::vec3(0.0f);
    const glm::vec3 n = dist > TINY_LENGTH ? toCentre / dist : -up;
    return (dist - radiusM) * n;
}

// Collisions with every sphere at time timeS; true when the blade was hit.
bool collide(Blade& blade, float& eta, const std::vector<SphereCollider>& colliders, float timeS) {
    const glm::vec3 v0 = blade.v0(), up = blade.up();
    const float h = blade.h();
    bool hit = false;
    for (std::size_t index = 0; index < colliders.size(); ++index) {
        const SphereCollider& sphere = colliders[index];
        if (sphere.groupSize > 1) {
            const glm::vec3 bound =
                samplePath(sphere.path, timeS, sphere.centre) + sphere.boundOffset;
            const float boundReach = sphere.boundRadiusM + 1.01f * h;
            const glm::vec3 toBound = bound - v0;
            // NaN bounds fail the comparison and fall through to the exact tests.
            if (glm::dot(toBound, toBound) > boundReach * boundReach) {
                index += sphere.groupSize - 1;
                continue;
            }
        }
        const float radiusM = sphere.radiusM;
        if (!(radiusM > 0.0f))
            continue;
        const glm::vec3 c = samplePath(sphere.path, timeS, sphere.centre);
        if (!isFinite(c))
            continue;
        // v2 and m lie within the blade length of v0 (chord ≤ length estimate = h).
        const float reach = radiusM + 1.01f * h;
        const glm::vec3 rel = c - v0;
        if (glm::dot(rel, rel) > reach * reach)
            continue;
        glm::vec3 v2 = blade.v2();
        const glm::vec3 dTip = sphereCorrection(v2, c, radiusM, up);
        v2 += dTip;
        const glm::vec3 m = 0.25f * v0 + 0.5f * blade.v1() + 0.25f * v2;
        const glm::vec3 dMid = sphereCorrection(m, c, radiusM, up);
        // m moves a quarter as much as v2, so the tip moves by 4d.
        v2 += 4.0f * dMid;
        const float eta2 = glm::dot(dTip, dTip) + glm::dot(dMid, dMid);
        if (eta2 > 0.0f) {
            eta = std::min(eta + eta2, ETA_MAX);
            blade.v2W = glm::vec4(v2, blade.w());
            hit = true;
        }
    }
    return hit;
}

void stepRange(std::span<Blade> blades, std::span<float> eta, std::span<const glm::vec3> restTips,
               const PhysicsParams& params, const std::vector<WindSource>& wind,
               const std::vector<SphereCollider>& colliders, float timeS, GravityLoad load) {
    for (std::size_t i = 0; i < blades.size(); ++i)
        stepBlade(blades[i], eta[i], restTips[i], params, wind, colliders, timeS, load.at(i));
}

GravityLoad subLoad(GravityLoad load, std::size_t begin, std::size_t count) {
    if (!load.perBlade.empty())
        load.perBlade = load.perBlade.subspan(begin, count);
    return load;
}

}  // namespace

std::uint32_t substepCount(const PhysicsParams& params) {
    if (!(params.dtS > 0.0f) || !std::isfinite(params.dtS))
        return 0;
    const std::uint32_t cap = std::max(params.maxSubsteps, 1u);
    if (!(params.maxSubstepS > 0.0f))
        return cap;
    const float wanted = std::ceil(params.dtS / params.maxSubstepS);
    return wanted >= static_cast<float>(cap) ? cap
                                             : std::max(static_cast<std::uint32_t>(wanted), 1u);
}

std::size_t capEta(std::span<float> eta, float etaMax) {
    std::size_t lowered = 0;
    for (float& value : eta)
        if (value > etaMax) {
            value = etaMax;
            ++lowered;
        }
    return lowered;
}

glm::vec3 restTip(const Blade& blade) {
    const glm::vec3 up = unitUp(blade.up());
    const float h = std::isfinite(blade.h()) ? std::max(blade.h(), 0.0f) : 0.0f;
    return blade.v0() + h * up;
}

std::vector<glm::vec3> restTipsAsGrown(std::span<const Blade> blades) {
    std::vector<glm::vec3> tips;
    tips.reserve(blades.size());
    for (const Blade& b : blades)
        tips.push_back(isFinite(b.v2()) ? b.v2() : restTip(b));
    return tips;
}

std::vector<glm::vec3> restTips(std::span<const Blade> blades) {
    std::vector<glm::vec3> tips;
    tips.reserve(blades.size());
    for (const Blade& b : blades)
        tips.push_back(restTip(b));
    return tips;
}

std::string checkBlade(const Blade& blade) {
    if (!isFinite(blade.v0()) || !std::isfinite(blade.theta()))
        return "root v0 or theta is not finite";
    if (!isFinite(blade.up()))
        return "up is not finite";
    if (glm::length(blade.up()) < 1e-6f)
        return "up has zero length";
    if (!std::isfinite(blade.h()) || blade.h() < 0.0f)
        return "height h is negative or not finite";
    if (!std::isfinite(blade.s()) || blade.s() < 0.0f)
        return "stiffness s is negative or not finite";
    if (!std::isfinite(blade.w()))
        return "width w is not finite";
    if (!isFinite(blade.v1()) || !isFinite(blade.v2()))
        return "control point v1 or v2 is not finite";
    return {};
}

Result<void> checkBlades(std::span<const Blade> blades, const std::string& source) {
    for (std::size_t i = 0; i < blades.size(); ++i) {
        const std::string problem = checkBlade(blades[i]);
        if (!problem.empty())
            return makeError(source, "blade " + std::to_string(i) + ": " + problem);
    }
    return {};
}

Blade repairBlade(Blade blade) {
    if (!std::isfinite(blade.theta()))
        blade.v0Theta.w = 0.0f;
    if (!isFinite(blade.v0())) {
        blade.v0Theta = glm::vec4(0.0f, 0.0f, 0.0f, blade.theta());
        blade.v1H.w = 0.0f;
    }
    const glm::vec3 up = unitUp(blade.up());
    const float s = blade.s();
    blade.upS = glm::vec4(up, std::isfinite(s) ? std::max(s, 0.0f) : 0.0f);
    if (!std::isfinite(blade.h()) || blade.h() < 0.0f)
        blade.v1H.w = 0.0f;
    if (!std::isfinite(blade.w()))
        blade.v2W.w = 0.0f;
    const glm::vec3 tip = blade.v0() + blade.h() * up;
    if (!isFinite(blade.v2()))
        blade.v2W = glm::vec4(tip, blade.w());
    if (!isFinite(blade.v1()))
        blade.v1H = glm::vec4(tip, blade.h());
    return blade;
}

void validateBlade(Blade& blade) {
    const glm::vec3 v0 = blade.v0(), up = blade.up();
    const float h = blade.h();
    if (!(h > 0.0f)) {
        setPoints(blade, v0, v0);
        return;
    }
    // Relative to the root, so a small blade far from the origin keeps its precision.
    glm::vec3 d2 = blade.v2() - v0;
    // 1. Keep v2 above the ground plane.
    d2 -= up * std::min(glm::dot(up, d2), 0.0f);
    glm::vec3 d1(0.0f);
    for (int iteration = 0; iteration < VALIDATION_ITERATIONS; ++iteration) {
        // 2. Place v1 above v0 from the projected length of v0→v2 on the ground plane.
        const float lproj = glm::length(d2 - up * glm::dot(d2, up));
        const float ratio = lproj / h;
        d1 = up * (h * std::max(1.0f - ratio, 0.05f * std::max(ratio, 1.0f)));
        // 3. Length correction, degree n = 2: scale both points so the estimate equals h.
        const float l0 = glm::length(d2);
        const float l1 = glm::length(d2 - d1) + glm::length(d1);
        const float length = (2.0f * l0 + l1) / 3.0f;
        const float r = h / length;
        if (!(length > 0.0f) || !std::isfinite(r) || !isFinite(d2)) {
            // Underflow (a blade of denormal height) or overflow: stand the blade straight.
            setPoints(blade, v0 + h * up, v0 + h * up);
            return;
        }
        d1 *= r;
        d2 *= r;
    }
    setPoints(blade, v0 + d1, v0 + d2);
}

void stepBlade(Blade& blade, float& eta, glm::vec3 restTipIn, const PhysicsParams& params,
               const std::vector<WindSource>& wind, const std::vector<SphereCollider>& colliders,
               float timeS, float extraGravity) {
    blade = repairBlade(blade);
    eta = std::isfinite(eta) ? std::clamp(eta, 0.0f, ETA_MAX) : 0.0f;
    const float h = blade.h();
    const glm::vec3 v0 = blade.v0(), up = blade.up();
    if (!(h > 0.0f)) {
        setPoints(blade, v0, v0);
        return;
    }
    const glm::vec3 iv2 = isFinite(restTipIn) ? restTipIn : v0 + h * up;
    const float extra = std::isfinite(extraGravity) ? std::max(extraGravity, 0.0f) : 0.0f;
    const float gMagnitude = (std::isfinite(params.gravity.w) ? params.gravity.w : 0.0f) + extra;
    // Nothing acts on a blade at rest: skip it (a still field costs one comparison per blade).
    if (wind.empty() && colliders.empty() && gMagnitude == 0.0f && eta == 0.0f && blade.v2() == iv2)
        return;

    // Gravity is constant over the step: environmental gE plus the paper's front gravity
    // 0.25·|gE|·f, f = normalize(cross(up, widthDir)) (not scaled by h, not turned along gE).
    glm::vec3 gravity(0.0f);
    if (gMagnitude != 0.0f) {
        const glm::vec3 g = glm::vec3(params.gravity);
        const glm::vec3 dir =
            params.gravityMode == GravityMode::Centre ? safeNormalize(g - v0) : safeNormalize(g);
        const glm::vec3 gE = dir * gMagnitude;
        const glm::vec3 f = safeNormalize(glm::cross(up, widthDirection(up, blade.theta())));
        gravity = gE + params.frontGravityScale * glm::length(gE) * f;
        if (!isFinite(gravity))
            gravity = glm::vec3(0.0f);
    }

    const std::uint32_t n = substepCount(params);
    const float tau = n > 0 ? params.dtS / static_cast<float>(n) : 0.0f;
    const float maxMove = std::max(params.maxMovePerSubstep, 0.0f) * h;
    const float decayPerS = std::isfinite(params.etaDecayPerS) ? params.etaDecayPerS : 0.0f;
    for (std::uint32_t i = 0; i < n; ++i) {
        const float t = timeS + static_cast<float>(i) * tau;
        glm::vec3 v2 = blade.v2();
        const glm::vec3 d2 = v2 - v0;
        glm::vec3 force = gravity;
        if (!wind.empty()) {
            const glm::vec3 wi = windAt(wind, v0, t);
            if (wi != glm::vec3(0.0f)) {
                const float fd = 1.0f - std::abs(glm::dot(safeNormalize(wi), safeNormalize(d2)));
                const float fr = glm::dot(d2, up) / h;
                force += wi * (fd * fr);
            }
        }
        // Exact solution over τ of dv2/dt = k·(Iv2 − v2) + F with F frozen:
        // v2 += (Iv2 − v2)·(1 − e^{−kτ}) + F·(1 − e^{−kτ})/k, and F·τ as k → 0.
        const float k = blade.s() * std::max(1.0f - eta, params.crushedRecoveryFloor);
        const float kTau = k * tau;
        const float relax = kTau > 1e-6f ? -std::expm1(-kTau) : kTau;
        const float phi = kTau > 1e-6f ? relax / k : tau;
        glm::vec3 delta = (iv2 - v2) * relax + force * phi;
        const float move = glm::length(delta);
        if (!std::isfinite(move)) {
            delta = glm::vec3(0.0f);
        } else if (move > maxMove) {
            delta *= maxMove / move;
        }
        v2 += delta;
        blade.v2W = glm::vec4(v2, blade.w());
        eta = std::max(eta - decayPerS * tau, 0.0f);
        validateBlade(blade);
        if (!colliders.empty() && collide(blade, eta, colliders, t + tau))
            validateBlade(blade);
    }
}

void stepPhysics(std::span<Blade> blades, std::span<float> eta,
                 std::span<const glm::vec3> restTipsIn, const PhysicsParams& params,
                 const std::vector<WindSource>& wind, const std::vector<SphereCollider>& colliders,
                 float timeS, unsigned threadCount, GravityLoad load) {
    GRASS_ASSERT(eta.size() == blades.size() && restTipsIn.size() == blades.size());
    GRASS_ASSERT(load.perBlade.empty() || load.perBlade.size() == blades.size());
    unsigned threads = threadCount > 0 ? threadCount : std::thread::hardware_concurrency();
    threads = std::clamp(threads, 1u, MAX_THREADS);
    const std::size_t byWork = blades.size() / MIN_BLADES_PER_THREAD;
    threads =
        static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(byWork, 1)));
    if (threads <= 1) {
        stepRange(blades, eta, restTipsIn, params, wind, colliders, timeS, load);
        return;
    }
    // Every blade is independent, so any split gives bit-identical results.
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    const std::size_t chunk = (blades.size() + threads - 1) / threads;
    for (unsigned t = 1; t < threads; ++t) {
        const std::size_t begin = std::min(blades.size(), t * chunk);
        const std::size_t count = std::min(chunk, blades.size() - begin);
        workers.emplace_back([=, &params, &wind, &colliders] {
            stepRange(blades.subspan(begin, count), eta.subspan(begin, count),
                      restTipsIn.subspan(begin, count), params, wind, colliders, timeS,
                      subLoad(load, begin, count));
        });
    }
    const std::size_t first = std::min(chunk, blades.size());
    stepRange(blades.first(first), eta.first(first), restTipsIn.first(first), params, wind,
              colliders, timeS, subLoad(load, 0, first));
    for (std::thread& w : workers)
        w.join();
}

}  // namespace grass::core
