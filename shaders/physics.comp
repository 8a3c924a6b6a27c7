#version 450 core
// Blade physics on the GPU: core/physics/physics.cpp step for step (stepBlade, repairBlade,
// validateBlade, collide), one invocation per blade. See docs/physics.md for the integration and
// shaders/include/physics.glsl for what the CPU side precomputes per substep.
// GROUP_SIZE: invocations a work group (core/util/blade_pass_group.h: 32 unless
// GRASS_COMPUTE_GROUP says); each invocation is one blade, so the size changes no result.
#ifndef GROUP_SIZE
#define GROUP_SIZE 32
#endif
layout(local_size_x = GROUP_SIZE) in;

#include "blade.glsl"
#include "dispatch_grid.glsl"
#include "physics.glsl"

// One invocation per blade slot below bladeCount, dispatched as a grid (dispatch_grid.glsl).
uniform uint bladeCount;
// core::substepCount(params), computed on the CPU (see physics.glsl).
uniform uint substepCount;
uniform uint windCount;
uniform uint colliderCount;
uniform float gravityLoadScale;  // 0: no load buffer bound
// The editor's rest detection (editor/app/live_scene.h): a step marks `motionSeen` when it moves
// a tip by more than stillTipMove of its blade's height, or lets a crushed blade recover (η falls
// by more than half the step's pure decay, etaDecayStep: no collider pressed it). 0: not asked,
// and no buffer is bound.
uniform float stillTipMove;
uniform float etaDecayStep;
layout(std430, binding = 10) buffer MotionReportBuffer {
    uint motionSeen;
};

const float ETA_MAX = 1.0e4;
// See VALIDATION_ITERATIONS in core/physics/physics.cpp: passes 2–3 converge to a fixed point.
const int VALIDATION_ITERATIONS = 4;

vec3 unitUp(vec3 up) {
    float len2 = dot(up, up);
    if (!isFiniteFloat(len2) || len2 < 1e-12)
        return vec3(0.0, 1.0, 0.0);
    return abs(len2 - 1.0) <= 1e-5 ? up : up / sqrt(len2);
}

void setPoints(inout Blade blade, vec3 v1, vec3 v2) {
    blade.v1H = vec4(v1, blade.v1H.w);
    blade.v2W = vec4(v2, blade.v2W.w);
}

Blade repairBlade(Blade blade) {
    if (!isFiniteFloat(blade.v0Theta.w))
        blade.v0Theta.w = 0.0;
    if (!isFinite(blade.v0Theta.xyz)) {
        blade.v0Theta = vec4(0.0, 0.0, 0.0, blade.v0Theta.w);
        blade.v1H.w = 0.0;
    }
    vec3 up = unitUp(blade.upS.xyz);
    float s = blade.upS.w;
    blade.upS = vec4(up, isFiniteFloat(s) ? max(s, 0.0) : 0.0);
    if (!isFiniteFloat(blade.v1H.w) || blade.v1H.w < 0.0)
        blade.v1H.w = 0.0;
    if (!isFiniteFloat(blade.v2W.w))
        blade.v2W.w = 0.0;
    vec3 tip = blade.v0Theta.xyz + blade.v1H.w * up;
    if (!isFinite(blade.v2W.xyz))
        blade.v2W = vec4(tip, blade.v2W.w);
    if (!isFinite(blade.v1H.xyz))
        blade.v1H = vec4(tip, blade.v1H.w);
    return blade;
}

void validateBlade(inout Blade blade) {
    vec3 v0 = blade.v0Theta.xyz, up = blade.upS.xyz;
    float h = blade.v1H.w;
    if (!(h > 0.0)) {
        setPoints(blade, v0, v0);
        return;
    }
    vec3 d2 = blade.v2W.xyz - v0;
    // 1. Keep v2 above the ground plane.
    d2 -= up * min(dot(up, d2), 0.0);
    vec3 d1 = vec3(0.0);
    for (int iteration = 0; iteration < VALIDATION_ITERATIONS; ++iteration) {
        // 2. Place v1 above v0 from the projected length of v0→v2 on the ground plane.
        float lproj = length(d2 - up * dot(d2, up));
        float ratio = lproj / h;
        d1 = up * (h * max(1.0 - ratio, 0.05 * max(ratio, 1.0)));
        // 3. Length correction, degree n = 2: scale both points so the estimate equals h.
        float l0 = length(d2);
        float l1 = length(d2 - d1) + length(d1);
        float len = (2.0 * l0 + l1) / 3.0;
        float r = h / len;
        if (!(len > 0.0) || !isFiniteFloat(r) || !isFinite(d2)) {
            setPoints(blade, v0 + h * up, v0 + h * up);
            return;
        }
        d1 *= r;
        d2 *= r;
    }
    setPoints(blade, v0 + d1, v0 + d2);
}

vec3 sphereCorrection(vec3 p, vec3 c, float radiusM, vec3 up) {
    vec3 toCentre = c - p;
    float dist = length(toCentre);
    if (!(dist < radiusM))
        return vec3(0.0);
    vec3 n = dist > TINY_LENGTH ? toCentre / dist : -up;
    return (dist - radiusM) * n;
}

// Whether the tip or the midpoint may lie inside the sphere (c, √clearSquared).
bool tipOrMidpointWithin(vec3 c, float clearSquared, vec3 v0, Blade blade) {
    vec3 toTip = c - blade.v2W.xyz;
    vec3 toMid = c - (0.25 * v0 + 0.5 * blade.v1H.xyz + 0.25 * blade.v2W.xyz);
    return !(dot(toTip, toTip) > clearSquared) || !(dot(toMid, toMid) > clearSquared);
}

// core/physics/physics_simd.cpp, TipOrMidpointNearBound: a group's bound with its margin.
bool tipOrMidpointNearBound(vec3 b, float radiusM, float h, vec3 v0, Blade blade) {
    vec3 a = abs(b);
    float reach = radiusM * (1.0 + 1e-3) + 1e-6 * max(a.x, max(a.y, a.z)) + 1e-3 * h;
    return tipOrMidpointWithin(b, reach * reach, v0, blade);
}

// Collisions with every sphere at substep i's t + τ; true when the blade was hit.
bool collide(inout Blade blade, inout float bladeEta, uint substep) {
    vec3 v0 = blade.v0Theta.xyz, up = blade.upS.xyz;
    float h = blade.v1H.w;
    bool hit = false;
    for (uint j = 0u; j < colliderCount; ++j) {
        vec4 sphere = colliderSpheres[substep * colliderCount + j];
        ColliderGroup group = colliderGroups[j];
        if (group.size.x > 1u) {
            vec3 bound = sphere.xyz + group.boundOffsetRadius.xyz;
            vec3 toBound = bound - v0;
            float boundReach = group.boundOffsetRadius.w + 1.01 * h;
            // Out of reach of the root, or the tip and midpoint clearly outside the bound (so
            // outside every sphere of the group: core/physics/physics_simd.cpp,
            // TipOrMidpointNearBound, with its margin): the group leaves the blade as it is.
            if (dot(toBound, toBound) > boundReach * boundReach ||
                !tipOrMidpointNearBound(bound, group.boundOffsetRadius.w, h, v0, blade)) {
                j += group.size.x - 1u;
                continue;
            }
        }
        float radiusM = sphere.w;
        if (!(radiusM > 0.0))
            continue;
        vec3 c = sphere.xyz;
        if (!isFinite(c))
            continue;
        float reach = radiusM + 1.01 * h;
        vec3 rel = c - v0;
        if (dot(rel, rel) > reach * reach)
            continue;
        // Most spheres within reach touch neither the tip nor the midpoint, and leave the blade
        // as it is: skipped on squared distances, with a margin (1e-4 of R²) far beyond the
        // rounding of the exact tests below (core/physics/physics_simd.cpp, TipOrMidpointNear).
        // Under projects/nature's bunny a blade has up to ~730 spheres within reach, ~80 of
        // which touch it; the walk is a serial chain, and this takes the square roots and
        // divisions out of most of its links.
        if (!tipOrMidpointWithin(c, radiusM * radiusM * (1.0 + 1e-4), v0, blade))
            continue;
        vec3 v2 = blade.v2W.xyz;
        vec3 dTip = sphereCorrection(v2, c, radiusM, up);
        v2 += dTip;
        vec3 m = 0.25 * v0 + 0.5 * blade.v1H.xyz + 0.25 * v2;
        vec3 dMid = sphereCorrection(m, c, radiusM, up);
        // m moves a quarter as much as v2, so the tip moves by 4d.
        v2 += 4.0 * dMid;
        float eta2 = dot(dTip, dTip) + dot(dMid, dMid);
        if (eta2 > 0.0) {
            bladeEta = min(bladeEta + eta2, ETA_MAX);
            blade.v2W = vec4(v2, blade.v2W.w);
            hit = true;
        }
    }
    return hit;
}

void stepBlade(inout Blade blade, inout float bladeEta, vec3 restTipIn, float extraGravity) {
    blade = repairBlade(blade);
    bladeEta = isFiniteFloat(bladeEta) ? clamp(bladeEta, 0.0, ETA_MAX) : 0.0;
    float h = blade.v1H.w;
    vec3 v0 = blade.v0Theta.xyz, up = blade.upS.xyz;
    if (!(h > 0.0)) {
        setPoints(blade, v0, v0);
        return;
    }
    vec3 iv2 = isFinite(restTipIn) ? restTipIn : v0 + h * up;
    float extra = isFiniteFloat(extraGravity) ? max(extraGravity, 0.0) : 0.0;
    float gMagnitude = (isFiniteFloat(params.gravity.w) ? params.gravity.w : 0.0) + extra;
    // Nothing acts on a blade at rest: skip it.
    if (windCount == 0u && colliderCount == 0u && gMagnitude == 0.0 && bladeEta == 0.0 &&
        blade.v2W.xyz == iv2)
        return;

    // Gravity is constant over the step: gE plus the front gravity 0.25·|gE|·f.
    vec3 gravity = vec3(0.0);
    if (gMagnitude != 0.0) {
        vec3 g = params.gravity.xyz;
        vec3 dir = params.gravityMode == GRAVITY_MODE_CENTRE ? safeNormalize(g - v0)
                                                             : safeNormalize(g);
        vec3 gE = dir * gMagnitude;
        vec3 f = safeNormalize(cross(up, widthDirection(up, blade.v0Theta.w)));
        gravity = gE + params.frontGravityScale * length(gE) * f;
        if (!isFinite(gravity))
            gravity = vec3(0.0);
    }

    uint n = substepCount;
    float maxMove = max(params.maxMovePerSubstep, 0.0) * h;
    float decayPerS = isFiniteFloat(params.etaDecayPerS) ? params.etaDecayPerS : 0.0;
    for (uint i = 0u; i < n; ++i) {
        float t = substepTimes[i].x;
        float tau = substepTimes[i].y;
        vec3 v2 = blade.v2W.xyz;
        vec3 d2 = v2 - v0;
        vec3 force = gravity;
        if (windCount > 0u) {
            vec3 wi = vec3(0.0);
            for (uint j = 0u; j < windCount; ++j)
                wi += windAt(windSources[j], windCentres[i * windCount + j].xyz, v0, t);
            if (wi != vec3(0.0)) {
                float fd = 1.0 - abs(dot(safeNormalize(wi), safeNormalize(d2)));
                float fr = dot(d2, up) / h;
                force += wi * (fd * fr);
            }
        }
        // Exact solution over τ of dv2/dt = k·(Iv2 − v2) + F with F frozen.
        float k = blade.upS.w * max(1.0 - bladeEta, params.crushedRecoveryFloor);
        float kTau = k * tau;
        float relax = kTau > 1e-6 ? -expm1(-kTau) : kTau;
        float phi = kTau > 1e-6 ? relax / k : tau;
        vec3 delta = (iv2 - v2) * relax + force * phi;
        float move = length(delta);
        if (!isFiniteFloat(move)) {
            delta = vec3(0.0);
        } else if (move > maxMove) {
            delta *= maxMove / move;
        }
        v2 += delta;
        blade.v2W = vec4(v2, blade.v2W.w);
        bladeEta = max(bladeEta - decayPerS * tau, 0.0);
        validateBlade(blade);
        if (colliderCount > 0u && collide(blade, bladeEta, i))
            validateBlade(blade);
    }
}

void main() {
    uint index = invocationInPass();
    if (index >= bladeCount)
        return;
    const Blade original = physicsBlades[index];
    const float originalEta = eta[index];
    Blade blade = original;
    float bladeEta = originalEta;
    float extraGravity = gravityLoadScale > 0.0 ? gravityLoadScale * gravityLoad[index] : 0.0;
    stepBlade(blade, bladeEta, restTips[index].xyz, extraGravity);
    // A blade at rest is not written back: a still field costs reads only.
    if (blade != original)
        physicsBlades[index] = blade;
    if (bladeEta != originalEta)
        eta[index] = bladeEta;
    // Read before it is written, so that a moving field writes the mark about once a group.
    if (stillTipMove > 0.0 && motionSeen == 0u) {
        vec3 tipMove = blade.v2W.xyz - original.v2W.xyz;
        float reach = stillTipMove * blade.v1H.w;
        // Written so that a NaN counts as motion, as on the CPU (tipsMoved, anyRecovering).
        bool tipMoved = !(dot(tipMove, tipMove) <= reach * reach);
        bool recovering = bladeEta != 0.0 && !(bladeEta >= originalEta - 0.5 * etaDecayStep);
        if (tipMoved || recovering)
            motionSeen = 1u;
    }
}
