// Physics test cases shared by both executions of the one physics model (STYLE.md §1): the
// extremes sweep of SPEC §3 / issue 4, a set of degenerate blades, and the invariants every step
// must keep. tests/core/physics/physics_test.cpp runs them through core::stepBlade,
// tests/gl/physics_extremes_gl_test.cpp through shaders/physics.comp. World space, metres, seconds.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "blade/bezier.h"
#include "blade/blade.h"
#include "physics/physics.h"
#include "physics/wind.h"
#include "project/project.h"
#include "quality/quality_presets.h"

namespace grass::test {

// Every combination of these is one case (6 × 5 × 3 × 3 × 3 = 810), stepped EXTREME_STEP_COUNT
// times from rest with gravity, a gusty wave plus a vortex, and one sphere.
inline constexpr std::array<float, 6> EXTREME_DT_S{1e-5f, 1e-3f, 1.0f / 60.0f, 0.1f, 1.0f, 10.0f};
inline constexpr std::array<float, 5> EXTREME_STIFFNESS{0.0f, 1e-3f, 1.0f, 1e2f, 1e4f};
inline constexpr std::array<float, 3> EXTREME_WIND{0.0f, 1.0f, 1e3f};
inline constexpr std::array<float, 3> EXTREME_HEIGHT_M{1e-4f, 1.0f, 1e3f};
inline constexpr std::array<float, 3> EXTREME_RADIUS_M{0.0f, 1e-6f, 1e3f};
inline constexpr int EXTREME_STEP_COUNT = 12;

struct ExtremeCase {
    float dtS = 1.0f / 60.0f;
    float s = 1.0f;
    float windStrength = 0.0f;
    float h = 1.0f;
    float radiusM = 0.0f;
    bool operator==(const ExtremeCase&) const = default;
};

// In the order of the nested loops dt, s, wind, h, radius.
inline std::vector<ExtremeCase> extremeCases() {
    std::vector<ExtremeCase> cases;
    for (const float dtS : EXTREME_DT_S)
        for (const float s : EXTREME_STIFFNESS)
            for (const float windStrength : EXTREME_WIND)
                for (const float h : EXTREME_HEIGHT_M)
                    for (const float radiusM : EXTREME_RADIUS_M)
                        cases.push_back({dtS, s, windStrength, h, radiusM});
    return cases;
}

inline std::string describeCase(const ExtremeCase& c) {
    return "dt " + std::to_string(c.dtS) + " s " + std::to_string(c.s) + " wind " +
           std::to_string(c.windStrength) + " h " + std::to_string(c.h) + " radius " +
           std::to_string(c.radiusM);
}

// Every case has the same root and a slightly tilted up, so up is not an axis.
inline glm::vec3 extremeRoot() {
    return {0.3f, 0.0f, -0.2f};
}
inline glm::vec3 extremeUp() {
    return glm::normalize(glm::vec3(0.1f, 1.0f, 0.0f));
}

// Default parameters (gravity 9.81 down) with the case's step.
inline core::PhysicsParams extremeParams(const ExtremeCase& c) {
    core::PhysicsParams params;
    params.dtS = c.dtS;
    return params;
}

// The same at a quality preset (issue 10): the preset's substep policy on top, as `--preset`
// writes it into a project (a 10 s step at reference's 1/960 s substep hits the cap of 64).
inline core::PhysicsParams extremeParams(const ExtremeCase& c, core::QualityPreset preset) {
    core::Project project;
    project.physics = extremeParams(c);
    core::applyQuality(core::qualitySettings(preset), project);
    return project.physics;
}

// A fully gusty wave plus a vortex about the y axis through the origin, both at the case's
// strength (a strength of 0 keeps the sources, so the "nothing acts" shortcut is not taken).
inline std::vector<core::WindSource> extremeWind(const ExtremeCase& c) {
    core::WindSource gusty;
    gusty.strength = c.windStrength;
    gusty.gust = 1.0f;
    core::WindSource vortex;
    vortex.kind = core::WindKind::Vortex;
    vortex.strength = c.windStrength;
    return {gusty, vortex};
}

// A sphere beside the upper half of the blade; its place scales with h, so a large radius
// swallows the whole blade and a tiny one sits in its path.
inline std::vector<core::SphereCollider> extremeColliders(const ExtremeCase& c) {
    const glm::vec3 centre =
        extremeRoot() + extremeUp() * (0.6f * c.h) + glm::vec3(0.2f * c.h, 0.0f, 0.0f);
    return {{centre, c.radiusM, {}}};
}

inline core::Blade extremeBlade(const ExtremeCase& c) {
    return core::makeRestBlade(extremeRoot(), extremeUp(), c.h, 0.01f, c.s, 0.7f);
}

// Start time of step `step` of a case (steps follow each other without gaps).
inline float extremeStepTimeS(const ExtremeCase& c, int step) {
    return static_cast<float>(step) * c.dtS;
}

inline float lengthEstimate(const core::Blade& b) {
    return core::bezierLengthEstimate(b.v0(), b.v1(), b.v2());
}

// The stated tolerance (docs/physics.md): 1e-4 relative to h, plus float rounding of the world
// position (points are stored absolute, so a blade far from the origin loses ulp(|v0|)).
inline float lengthTolerance(const core::Blade& b) {
    const glm::vec3 a = glm::abs(b.v0());
    return 1e-4f * b.h() +
           4.0f * std::numeric_limits<float>::epsilon() * (std::max({a.x, a.y, a.z}) + b.h());
}

inline bool isFinite(const core::Blade& b) {
    for (const glm::vec4& v : {b.v0Theta, b.v1H, b.v2W, b.upS})
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(v[i]))
                return false;
    return true;
}

// The invariants after every step of a case, given the tip before the step: no NaN/Inf, the tip
// never below the ground plane, the length estimate at h, the tip within h of its root, and no
// step moving the tip further than physically possible (two tips within h of the root are at
// most 2h apart).
inline ::testing::AssertionResult keepsExtremeInvariants(const core::Blade& b, float eta,
                                                         const ExtremeCase& c, glm::vec3 v2Before) {
    if (!isFinite(b) || !std::isfinite(eta))
        return ::testing::AssertionFailure() << "not finite (eta " << eta << ")";
    const glm::vec3 v0 = extremeRoot(), up = extremeUp();
    const float tol = lengthTolerance(b);
    const float height = glm::dot(up, b.v2() - v0);
    if (!(height >= -tol))
        return ::testing::AssertionFailure() << "tip " << height << " below the ground plane";
    const float length = lengthEstimate(b);
    if (!(std::abs(length - c.h) <= tol))
        return ::testing::AssertionFailure()
               << "length estimate " << length << " differs from h by more than " << tol;
    const float reach = glm::length(b.v2() - v0);
    if (!(reach <= c.h + tol))
        return ::testing::AssertionFailure() << "tip " << reach << " from the root";
    const float move = glm::length(b.v2() - v2Before);
    if (!(move <= 2.0f * c.h + 2.0f * tol))
        return ::testing::AssertionFailure() << "tip moved " << move << " in one step";
    return ::testing::AssertionSuccess();
}

inline float relativeLengthError(const core::Blade& b, float h) {
    return std::abs(lengthEstimate(b) - h) / h;
}

// A gusty wave and a point source moving on a path (the CPU/GPU and scalar/SIMD agreement tests).
inline std::vector<core::WindSource> movingWind() {
    core::WindSource wave;
    wave.kind = core::WindKind::Directional;
    wave.direction = glm::vec3(1.0f, 0.0f, 0.3f);
    wave.strength = 3.0f;
    wave.wavelengthM = 3.0f;
    wave.speedMps = 1.5f;
    wave.gust = 0.4f;
    core::WindSource point;
    point.kind = core::WindKind::Point;
    point.strength = 4.0f;
    point.radiusM = 2.5f;
    point.coreRadiusM = 0.5f;
    point.path = {{0.0f, {-1.5f, 0.5f, 1.5f}}, {16.0f, {1.5f, 0.5f, -1.5f}}};
    return {wave, point};
}

// A sphere rolling through a 4 m field and back, and a packed group of three spheres sliding
// across it behind one bounding sphere.
inline std::vector<core::SphereCollider> movingColliders() {
    core::SphereCollider sphere;
    sphere.radiusM = 0.6f;
    // Rolls across the field and back, through the blades (centre below their tips).
    sphere.path = {
        {0.0f, {-2.5f, 0.3f, 0.0f}}, {8.0f, {2.5f, 0.3f, 0.5f}}, {16.0f, {-2.5f, 0.3f, -0.5f}}};
    // A packed mesh: three spheres moving together behind one bounding sphere (broad phase).
    std::vector<core::SphereCollider> colliders{sphere};
    for (const glm::vec3 offset :
         {glm::vec3(0.0f), glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 0.5f)}) {
        core::SphereCollider part;
        part.radiusM = 0.4f;
        part.centre = glm::vec3(0.0f, 0.2f, 2.5f) + offset;
        part.path = {{0.0f, part.centre}, {12.0f, part.centre + glm::vec3(0.0f, 0.0f, -5.0f)}};
        colliders.push_back(part);
    }
    colliders[1].groupSize = 3;
    colliders[1].boundOffset = glm::vec3(0.25f, 0.0f, 0.25f);
    colliders[1].boundRadiusM = 0.4f + glm::length(glm::vec3(0.25f, 0.0f, 0.25f)) + 1e-4f;
    return colliders;
}

// Cases that can share one dispatch (one step call, on the GPU or the SIMD execution): the same
// step, wind and collider. The collider's centre scales with h, so cases of different h share one only when its radius is 0 (a sphere of radius
// 0 is skipped before its centre is read). Putting the three spheres of a group in one dispatch
// does not work: the 1e3 m sphere placed for h = 1e-4 would swallow the 1 m blade at the same root.
inline bool shareDispatch(const ExtremeCase& a, const ExtremeCase& b) {
    const bool sameCollider =
        extremeColliders(a) == extremeColliders(b) || (a.radiusM == 0.0f && b.radiusM == 0.0f);
    return a.dtS == b.dtS && a.windStrength == b.windStrength && sameCollider;
}

inline std::vector<std::vector<ExtremeCase>> groupCases(const std::vector<ExtremeCase>& cases) {
    std::vector<std::vector<ExtremeCase>> groups;
    for (const ExtremeCase& c : cases) {
        auto group = std::find_if(groups.begin(), groups.end(),
                                  [&](const auto& g) { return shareDispatch(g.front(), c); });
        if (group == groups.end())
            groups.push_back({c});
        else
            group->push_back(c);
    }
    return groups;
}

// Degenerate input for the repair rule of core::repairBlade (docs/physics.md). Blades 0–4 are
// the ones tests/core/physics/physics_test.cpp names by index; checkBlades reports blade 2 first.
inline std::vector<core::Blade> degenerateBlades() {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<core::Blade> blades;
    // 0: h = 0.
    blades.push_back(core::makeRestBlade({1, 0, 0}, {0, 1, 0}, 0.0f, 0.01f, 1.0f, 0.0f));
    // 1: v2 == v0, no recovery (s = 0).
    core::Blade collapsed = core::makeRestBlade({2, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 0.0f, 0.0f);
    collapsed.v2W = glm::vec4(collapsed.v0(), 0.01f);
    blades.push_back(collapsed);
    // 2: up of zero length.
    blades.push_back(core::makeRestBlade({3, 0, 0}, {0, 0, 0}, 1.0f, 0.01f, 1.0f, 0.0f));
    // 3: NaN tip.
    core::Blade nanTip = core::makeRestBlade({4, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 1.0f, 0.0f);
    nanTip.v2W.x = nan;
    blades.push_back(nanTip);
    // 4: NaN root and NaN stiffness.
    blades.push_back(core::makeRestBlade({nan, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, nan, 0.0f));
    // 5: infinite tip.
    core::Blade infTip = core::makeRestBlade({5, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 1.0f, 0.0f);
    infTip.v2W.y = inf;
    blades.push_back(infTip);
    // 6: NaN up.
    blades.push_back(core::makeRestBlade({6, 0, 0}, {nan, 1, 0}, 1.0f, 0.01f, 1.0f, 0.0f));
    // 7: negative h.
    blades.push_back(core::makeRestBlade({7, 0, 0}, {0, 1, 0}, -1.0f, 0.01f, 1.0f, 0.0f));
    // 8: negative stiffness, infinite theta, NaN width.
    blades.push_back(core::makeRestBlade({8, 0, 0}, {0, 1, 0}, 1.0f, nan, -5.0f, inf));
    // 9: NaN v1 only.
    core::Blade nanMiddle = core::makeRestBlade({9, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 1.0f, 0.0f);
    nanMiddle.v1H.z = nan;
    blades.push_back(nanMiddle);
    // 10: up of length 3 (normalised by the repair).
    blades.push_back(core::makeRestBlade({10, 0, 0}, {0, 3, 0}, 1.0f, 0.01f, 1.0f, 0.0f));
    // 11: a denormal height (the validation's underflow path).
    blades.push_back(core::makeRestBlade({11, 0, 0}, {0, 1, 0}, 1e-40f, 0.01f, 1.0f, 0.0f));
    return blades;
}

// Spheres whose surface passes within a hair of a blade's tip or midpoint, for the collision
// loops' squared-distance shortcut (core/physics/physics_simd.cpp TipOrMidpointNear, the same in
// shaders/physics.comp): blades at rest (upright; run them without wind or gravity) beside a
// sphere of radius 1 m whose centre lies (1 + δ) m from the tip, or from the midpoint,
// horizontally. Inside (δ < 0) the exact test corrects the blade, so η > 0 after a step; outside
// it leaves the blade as it is, η = 0. The outside δ lie both within the shortcut's margin
// (√(1 + 1e-4) − 1 ≈ 5e-5) and beyond it; the smallest, 1e-5 m, is ~20 float steps of the
// coordinates (every site lies within 8 m of the origin). Sites 3 m apart, out of each other's
// reach; 16 equal blades a site, so every block of SIMD lanes (4, 8 or 16) holds one case.
//
// `grouped`: each sphere heads a group of two (a packed mesh's broad phase, SphereCollider::
// groupSize) with a small sphere on its far side, and the group's bound touches the sphere where
// it is nearest the tip or midpoint: the bound's surface passes the same hair from the point, for
// the shortcut that skips a whole group (TipOrMidpointNearBound). Its margin (~1.6e-3 m here) is
// wider than the per-sphere one: the 1e-2 and 1e-1 m sites lie beyond it, the rest within.
struct SphereEdgeField {
    std::vector<core::Blade> blades;
    std::vector<float> deltas;  // per blade: its site's δ
    std::vector<core::SphereCollider> colliders;
};

// One substep without gravity, wind or η's decay: η after the step is the first collision's
// squared correction, ≥ 1e-10 m² for the nearest inside surface (a decay of 0.1/s over the
// substep would take 8e-4 off it).
inline core::PhysicsParams sphereEdgeParams() {
    core::PhysicsParams params;
    params.gravity.w = 0.0f;
    params.etaDecayPerS = 0.0f;
    params.dtS = params.maxSubstepS;
    return params;
}

inline SphereEdgeField sphereEdgeField(bool grouped = false) {
    constexpr std::array<float, 12> DELTAS{-1e-3f, -1e-4f, -2e-5f, -1e-5f, 1e-5f, 2e-5f,
                                           4e-5f,  6e-5f,  1e-4f,  1e-3f,  1e-2f, 1e-1f};
    constexpr float H = 0.5f, RADIUS = 1.0f;
    constexpr std::size_t BLADES_PER_SITE = 16;
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    SphereEdgeField field;
    std::size_t site = 0;
    for (const bool atMidpoint : {false, true})
        for (const float delta : DELTAS) {
            const glm::vec3 root(3.0f * float(site % 5) - 6.0f, 0.0f, 3.0f * float(site / 5) - 4.5f);
            ++site;
            const core::Blade blade = core::makeRestBlade(root, up, H, 0.01f, 1.0f, 0.3f);
            // At rest v1 = v2 = the tip, so the midpoint 0.25·v0 + 0.5·v1 + 0.25·v2 is 0.75·h up.
            const glm::vec3 point = root + (atMidpoint ? 0.75f * H : H) * up;
            core::SphereCollider sphere;
            sphere.centre = point + glm::vec3(RADIUS * (1.0f + delta), 0.0f, 0.0f);
            sphere.radiusM = RADIUS;
            field.colliders.push_back(sphere);
            if (grouped) {
                // A 0.05 m sphere 1.2 m beyond the centre: the bound spans x from the centre −1
                // to +1.25, so it is centred 0.125 m beyond the centre with a radius of 1.125 m
                // (both exact in float) and touches the big sphere at the point's side.
                core::SphereCollider& head = field.colliders.back();
                head.groupSize = 2;
                head.boundOffset = glm::vec3(0.125f, 0.0f, 0.0f);
                head.boundRadiusM = 1.125f;
                core::SphereCollider far;
                far.centre = sphere.centre + glm::vec3(1.2f, 0.0f, 0.0f);
                far.radiusM = 0.05f;
                field.colliders.push_back(far);
            }
            for (std::size_t i = 0; i < BLADES_PER_SITE; ++i) {
                field.blades.push_back(blade);
                field.deltas.push_back(delta);
            }
        }
    return field;
}

}  // namespace grass::test
