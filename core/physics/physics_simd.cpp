// The SIMD execution of the blade physics (physics_simd.h): the scalar reference's stepBlade,
// line for line, on Highway vectors of blades. Compiled once per instruction set by Highway's
// foreach_target; stepPhysicsSimd picks the best at run time.
#include "physics/physics_simd.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "util/assert.h"
#include "util/thread_pool.h"

// What every instruction set's code reads: one step's constants, built once per step.
#ifndef GRASS_PHYSICS_SIMD_JOB
#define GRASS_PHYSICS_SIMD_JOB
namespace grass::core::simd_step {

// The most float lanes of any target (AVX-512: 16).
constexpr std::size_t MAX_LANES = 16;

struct Source {
    WindKind kind = WindKind::Directional;
    glm::vec3 dir{0.0f};  // directional: safeNormalize(direction); vortex: safeNormalize(axis)
    float strength = 0.0f, radiusM = 0.0f, coreRadiusM = 0.0f, wavelengthM = 0.0f,
          speedMps = 0.0f, gust = 0.0f, cellM = 0.0f;
};

struct Job {
    std::span<Blade> blades;
    std::span<float> eta;
    std::span<const glm::vec3> restTips;
    GravityLoad load;
    const PhysicsParams* params = nullptr;
    const std::vector<WindSource>* wind = nullptr;
    const std::vector<SphereCollider>* colliders = nullptr;
    float timeS = 0.0f;
    std::uint32_t substeps = 0;
    float tau = 0.0f;
    float gravityW = 0.0f;  // |gE| of the params, 0 when not finite
    float decayTau = 0.0f;  // etaDecayPerS · τ, as the reference computes it
    float maxMoveFraction = 0.0f;
    bool restSkip = false;  // no wind and no colliders: a blade at rest is left alone
    std::vector<float> times;          // t of each substep
    std::vector<Source> sources;       // the wind sources that blow (strength ≠ 0)
    std::vector<glm::vec3> centres;    // [substep · sources + k], at t
    std::vector<glm::vec4> spheres;    // [substep · colliders + j]: centre at t + τ, radius
    std::vector<glm::vec3> bounds;     // [substep · colliders + j]: the group's bound centre
};

}  // namespace grass::core::simd_step
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "physics/physics_simd.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace grass::core::simd_step {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<D>;
using DU = hn::RebindToUnsigned<D>;
using V = hn::Vec<D>;
using VU = hn::Vec<DU>;
using M = hn::Mask<D>;

struct V3 {
    V x, y, z;
};

HWY_INLINE V3 Splat3(D d, glm::vec3 v) {
    return {hn::Set(d, v.x), hn::Set(d, v.y), hn::Set(d, v.z)};
}
HWY_INLINE V3 Add3(V3 a, V3 b) {
    return {hn::Add(a.x, b.x), hn::Add(a.y, b.y), hn::Add(a.z, b.z)};
}
HWY_INLINE V3 Sub3(V3 a, V3 b) {
    return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)};
}
HWY_INLINE V3 Scale3(V3 a, V s) {
    return {hn::Mul(a.x, s), hn::Mul(a.y, s), hn::Mul(a.z, s)};
}
// Fused multiply-adds where the target has them: one rounding less than the reference's
// products and sums (it rounds each), well inside the agreement tolerance.
HWY_INLINE V Dot3(V3 a, V3 b) {
    return hn::MulAdd(a.z, b.z, hn::MulAdd(a.y, b.y, hn::Mul(a.x, b.x)));
}
HWY_INLINE V Length3(V3 a) {
    return hn::Sqrt(Dot3(a, a));
}
HWY_INLINE V3 Cross3(V3 a, V3 b) {
    return {hn::Sub(hn::Mul(a.y, b.z), hn::Mul(a.z, b.y)),
            hn::Sub(hn::Mul(a.z, b.x), hn::Mul(a.x, b.z)),
            hn::Sub(hn::Mul(a.x, b.y), hn::Mul(a.y, b.x))};
}
HWY_INLINE V3 Select3(M m, V3 yes, V3 no) {
    return {hn::IfThenElse(m, yes.x, no.x), hn::IfThenElse(m, yes.y, no.y),
            hn::IfThenElse(m, yes.z, no.z)};
}
HWY_INLINE V3 Zero3(D d) {
    return {hn::Zero(d), hn::Zero(d), hn::Zero(d)};
}
HWY_INLINE M Finite3(V3 a) {
    return hn::And(hn::And(hn::IsFinite(a.x), hn::IsFinite(a.y)), hn::IsFinite(a.z));
}
// v / |v|, or 0 when |v| is tiny or not finite (the reference's safeNormalize).
HWY_INLINE V3 SafeNormalize3(D d, V3 v) {
    const V len = Length3(v);
    const M ok = hn::And(hn::Gt(len, hn::Set(d, 1e-20f)), hn::IsFinite(len));
    return Select3(ok, V3{hn::Div(v.x, len), hn::Div(v.y, len), hn::Div(v.z, len)}, Zero3(d));
}
// glm::normalize: v · (1 / sqrt(v·v)).
HWY_INLINE V3 Normalize3(D d, V3 v) {
    return Scale3(v, hn::Div(hn::Set(d, 1.0f), hn::Sqrt(Dot3(v, v))));
}

// core::widthDirection: the tangent basis of up (a reference axis not parallel to it) at θ.
HWY_INLINE V3 WidthDirection(D d, V3 up, V theta) {
    const M useY = hn::Lt(hn::Abs(up.y), hn::Set(d, 0.9f));
    const V3 reference{hn::IfThenZeroElse(useY, hn::Set(d, 1.0f)),
                       hn::IfThenElseZero(useY, hn::Set(d, 1.0f)), hn::Zero(d)};
    const V3 t = Normalize3(d, Cross3(reference, up));
    const V3 b = Cross3(up, t);
    return Add3(Scale3(t, hn::Cos(d, theta)), Scale3(b, hn::Sin(d, theta)));
}

// The wind module's value noise (wind.cpp): lowbias32 of the lattice indices, quintic fade.
HWY_INLINE V LatticeValue(D d, VU x, VU y, VU z) {
    const DU du;
    const DI di;
    VU h = hn::Xor(hn::Xor(hn::Mul(x, hn::Set(du, 0x8da6b343u)), hn::Mul(y, hn::Set(du, 0xd8163841u))),
                   hn::Mul(z, hn::Set(du, 0xcb1ab31fu)));
    h = hn::Xor(h, hn::ShiftRight<16>(h));
    h = hn::Mul(h, hn::Set(du, 0x7feb352du));
    h = hn::Xor(h, hn::ShiftRight<15>(h));
    h = hn::Mul(h, hn::Set(du, 0x846ca68bu));
    h = hn::Xor(h, hn::ShiftRight<16>(h));
    return hn::Mul(hn::ConvertTo(d, hn::BitCast(di, hn::ShiftRight<8>(h))),
                   hn::Set(d, 1.0f / 16777215.0f));
}
HWY_INLINE V Fade(D d, V t) {
    const V inner = hn::Add(hn::Mul(t, hn::Sub(hn::Mul(t, hn::Set(d, 6.0f)), hn::Set(d, 15.0f))),
                            hn::Set(d, 10.0f));
    return hn::Mul(hn::Mul(hn::Mul(t, t), t), inner);
}
HWY_INLINE V Lerp(V a, V b, V u) {
    return hn::Add(a, hn::Mul(hn::Sub(b, a), u));
}
HWY_INLINE V ValueNoise3(D d, V3 p) {
    const DI di;
    const DU du;
    const V period = hn::Set(d, 65536.0f);
    // fmod(p, period): exact (p itself) while |p| < period.
    const V inversePeriod = hn::Set(d, 1.0f / 65536.0f);  // a power of two: exact
    const auto wrap = [&](V x) {
        return hn::Sub(x, hn::Mul(period, hn::Trunc(hn::Mul(x, inversePeriod))));
    };
    const V qx = wrap(p.x), qy = wrap(p.y), qz = wrap(p.z);
    const V cx = hn::Floor(qx), cy = hn::Floor(qy), cz = hn::Floor(qz);
    const auto index = [&](V cell) {
        return hn::BitCast(du, hn::Add(hn::ConvertTo(di, cell), hn::Set(di, 65536)));
    };
    const VU ix = index(cx), iy = index(cy), iz = index(cz);
    const VU one = hn::Set(du, 1u);
    const V ux = Fade(d, hn::Sub(qx, cx)), uy = Fade(d, hn::Sub(qy, cy)), uz = Fade(d, hn::Sub(qz, cz));
    V zs[2];
    for (int dz = 0; dz < 2; ++dz) {
        const VU z = dz == 0 ? iz : hn::Add(iz, one);
        const V c00 = LatticeValue(d, ix, iy, z), c10 = LatticeValue(d, hn::Add(ix, one), iy, z);
        const V c01 = LatticeValue(d, ix, hn::Add(iy, one), z);
        const V c11 = LatticeValue(d, hn::Add(ix, one), hn::Add(iy, one), z);
        zs[dz] = Lerp(Lerp(c00, c10, ux), Lerp(c01, c11, ux), uy);
    }
    return Lerp(zs[0], zs[1], uz);
}

// (1 − (r/R)²)² inside R, 0 outside, 1 for R ≤ 0; the core's linear ramp.
HWY_INLINE V Falloff(D d, V r, float radiusM) {
    if (radiusM <= 0.0f)
        return hn::Set(d, 1.0f);
    const V rr = hn::Mul(r, hn::Set(d, 1.0f / radiusM));
    const V q = hn::Sub(hn::Set(d, 1.0f), hn::Mul(rr, rr));
    return hn::IfThenZeroElse(hn::Ge(r, hn::Set(d, radiusM)), hn::Mul(q, q));
}
HWY_INLINE V CoreRamp(D d, V r, float coreRadiusM) {
    if (!(coreRadiusM > 0.0f))
        return hn::Set(d, 1.0f);
    return hn::Min(hn::Mul(r, hn::Set(d, 1.0f / coreRadiusM)), hn::Set(d, 1.0f));
}

// core::windAt summed over the sources at the root p (finite in every lane) at time t.
HWY_INLINE V3 WindAt(D d, const Job& job, std::uint32_t substep, V3 p) {
    V3 sum = Zero3(d);
    const float t = job.times[substep];
    if (!std::isfinite(t))
        return sum;
    for (std::size_t k = 0; k < job.sources.size(); ++k) {
        const Source& s = job.sources[k];
        const V3 centre = Splat3(d, job.centres[substep * job.sources.size() + k]);
        V3 result;
        if (s.kind == WindKind::Directional) {
            V magnitude = hn::Set(d, s.strength);
            const V3 dir = Splat3(d, s.dir);
            if (s.wavelengthM > 0.0f) {
                // Divided as the reference divides: the wave's phase is where the windiest
                // extremes are most sensitive to rounding.
                const V phase = hn::Div(
                    hn::Mul(hn::Set(d, 6.28318530717958647692f),
                            hn::Sub(Dot3(dir, p), hn::Set(d, s.speedMps * t))),
                    hn::Set(d, s.wavelengthM));
                magnitude = hn::Mul(magnitude, hn::Add(hn::Set(d, 0.5f),
                                                       hn::Mul(hn::Set(d, 0.5f), hn::Sin(d, phase))));
            }
            if (s.gust > 0.0f) {
                const V3 moved = Sub3(p, Scale3(dir, hn::Set(d, s.speedMps * t)));
                const V n = ValueNoise3(d, Scale3(moved, hn::Set(d, 1.0f / s.cellM)));
                const float g = std::clamp(s.gust, 0.0f, 1.0f);
                magnitude = hn::Mul(magnitude, hn::Add(hn::Set(d, 1.0f - g), hn::Mul(hn::Set(d, g), n)));
            }
            const V r = s.radiusM > 0.0f ? Length3(Sub3(p, centre)) : hn::Zero(d);
            result = Scale3(dir, hn::Mul(magnitude, Falloff(d, r, s.radiusM)));
        } else if (s.kind == WindKind::Point) {
            const V3 delta = Sub3(p, centre);
            const V r = Length3(delta);
            result = Scale3(SafeNormalize3(d, delta),
                            hn::Mul(hn::Mul(hn::Set(d, s.strength), CoreRamp(d, r, s.coreRadiusM)),
                                    Falloff(d, r, s.radiusM)));
        } else {
            const V3 axis = Splat3(d, s.dir);
            const V3 delta = Sub3(p, centre);
            const V3 radial = Sub3(delta, Scale3(axis, Dot3(delta, axis)));
            const V r = Length3(radial);
            result = Scale3(SafeNormalize3(d, Cross3(axis, radial)),
                            hn::Mul(hn::Mul(hn::Set(d, s.strength), CoreRamp(d, r, s.coreRadiusM)),
                                    Falloff(d, r, s.radiusM)));
        }
        sum = Add3(sum, Select3(Finite3(result), result, Zero3(d)));
    }
    return sum;
}

// Validation 1–3 of SPEC §3 (core::validateBlade), four passes; h > 0 in every lane.
HWY_INLINE void Validate(D d, V3 v0, V3 up, V h, V invH, V3& v1, V3& v2) {
    V3 d2 = Sub3(v2, v0);
    d2 = Sub3(d2, Scale3(up, hn::Min(Dot3(up, d2), hn::Zero(d))));
    V3 d1 = Zero3(d);
    for (int iteration = 0; iteration < 4; ++iteration) {
        const V lproj = Length3(Sub3(d2, Scale3(up, Dot3(d2, up))));
        const V ratio = hn::Mul(lproj, invH);
        d1 = Scale3(up, hn::Mul(h, hn::Max(hn::Sub(hn::Set(d, 1.0f), ratio),
                                           hn::Mul(hn::Set(d, 0.05f),
                                                   hn::Max(ratio, hn::Set(d, 1.0f))))));
        const V l0 = Length3(d2);
        const V l1 = hn::Add(Length3(Sub3(d2, d1)), Length3(d1));
        const V length = hn::Div(hn::Add(hn::Mul(hn::Set(d, 2.0f), l0), l1), hn::Set(d, 3.0f));
        const V r = hn::Div(h, length);
        d1 = Scale3(d1, r);
        d2 = Scale3(d2, r);
    }
    // The reference stands a blade straight as soon as a pass meets a length that is not > 0, a
    // ratio that is not finite or a d2 that is not: each of these leaves d2 or d1 non-finite
    // (0·∞, ∞ and NaN persist through the later passes), so one test after the passes finds the
    // same lanes.
    const M straight = hn::Not(hn::And(Finite3(d1), Finite3(d2)));
    const V3 top = Add3(v0, Scale3(up, h));
    v1 = Select3(straight, top, Add3(v0, d1));
    v2 = Select3(straight, top, Add3(v0, d2));
}

// The reference's sphereCorrection: onto the surface of the sphere (c, R) when inside it.
HWY_INLINE V3 SphereCorrection(D d, V3 p, V3 c, V radius, V3 up) {
    const V3 toCentre = Sub3(c, p);
    const V dist = Length3(toCentre);
    const V3 n = Select3(hn::Gt(dist, hn::Set(d, 1e-20f)),
                         Scale3(toCentre, hn::Div(hn::Set(d, 1.0f), dist)),
                         V3{hn::Neg(up.x), hn::Neg(up.y), hn::Neg(up.z)});
    return Select3(hn::Lt(dist, radius), Scale3(n, hn::Sub(dist, radius)), Zero3(d));
}

// core's collide() at the substep's t + τ; the mask of lanes that were hit.
HWY_INLINE M Collide(D d, const Job& job, std::uint32_t substep, V3 v0, V3 up, V h, V3 v1,
                     V3& v2, V& eta) {
    const M all = hn::FirstN(d, hn::Lanes(d));
    M hitAny = hn::Not(all);
    const std::vector<SphereCollider>& colliders = *job.colliders;
    const std::size_t base = substep * colliders.size();
    const V reachH = hn::Mul(hn::Set(d, 1.01f), h);
    // A packed mesh's spheres follow their head (groupSize > 1): lanes out of the head's bound
    // skip the whole group, as the reference's loop does per blade.
    M group = all;
    std::size_t groupEnd = 0;
    for (std::size_t j = 0; j < colliders.size(); ++j) {
        const SphereCollider& sphere = colliders[j];
        if (j >= groupEnd)
            group = all;
        if (sphere.groupSize > 1) {
            const V3 toBound = Sub3(Splat3(d, job.bounds[base + j]), v0);
            const V boundReach = hn::Add(hn::Set(d, sphere.boundRadiusM), reachH);
            // NaN bounds fail the comparison and fall through to the exact tests.
            group = hn::Not(hn::Gt(Dot3(toBound, toBound), hn::Mul(boundReach, boundReach)));
            groupEnd = j + sphere.groupSize;
            if (hn::AllFalse(d, group)) {
                j = groupEnd - 1;
                continue;
            }
        }
        const glm::vec4 centre = job.spheres[base + j];
        if (!(centre.w > 0.0f) || !std::isfinite(centre.x) || !std::isfinite(centre.y) ||
            !std::isfinite(centre.z))
            continue;
        const V3 c = Splat3(d, glm::vec3(centre));
        const V radius = hn::Set(d, centre.w);
        const V reach = hn::Add(radius, reachH);
        const V3 rel = Sub3(c, v0);
        const M active = hn::And(group, hn::Not(hn::Gt(Dot3(rel, rel), hn::Mul(reach, reach))));
        if (hn::AllFalse(d, active))
            continue;
        V3 moved = v2;
        const V3 dTip = SphereCorrection(d, moved, c, radius, up);
        moved = Add3(moved, dTip);
        const V3 m = Add3(Add3(Scale3(v0, hn::Set(d, 0.25f)), Scale3(v1, hn::Set(d, 0.5f))),
                          Scale3(moved, hn::Set(d, 0.25f)));
        const V3 dMid = SphereCorrection(d, m, c, radius, up);
        moved = Add3(moved, Scale3(dMid, hn::Set(d, 4.0f)));
        const V eta2 = hn::Add(Dot3(dTip, dTip), Dot3(dMid, dMid));
        const M hit = hn::And(active, hn::Gt(eta2, hn::Zero(d)));
        eta = hn::IfThenElse(hit, hn::Min(hn::Add(eta, eta2), hn::Set(d, ETA_MAX)), eta);
        v2 = Select3(hit, moved, v2);
        hitAny = hn::Or(hitAny, hit);
    }
    return hitAny;
}

// The reference's step for blade i (the scalar lanes and the repairs).
HWY_INLINE void stepScalar(const Job& job, std::size_t i) {
    stepBlade(job.blades[i], job.eta[i], job.restTips[i], *job.params, *job.wind, *job.colliders,
              job.timeS, job.load.at(i));
}

// Blocks [firstBlock, endBlock) of Lanes(d) blades each.
void StepBlocks(const Job& job, std::size_t firstBlock, std::size_t endBlock) {
    const D d;
    const std::size_t lanes = hn::Lanes(d);
    HWY_ASSERT(lanes <= MAX_LANES);
    const PhysicsParams& params = *job.params;
    // Per lane: v0 θ | v1 h | v2 w | up s | η | rest tip | extra gravity.
    enum Field { V0X, V0Y, V0Z, THETA, V1X, V1Y, V1Z, H, V2X, V2Y, V2Z, W, UPX, UPY, UPZ, S, ETA,
                 TIPX, TIPY, TIPZ, EXTRA, FIELD_COUNT };
    HWY_ALIGN float in[FIELD_COUNT][MAX_LANES];
    HWY_ALIGN float out[7][MAX_LANES];
    for (std::size_t block = firstBlock; block < endBlock; ++block) {
        const std::size_t first = block * lanes;
        // Into lanes: the blade's 16 floats, then η, the rest tip and the extra gravity.
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::size_t i = first + l;
            float blade[16];
            std::memcpy(blade, &job.blades[i], sizeof blade);  // Blade: four vec4 (blade.h)
            for (int f = 0; f < 16; ++f)
                in[f][l] = blade[f];
            in[ETA][l] = job.eta[i];
            in[TIPX][l] = job.restTips[i].x;
            in[TIPY][l] = job.restTips[i].y;
            in[TIPZ][l] = job.restTips[i].z;
            in[EXTRA][l] = job.load.at(i);
        }
        const auto load = [&](int f) { return hn::Load(d, in[f]); };
        // The lanes the reference would repair or collapse take its scalar step (all fields
        // finite, h > 0, up of unit length, s ≥ 0, η in [0, ETA_MAX], extra gravity ≥ 0 pass).
        M finite = hn::IsFinite(load(0));
        for (int f = 1; f < FIELD_COUNT; ++f)
            finite = hn::And(finite, hn::IsFinite(load(f)));
        const V upLen2 = hn::Add(hn::Add(hn::Mul(load(UPX), load(UPX)), hn::Mul(load(UPY), load(UPY))),
                                 hn::Mul(load(UPZ), load(UPZ)));
        const M simdLanes = hn::And(
            hn::And(hn::And(finite, hn::Gt(load(H), hn::Zero(d))),
                    hn::Le(hn::Abs(hn::Sub(upLen2, hn::Set(d, 1.0f))), hn::Set(d, 1e-5f))),
            hn::And(hn::And(hn::Ge(load(S), hn::Zero(d)), hn::Ge(load(EXTRA), hn::Zero(d))),
                    hn::And(hn::Ge(load(ETA), hn::Zero(d)), hn::Le(load(ETA), hn::Set(d, ETA_MAX)))));
        if (hn::AllFalse(d, simdLanes)) {
            for (std::size_t l = 0; l < lanes; ++l)
                stepScalar(job, first + l);
            continue;
        }
        bool simd[MAX_LANES];
        {
            HWY_ALIGN std::int32_t bits[MAX_LANES];
            hn::Store(hn::VecFromMask(DI(), hn::RebindMask(DI(), simdLanes)), DI(), bits);
            for (std::size_t l = 0; l < lanes; ++l) {
                simd[l] = bits[l] != 0;
                // The lane still computes, on the blade as it was; its result is not stored.
                if (!simd[l])
                    stepScalar(job, first + l);
            }
        }
        const V3 v0{load(V0X), load(V0Y), load(V0Z)};
        const V3 up{load(UPX), load(UPY), load(UPZ)};
        const V h = load(H), s = load(S);
        const V invH = hn::Div(hn::Set(d, 1.0f), h);  // for the validation's ratio lproj / h
        V3 v1{load(V1X), load(V1Y), load(V1Z)};
        V3 v2{load(V2X), load(V2Y), load(V2Z)};
        V eta = load(ETA);
        const V3 iv2{load(TIPX), load(TIPY), load(TIPZ)};
        const V3 v1Start = v1, v2Start = v2;
        const V etaStart = eta;
        // Nothing acts on a blade at rest (no wind, no colliders, no gravity, η = 0, the tip at
        // its rest): the reference leaves it as it was. A block of such blades is done.
        const V gMagnitudeStart = hn::Add(hn::Set(d, job.gravityW), load(EXTRA));
        const M atRest =
            job.restSkip
                ? hn::And(hn::And(hn::Eq(gMagnitudeStart, hn::Zero(d)), hn::Eq(eta, hn::Zero(d))),
                          hn::And(hn::And(hn::Eq(v2.x, iv2.x), hn::Eq(v2.y, iv2.y)),
                                  hn::Eq(v2.z, iv2.z)))
                : hn::Not(hn::FirstN(d, lanes));
        if (hn::AllTrue(d, hn::Or(atRest, hn::Not(simdLanes))))
            continue;

        // Gravity, constant over the step: gE plus the front gravity 0.25·|gE|·f.
        const V gMagnitude = gMagnitudeStart;
        const M pulled = hn::Ne(gMagnitude, hn::Zero(d));
        V3 gravity = Zero3(d);
        if (!hn::AllFalse(d, pulled)) {
            const V3 g = Splat3(d, glm::vec3(params.gravity));
            const V3 dir = SafeNormalize3(
                d, params.gravityMode == GravityMode::Centre ? Sub3(g, v0) : g);
            const V3 gE = Scale3(dir, gMagnitude);
            const V3 f = SafeNormalize3(d, Cross3(up, WidthDirection(d, up, load(THETA))));
            gravity = Add3(gE, Scale3(f, hn::Mul(hn::Set(d, params.frontGravityScale), Length3(gE))));
            gravity = Select3(hn::And(pulled, Finite3(gravity)), gravity, Zero3(d));
        }
        const V maxMove = hn::Mul(hn::Set(d, std::max(params.maxMovePerSubstep, 0.0f)), h);
        const V tau = hn::Set(d, job.tau);
        for (std::uint32_t i = 0; i < job.substeps; ++i) {
            const V3 d2 = Sub3(v2, v0);
            V3 force = gravity;
            if (!job.sources.empty()) {
                const V3 wi = WindAt(d, job, i, v0);
                const M blows = hn::Or(hn::Or(hn::Ne(wi.x, hn::Zero(d)), hn::Ne(wi.y, hn::Zero(d))),
                                       hn::Ne(wi.z, hn::Zero(d)));
                const V fd = hn::Sub(hn::Set(d, 1.0f),
                                     hn::Abs(Dot3(SafeNormalize3(d, wi), SafeNormalize3(d, d2))));
                const V fr = hn::Div(Dot3(d2, up), h);
                force = Select3(blows, Add3(force, Scale3(wi, hn::Mul(fd, fr))), force);
            }
            // v2 += (Iv2 − v2)·(1 − e^{−kτ}) + F·(1 − e^{−kτ})/k, and F·τ as k → 0.
            const V k = hn::Mul(s, hn::Max(hn::Sub(hn::Set(d, 1.0f), eta),
                                           hn::Set(d, params.crushedRecoveryFloor)));
            const V kTau = hn::Mul(k, tau);
            const M stiff = hn::Gt(kTau, hn::Set(d, 1e-6f));
            const V relax = hn::IfThenElse(stiff, hn::Neg(hn::Expm1(d, hn::Neg(kTau))), kTau);
            const V phi = hn::IfThenElse(stiff, hn::Div(relax, k), tau);
            V3 delta = Add3(Scale3(Sub3(iv2, v2), relax), Scale3(force, phi));
            const V move = Length3(delta);
            const V3 capped = Scale3(delta, hn::Div(maxMove, move));
            delta = Select3(hn::Gt(move, maxMove), capped, delta);
            delta = Select3(hn::IsFinite(move), delta, Zero3(d));
            v2 = Add3(v2, delta);
            eta = hn::Max(hn::Sub(eta, hn::Set(d, job.decayTau)), hn::Zero(d));
            Validate(d, v0, up, h, invH, v1, v2);
            if (!job.colliders->empty()) {
                V3 hitV2 = v2;
                const M hit = Collide(d, job, i, v0, up, h, v1, hitV2, eta);
                if (!hn::AllFalse(d, hit)) {
                    V3 hitV1 = v1;
                    Validate(d, v0, up, h, invH, hitV1, hitV2);
                    v1 = Select3(hit, hitV1, v1);
                    v2 = Select3(hit, hitV2, v2);
                }
            }
        }
        v1 = Select3(atRest, v1Start, v1);
        v2 = Select3(atRest, v2Start, v2);
        eta = hn::IfThenElse(atRest, etaStart, eta);
        const V results[7] = {v1.x, v1.y, v1.z, v2.x, v2.y, v2.z, eta};
        for (int f = 0; f < 7; ++f)
            hn::Store(results[f], d, out[f]);
        for (std::size_t l = 0; l < lanes; ++l) {
            if (!simd[l])
                continue;
            Blade& b = job.blades[first + l];
            b.v1H = glm::vec4(out[0][l], out[1][l], out[2][l], b.v1H.w);
            b.v2W = glm::vec4(out[3][l], out[4][l], out[5][l], b.v2W.w);
            job.eta[first + l] = out[6][l];
        }
    }
}

std::size_t LaneCount() {
    return hn::Lanes(D());
}

std::int64_t Target() {
    return HWY_TARGET;
}

}  // namespace HWY_NAMESPACE
}  // namespace grass::core::simd_step
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace grass::core {
namespace simd_step {
HWY_EXPORT(StepBlocks);
HWY_EXPORT(LaneCount);
HWY_EXPORT(Target);

// Below this many blocks a task, waking a worker costs more than it saves.
constexpr std::size_t MIN_BLOCKS_PER_TASK = 64;

Job makeJob(const PhysicsParams& params, const std::vector<WindSource>& wind,
            const std::vector<SphereCollider>& colliders, float timeS) {
    Job job;
    job.params = &params;
    job.wind = &wind;
    job.colliders = &colliders;
    job.timeS = timeS;
    job.substeps = substepCount(params);
    job.tau = job.substeps > 0 ? params.dtS / static_cast<float>(job.substeps) : 0.0f;
    job.gravityW = std::isfinite(params.gravity.w) ? params.gravity.w : 0.0f;
    const float decayPerS = std::isfinite(params.etaDecayPerS) ? params.etaDecayPerS : 0.0f;
    job.decayTau = decayPerS * job.tau;
    job.restSkip = wind.empty() && colliders.empty();
    const auto safeNormalize = [](glm::vec3 v) {
        const float len = glm::length(v);
        return (len > 1e-20f && std::isfinite(len)) ? v / len : glm::vec3(0.0f);
    };
    std::vector<const WindSource*> blowing;
    for (const WindSource& w : wind) {
        if (!(w.strength != 0.0f))
            continue;  // windAt gives no wind for it
        Source s;
        s.kind = w.kind;
        s.dir = safeNormalize(w.kind == WindKind::Vortex ? w.axis : w.direction);
        s.strength = w.strength;
        s.radiusM = w.radiusM;
        s.coreRadiusM = w.coreRadiusM;
        s.wavelengthM = w.wavelengthM;
        s.speedMps = w.speedMps;
        s.gust = w.gust;
        s.cellM = w.wavelengthM > 0.0f ? w.wavelengthM : 10.0f;  // DEFAULT_GUST_CELL_M
        job.sources.push_back(s);
        blowing.push_back(&w);
    }
    for (std::uint32_t i = 0; i < job.substeps; ++i) {
        const float t = timeS + static_cast<float>(i) * job.tau;
        job.times.push_back(t);
        for (const WindSource* w : blowing)
            job.centres.push_back(samplePath(w->path, t, w->position));
        for (const SphereCollider& sphere : colliders) {
            const glm::vec3 c = samplePath(sphere.path, t + job.tau, sphere.centre);
            job.spheres.emplace_back(c, sphere.radiusM);
            job.bounds.push_back(c + sphere.boundOffset);
        }
    }
    return job;
}

}  // namespace simd_step

void stepPhysicsSimd(std::span<Blade> blades, std::span<float> eta,
                     std::span<const glm::vec3> restTips, const PhysicsParams& params,
                     const std::vector<WindSource>& wind,
                     const std::vector<SphereCollider>& colliders, float timeS,
                     unsigned threadCount, GravityLoad load) {
    GRASS_ASSERT(eta.size() == blades.size() && restTips.size() == blades.size());
    GRASS_ASSERT(load.perBlade.empty() || load.perBlade.size() == blades.size());
    simd_step::Job job = simd_step::makeJob(params, wind, colliders, timeS);
    if (job.substeps == 0 || blades.empty()) {
        stepPhysics(blades, eta, restTips, params, wind, colliders, timeS, threadCount, load);
        return;
    }
    job.blades = blades;
    job.eta = eta;
    job.restTips = restTips;
    job.load = load;
    const std::size_t lanes = HWY_DYNAMIC_DISPATCH(simd_step::LaneCount)();
    const std::size_t blocks = blades.size() / lanes;
    ThreadPool& pool = ThreadPool::shared();
    const std::size_t threads = threadCount > 0 ? threadCount : pool.workerCount() + 1;
    const std::size_t tasks =
        std::clamp<std::size_t>(blocks / simd_step::MIN_BLOCKS_PER_TASK, 1, threads);
    pool.run(blocks, tasks, [&job](std::size_t begin, std::size_t end) {
        HWY_DYNAMIC_DISPATCH(simd_step::StepBlocks)(job, begin, end);
    });
    // The last partial block: the scalar reference.
    for (std::size_t i = blocks * lanes; i < blades.size(); ++i)
        stepBlade(blades[i], eta[i], restTips[i], params, wind, colliders, timeS, load.at(i));
}

const char* cpuPhysicsName(CpuPhysics path) {
    return path == CpuPhysics::Scalar ? "scalar" : "simd";
}

void stepPhysicsOn(CpuPhysics path, std::span<Blade> blades, std::span<float> eta,
                   std::span<const glm::vec3> restTips, const PhysicsParams& params,
                   const std::vector<WindSource>& wind,
                   const std::vector<SphereCollider>& colliders, float timeS,
                   unsigned threadCount, GravityLoad load) {
    if (path == CpuPhysics::Scalar)
        stepPhysics(blades, eta, restTips, params, wind, colliders, timeS, threadCount, load);
    else
        stepPhysicsSimd(blades, eta, restTips, params, wind, colliders, timeS, threadCount, load);
}

std::string physicsSimdTarget() {
    return hwy::TargetName(HWY_DYNAMIC_DISPATCH(simd_step::Target)());
}

std::size_t physicsSimdLanes() {
    return HWY_DYNAMIC_DISPATCH(simd_step::LaneCount)();
}

}  // namespace grass::core
#endif
