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

// Native vectors a block steps together (simd_pack-inl.h), and the most float lanes of a block on
// any target (AVX-512: 16 a vector). The sanitizer build (tests/fuzz) sets 1: the three-part
// step, inlined once per instruction set, took clang's instrumented -O1 over 15 minutes and
// 4 GB to compile; one part is the same code and checks the same paths.
#ifndef GRASS_PHYSICS_PACK_PARTS
#define GRASS_PHYSICS_PACK_PARTS 3
#endif
constexpr std::size_t PACK_PARTS = GRASS_PHYSICS_PACK_PARTS;
constexpr std::size_t MAX_LANES = 16 * PACK_PARTS;

struct Source {
    WindKind kind = WindKind::Directional;
    glm::vec3 dir{0.0f};  // directional: safeNormalize(direction); vortex: safeNormalize(axis)
    float strength = 0.0f, radiusM = 0.0f, coreRadiusM = 0.0f, wavelengthM = 0.0f, speedMps = 0.0f,
          gust = 0.0f, cellM = 0.0f;
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
    bool restSkip = false;           // no wind and no colliders: a blade at rest is left alone
    std::vector<float> times;        // t of each substep
    std::vector<Source> sources;     // the wind sources that blow (strength ≠ 0)
    std::vector<glm::vec3> centres;  // [substep · sources + k], at t
    std::vector<glm::vec4> spheres;  // [substep · colliders + j]: centre at t + τ, radius
    std::vector<glm::vec3> bounds;   // [substep · colliders + j]: the group's bound centre
};

}  // namespace grass::core::simd_step
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "physics/physics_simd.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

// clang-format off
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>
// clang-format on

#include "physics/simd_pack-inl.h"

HWY_BEFORE_NAMESPACE();
namespace grass::core::simd_step {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace pk = grass::core::simd_pack::HWY_NAMESPACE;

// A block is PACK_PARTS native vectors of blades stepped together (simd_pack-inl.h: their
// dependency chains overlap).
using DN = hn::ScalableTag<float>;
using D = pk::Tag<DN, PACK_PARTS>;
using DI = pk::RebindToSigned<D>;
using DU = pk::RebindToUnsigned<D>;
using V = pk::Vec<DN, PACK_PARTS>;
using VU = pk::Vec<hn::RebindToUnsigned<DN>, PACK_PARTS>;
using M = pk::Mask<DN, PACK_PARTS>;

struct V3 {
    V x, y, z;
};

HWY_INLINE V3 Splat3(D d, glm::vec3 v) {
    return {pk::Set(d, v.x), pk::Set(d, v.y), pk::Set(d, v.z)};
}
HWY_INLINE V3 Add3(V3 a, V3 b) {
    return {pk::Add(a.x, b.x), pk::Add(a.y, b.y), pk::Add(a.z, b.z)};
}
HWY_INLINE V3 Sub3(V3 a, V3 b) {
    return {pk::Sub(a.x, b.x), pk::Sub(a.y, b.y), pk::Sub(a.z, b.z)};
}
HWY_INLINE V3 Scale3(V3 a, V s) {
    return {pk::Mul(a.x, s), pk::Mul(a.y, s), pk::Mul(a.z, s)};
}
// Fused multiply-adds where the target has them: one rounding less than the reference's
// products and sums (it rounds each), well inside the agreement tolerance.
HWY_INLINE V Dot3(V3 a, V3 b) {
    return pk::MulAdd(a.z, b.z, pk::MulAdd(a.y, b.y, pk::Mul(a.x, b.x)));
}
HWY_INLINE V Length3(V3 a) {
    return pk::Sqrt(Dot3(a, a));
}
HWY_INLINE V3 Cross3(V3 a, V3 b) {
    return {pk::Sub(pk::Mul(a.y, b.z), pk::Mul(a.z, b.y)),
            pk::Sub(pk::Mul(a.z, b.x), pk::Mul(a.x, b.z)),
            pk::Sub(pk::Mul(a.x, b.y), pk::Mul(a.y, b.x))};
}
HWY_INLINE V3 Select3(M m, V3 yes, V3 no) {
    return {pk::IfThenElse(m, yes.x, no.x), pk::IfThenElse(m, yes.y, no.y),
            pk::IfThenElse(m, yes.z, no.z)};
}
HWY_INLINE V3 Zero3(D d) {
    return {pk::Zero(d), pk::Zero(d), pk::Zero(d)};
}
HWY_INLINE M Finite3(V3 a) {
    return pk::And(pk::And(pk::IsFinite(a.x), pk::IsFinite(a.y)), pk::IsFinite(a.z));
}
// v / |v|, or 0 when |v| is tiny or not finite (the reference's safeNormalize).
HWY_INLINE V3 SafeNormalize3(D d, V3 v) {
    const V len = Length3(v);
    const M ok = pk::And(pk::Gt(len, pk::Set(d, 1e-20f)), pk::IsFinite(len));
    return Select3(ok, V3{pk::Div(v.x, len), pk::Div(v.y, len), pk::Div(v.z, len)}, Zero3(d));
}
// glm::normalize: v · (1 / sqrt(v·v)).
HWY_INLINE V3 Normalize3(D d, V3 v) {
    return Scale3(v, pk::Div(pk::Set(d, 1.0f), pk::Sqrt(Dot3(v, v))));
}

// core::widthDirection: the tangent basis of up (a reference axis not parallel to it) at θ.
HWY_INLINE V3 WidthDirection(D d, V3 up, V theta) {
    const M useY = pk::Lt(pk::Abs(up.y), pk::Set(d, 0.9f));
    const V3 reference{pk::IfThenZeroElse(useY, pk::Set(d, 1.0f)),
                       pk::IfThenElseZero(useY, pk::Set(d, 1.0f)), pk::Zero(d)};
    const V3 t = Normalize3(d, Cross3(reference, up));
    const V3 b = Cross3(up, t);
    return Add3(Scale3(t, pk::Cos(d, theta)), Scale3(b, pk::Sin(d, theta)));
}

// The wind module's value noise (wind.cpp): lowbias32 of the lattice indices, quintic fade. The
// hash starts from x·A ^ y·B ^ z·C; the products of a cell's neighbours (x + 1)·A = x·A + A are
// sums (the same bits: arithmetic mod 2³²), so the eight corners take three multiplies, not 24.
HWY_INLINE V LatticeValue(D d, VU hashed) {
    const DU du;
    const DI di;
    VU h = hashed;
    h = pk::Xor(h, pk::ShiftRight<16>(h));
    h = pk::Mul(h, pk::Set(du, 0x7feb352du));
    h = pk::Xor(h, pk::ShiftRight<15>(h));
    h = pk::Mul(h, pk::Set(du, 0x846ca68bu));
    h = pk::Xor(h, pk::ShiftRight<16>(h));
    return pk::Mul(pk::ConvertTo(d, pk::BitCast(di, pk::ShiftRight<8>(h))),
                   pk::Set(d, 1.0f / 16777215.0f));
}
HWY_INLINE V Fade(D d, V t) {
    const V inner = pk::Add(pk::Mul(t, pk::Sub(pk::Mul(t, pk::Set(d, 6.0f)), pk::Set(d, 15.0f))),
                            pk::Set(d, 10.0f));
    return pk::Mul(pk::Mul(pk::Mul(t, t), t), inner);
}
HWY_INLINE V Lerp(V a, V b, V u) {
    return pk::Add(a, pk::Mul(pk::Sub(b, a), u));
}
// fmod(x, 65536): exact (x itself) while |x| < 65536 (1/65536 is a power of two: exact).
HWY_INLINE V WrapNoisePeriod(D d, V x) {
    return pk::Sub(
        x, pk::Mul(pk::Set(d, 65536.0f), pk::Trunc(pk::Mul(x, pk::Set(d, 1.0f / 65536.0f)))));
}
// The lattice index of a cell, as the reference's uint32(int(cell) + 65536).
HWY_INLINE VU LatticeIndex(V cell) {
    const DI di;
    return pk::BitCast(DU(), pk::Add(pk::ConvertTo(di, cell), pk::Set(di, 65536)));
}
HWY_INLINE V ValueNoise3(D d, V3 p) {
    const DU du;
    const V qx = WrapNoisePeriod(d, p.x), qy = WrapNoisePeriod(d, p.y),
            qz = WrapNoisePeriod(d, p.z);
    const V cx = pk::Floor(qx), cy = pk::Floor(qy), cz = pk::Floor(qz);
    const VU ix = LatticeIndex(cx), iy = LatticeIndex(cy), iz = LatticeIndex(cz);
    const V ux = Fade(d, pk::Sub(qx, cx)), uy = Fade(d, pk::Sub(qy, cy)),
            uz = Fade(d, pk::Sub(qz, cz));
    const VU ax = pk::Mul(ix, pk::Set(du, 0x8da6b343u)), by = pk::Mul(iy, pk::Set(du, 0xd8163841u)),
             cz0 = pk::Mul(iz, pk::Set(du, 0xcb1ab31fu));
    const VU ax1 = pk::Add(ax, pk::Set(du, 0x8da6b343u)),
             by1 = pk::Add(by, pk::Set(du, 0xd8163841u));
    const VU xy00 = pk::Xor(ax, by), xy10 = pk::Xor(ax1, by), xy01 = pk::Xor(ax, by1),
             xy11 = pk::Xor(ax1, by1);
    V zs[2];
    for (int dz = 0; dz < 2; ++dz) {
        const VU zc = dz == 0 ? cz0 : pk::Add(cz0, pk::Set(du, 0xcb1ab31fu));
        const V c00 = LatticeValue(d, pk::Xor(xy00, zc)), c10 = LatticeValue(d, pk::Xor(xy10, zc));
        const V c01 = LatticeValue(d, pk::Xor(xy01, zc)), c11 = LatticeValue(d, pk::Xor(xy11, zc));
        zs[dz] = Lerp(Lerp(c00, c10, ux), Lerp(c01, c11, ux), uy);
    }
    return Lerp(zs[0], zs[1], uz);
}

// (1 − (r/R)²)² inside R, 0 outside, 1 for R ≤ 0; the core's linear ramp.
HWY_INLINE V Falloff(D d, V r, float radiusM) {
    if (radiusM <= 0.0f)
        return pk::Set(d, 1.0f);
    const V rr = pk::Mul(r, pk::Set(d, 1.0f / radiusM));
    const V q = pk::Sub(pk::Set(d, 1.0f), pk::Mul(rr, rr));
    return pk::IfThenZeroElse(pk::Ge(r, pk::Set(d, radiusM)), pk::Mul(q, q));
}
HWY_INLINE V CoreRamp(D d, V r, float coreRadiusM) {
    if (!(coreRadiusM > 0.0f))
        return pk::Set(d, 1.0f);
    return pk::Min(pk::Mul(r, pk::Set(d, 1.0f / coreRadiusM)), pk::Set(d, 1.0f));
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
            V magnitude = pk::Set(d, s.strength);
            const V3 dir = Splat3(d, s.dir);
            if (s.wavelengthM > 0.0f) {
                // Divided as the reference divides: the wave's phase is where the windiest
                // extremes are most sensitive to rounding.
                const V phase = pk::Div(pk::Mul(pk::Set(d, 6.28318530717958647692f),
                                                pk::Sub(Dot3(dir, p), pk::Set(d, s.speedMps * t))),
                                        pk::Set(d, s.wavelengthM));
                magnitude = pk::Mul(
                    magnitude,
                    pk::Add(pk::Set(d, 0.5f), pk::Mul(pk::Set(d, 0.5f), pk::Sin(d, phase))));
            }
            if (s.gust > 0.0f) {
                const V3 moved = Sub3(p, Scale3(dir, pk::Set(d, s.speedMps * t)));
                const V n = ValueNoise3(d, Scale3(moved, pk::Set(d, 1.0f / s.cellM)));
                const float g = std::clamp(s.gust, 0.0f, 1.0f);
                magnitude =
                    pk::Mul(magnitude, pk::Add(pk::Set(d, 1.0f - g), pk::Mul(pk::Set(d, g), n)));
            }
            const V r = s.radiusM > 0.0f ? Length3(Sub3(p, centre)) : pk::Zero(d);
            result = Scale3(dir, pk::Mul(magnitude, Falloff(d, r, s.radiusM)));
        } else if (s.kind == WindKind::Point) {
            const V3 delta = Sub3(p, centre);
            const V r = Length3(delta);
            result = Scale3(SafeNormalize3(d, delta),
                            pk::Mul(pk::Mul(pk::Set(d, s.strength), CoreRamp(d, r, s.coreRadiusM)),
                                    Falloff(d, r, s.radiusM)));
        } else {
            const V3 axis = Splat3(d, s.dir);
            const V3 delta = Sub3(p, centre);
            const V3 radial = Sub3(delta, Scale3(axis, Dot3(delta, axis)));
            const V r = Length3(radial);
            result = Scale3(SafeNormalize3(d, Cross3(axis, radial)),
                            pk::Mul(pk::Mul(pk::Set(d, s.strength), CoreRamp(d, r, s.coreRadiusM)),
                                    Falloff(d, r, s.radiusM)));
        }
        sum = Add3(sum, Select3(Finite3(result), result, Zero3(d)));
    }
    return sum;
}

// sqrt(x) for x ≥ 0 without the divider: the approximate reciprocal square root and one Newton
// step (relative error ~2e-7, a few ulp). x = 0 gives 0; a non-finite x stays non-finite.
HWY_INLINE V FastSqrt(D d, V x) {
#if HWY_TARGET == HWY_SCALAR
    (void)d;
    return pk::Sqrt(x);  // one lane: no divider to spare, and its approximation is coarser
#endif
    const V y = pk::ApproximateReciprocalSqrt(pk::Max(x, pk::Set(d, 1.17549435e-38f)));
    const V xy = pk::Mul(x, y);
    return pk::Mul(xy, pk::NegMulAdd(pk::Mul(pk::Set(d, 0.5f), xy), y, pk::Set(d, 1.5f)));
}
HWY_INLINE V FastLength3(D d, V3 a) {
    return FastSqrt(d, Dot3(a, a));
}
// 1 / x for finite x ≠ 0: the approximate reciprocal and one Newton step (a few ulp); 0 and
// ±∞ give NaN, which the validation reads as a blade to stand straight.
HWY_INLINE V FastReciprocal(D d, V x) {
#if HWY_TARGET == HWY_SCALAR
    return pk::Div(pk::Set(d, 1.0f), x);
#endif
    const V y = pk::ApproximateReciprocal(x);
    return pk::Mul(y, pk::NegMulAdd(x, y, pk::Set(d, 2.0f)));
}

// The least height the SIMD step takes (below it, the reference's step: see StepBlocks).
constexpr float MIN_SIMD_HEIGHT = 1e-30f;

// Validation 1–3 of SPEC §3 (core::validateBlade), four passes; h ≥ MIN_SIMD_HEIGHT and
// |up| = 1 in every lane.
//
// The same passes on scalars: a pass only scales d2, and d1 lies along up. So d2 is split once
// into its part along up (u0) and across (length lproj0, |d2| = l00), and pass k works with the
// scale R the passes have applied so far: lproj = R·lproj0, |d2| = R·l00, and, the two parts
// being orthogonal, |d2 − d1| = sqrt(lproj² + (R·u0 − |d1|)²). One square root a pass instead of
// three, and no cancellation where d2 ≈ d1 (the reference's length of a difference). The passes
// are one dependency chain; the fast square root and reciprocal keep it off the divider.
HWY_INLINE void Validate(D d, V3 v0, V3 up, V h, V invH, V3& v1, V3& v2) {
    V3 d2 = Sub3(v2, v0);
    d2 = Sub3(d2, Scale3(up, pk::Min(Dot3(up, d2), pk::Zero(d))));
    const V u0 = Dot3(d2, up);
    const V lproj0 = FastLength3(d, Sub3(d2, Scale3(up, u0)));
    const V l00 = FastLength3(d, d2);
    V scale = pk::Set(d, 1.0f);  // R
    V d1Length = pk::Zero(d);    // |d1| = h·m
    for (int iteration = 0; iteration < 4; ++iteration) {
        const V lproj = pk::Mul(scale, lproj0);
        const V ratio = pk::Mul(lproj, invH);
        const V m = pk::Max(pk::Sub(pk::Set(d, 1.0f), ratio),
                            pk::Mul(pk::Set(d, 0.05f), pk::Max(ratio, pk::Set(d, 1.0f))));
        d1Length = pk::Mul(h, m);
        const V l0 = pk::Mul(scale, l00);
        const V along = pk::Sub(pk::Mul(scale, u0), d1Length);  // (d2 − d1)·up
        const V l1 =
            pk::Add(FastSqrt(d, pk::MulAdd(lproj, lproj, pk::Mul(along, along))), d1Length);
        const V length = pk::Mul(pk::MulAdd(pk::Set(d, 2.0f), l0, l1), pk::Set(d, 1.0f / 3.0f));
        const V r = pk::Mul(h, FastReciprocal(d, length));
        d1Length = pk::Mul(d1Length, r);
        scale = pk::Mul(scale, r);
    }
    const V3 d1 = Scale3(up, d1Length);
    d2 = Scale3(d2, scale);
    // The reference stands a blade straight as soon as a pass meets a length that is not > 0, a
    // ratio that is not finite or a d2 that is not: each of these leaves d2 or d1 non-finite
    // (0·∞, ∞ and NaN persist through the later passes), so one test after the passes finds the
    // same lanes.
    const M straight = pk::Not(pk::And(Finite3(d1), Finite3(d2)));
    const V3 top = Add3(v0, Scale3(up, h));
    v1 = Select3(straight, top, Add3(v0, d1));
    v2 = Select3(straight, top, Add3(v0, d2));
}

// The reference's sphereCorrection: onto the surface of the sphere (c, R) when inside it.
HWY_INLINE V3 SphereCorrection(D d, V3 p, V3 c, V radius, V3 up) {
    const V3 toCentre = Sub3(c, p);
    const V dist = Length3(toCentre);
    const V3 n =
        Select3(pk::Gt(dist, pk::Set(d, 1e-20f)), Scale3(toCentre, pk::Div(pk::Set(d, 1.0f), dist)),
                V3{pk::Neg(up.x), pk::Neg(up.y), pk::Neg(up.z)});
    return Select3(pk::Lt(dist, radius), Scale3(n, pk::Sub(dist, radius)), Zero3(d));
}

// Lanes whose tip or midpoint may lie inside the sphere (c, R). Most spheres within a blade's
// reach touch neither (projects/nature: under the bunny a blade has up to ~730 of its 1000
// spheres within reach, and an upright one ~80 that touch it), and such a sphere leaves the
// blade as it is: no correction, η unchanged. Squared distances only, with a margin (10⁻⁴ of
// R²) far beyond the rounding of the exact test in SphereCorrection, so a lane left out here is
// one the exact test leaves unchanged: the step moves every blade bit for bit as it would
// without this shortcut.
HWY_INLINE M TipOrMidpointWithin(D d, V3 c, V clearSquared, V3 v0, V3 v1, V3 v2) {
    const V3 toTip = Sub3(c, v2);
    const V3 m = Add3(Add3(Scale3(v0, pk::Set(d, 0.25f)), Scale3(v1, pk::Set(d, 0.5f))),
                      Scale3(v2, pk::Set(d, 0.25f)));
    const V3 toMid = Sub3(c, m);
    return pk::Or(pk::Not(pk::Gt(Dot3(toTip, toTip), clearSquared)),
                  pk::Not(pk::Gt(Dot3(toMid, toMid), clearSquared)));
}

HWY_INLINE M TipOrMidpointNear(D d, V3 c, V radius, V3 v0, V3 v1, V3 v2) {
    return TipOrMidpointWithin(d, c, pk::Mul(pk::Mul(radius, radius), pk::Set(d, 1.0f + 1e-4f)),
                               v0, v1, v2);
}

// The same for a whole group: lanes whose tip or midpoint may lie inside the group's bound
// (centre b, radius R ⊇ every sphere of the group). A point farther than R from b is outside
// every sphere of the group, so the group leaves that blade as it is and is skipped, bit for bit
// as testing its spheres would (the blade does not move while its group is walked unless a
// sphere touches it). The margin covers the rounding of the moved centres and of the distances:
// 10⁻³ of R + h, and 10⁻⁶ of the bound's largest coordinate (float rounding grows with distance
// from the origin). Under projects/nature's bunny the chunk bounds then keep a blade's walk to
// the chunks near its tip and midpoint instead of every chunk within reach of its root
// (docs/physics.md, Colliders).
HWY_INLINE M TipOrMidpointNearBound(D d, glm::vec3 b, float radiusM, V h, V3 v0, V3 v1, V3 v2) {
    const float largest = std::max({std::abs(b.x), std::abs(b.y), std::abs(b.z)});
    const V reach = pk::Add(pk::Set(d, radiusM * (1.0f + 1e-3f) + 1e-6f * largest),
                            pk::Mul(pk::Set(d, 1e-3f), h));
    return TipOrMidpointWithin(d, Splat3(d, b), pk::Mul(reach, reach), v0, v1, v2);
}

// core's collide() at the substep's t + τ; the mask of lanes that were hit.
HWY_INLINE M Collide(D d, const Job& job, std::uint32_t substep, V3 v0, V3 up, V h, V3 v1, V3& v2,
                     V& eta) {
    const M all = pk::FirstN(d, pk::Lanes(d));
    M hitAny = pk::Not(all);
    const std::vector<SphereCollider>& colliders = *job.colliders;
    const std::size_t base = substep * colliders.size();
    const V reachH = pk::Mul(pk::Set(d, 1.01f), h);
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
            const V boundReach = pk::Add(pk::Set(d, sphere.boundRadiusM), reachH);
            // NaN bounds fail the comparison and fall through to the exact tests.
            group = pk::And(
                pk::Not(pk::Gt(Dot3(toBound, toBound), pk::Mul(boundReach, boundReach))),
                TipOrMidpointNearBound(d, job.bounds[base + j], sphere.boundRadiusM, h, v0, v1,
                                       v2));
            groupEnd = j + sphere.groupSize;
            if (pk::AllFalse(d, group)) {
                j = groupEnd - 1;
                continue;
            }
        }
        const glm::vec4 centre = job.spheres[base + j];
        if (!(centre.w > 0.0f) || !std::isfinite(centre.x) || !std::isfinite(centre.y) ||
            !std::isfinite(centre.z))
            continue;
        const V3 c = Splat3(d, glm::vec3(centre));
        const V radius = pk::Set(d, centre.w);
        const V reach = pk::Add(radius, reachH);
        const V3 rel = Sub3(c, v0);
        const M active = pk::And(group, pk::Not(pk::Gt(Dot3(rel, rel), pk::Mul(reach, reach))));
        if (pk::AllFalse(d, active))
            continue;
        if (pk::AllFalse(d, pk::And(active, TipOrMidpointNear(d, c, radius, v0, v1, v2))))
            continue;
        V3 moved = v2;
        const V3 dTip = SphereCorrection(d, moved, c, radius, up);
        moved = Add3(moved, dTip);
        const V3 m = Add3(Add3(Scale3(v0, pk::Set(d, 0.25f)), Scale3(v1, pk::Set(d, 0.5f))),
                          Scale3(moved, pk::Set(d, 0.25f)));
        const V3 dMid = SphereCorrection(d, m, c, radius, up);
        moved = Add3(moved, Scale3(dMid, pk::Set(d, 4.0f)));
        const V eta2 = pk::Add(Dot3(dTip, dTip), Dot3(dMid, dMid));
        const M hit = pk::And(active, pk::Gt(eta2, pk::Zero(d)));
        eta = pk::IfThenElse(hit, pk::Min(pk::Add(eta, eta2), pk::Set(d, ETA_MAX)), eta);
        v2 = Select3(hit, moved, v2);
        hitAny = pk::Or(hitAny, hit);
    }
    return hitAny;
}

// The reference's step for blade i (the scalar lanes and the repairs).
HWY_INLINE void stepScalar(const Job& job, std::size_t i) {
    stepBlade(job.blades[i], job.eta[i], job.restTips[i], *job.params, *job.wind, *job.colliders,
              job.timeS, job.load.at(i));
}

// The blade records (four vec4 each: v0 θ | v1 h | v2 w | up s) of `count` blades into lanes:
// in[f][l] = float f of blade l. Four blades at a time by 4×4 transposes of 128-bit vectors
// (the scalar scatter was a fifth of the step's time).
HWY_INLINE void BladesIntoLanes(const Blade* blades, std::size_t count, float (*in)[MAX_LANES]) {
    const float* floats = reinterpret_cast<const float*>(blades);
    constexpr std::size_t STRIDE = sizeof(Blade) / sizeof(float);
    static_assert(STRIDE == 16);
#if HWY_TARGET == HWY_SCALAR
    for (std::size_t l = 0; l < count; ++l)
        for (std::size_t f = 0; f < STRIDE; ++f)
            in[f][l] = floats[l * STRIDE + f];
#else
    const hn::Full128<float> d4;
    for (std::size_t l = 0; l < count; l += 4) {
        for (std::size_t field = 0; field < 4; ++field) {
            const float* row = floats + l * STRIDE + 4 * field;
            const auto r0 = hn::LoadU(d4, row), r1 = hn::LoadU(d4, row + STRIDE),
                       r2 = hn::LoadU(d4, row + 2 * STRIDE), r3 = hn::LoadU(d4, row + 3 * STRIDE);
            const auto t0 = hn::InterleaveLower(d4, r0, r1);  // x0 x1 y0 y1
            const auto t1 = hn::InterleaveLower(d4, r2, r3);  // x2 x3 y2 y3
            const auto t2 = hn::InterleaveUpper(d4, r0, r1);  // z0 z1 w0 w1
            const auto t3 = hn::InterleaveUpper(d4, r2, r3);  // z2 z3 w2 w3
            hn::Store(hn::ConcatLowerLower(d4, t1, t0), d4, in[4 * field] + l);
            hn::Store(hn::ConcatUpperUpper(d4, t1, t0), d4, in[4 * field + 1] + l);
            hn::Store(hn::ConcatLowerLower(d4, t3, t2), d4, in[4 * field + 2] + l);
            hn::Store(hn::ConcatUpperUpper(d4, t3, t2), d4, in[4 * field + 3] + l);
        }
    }
#endif
}

// The inverse for the blade's second and third vec4 (v1 h, v2 w) from out[0..7], written only
// to the blades whose `write` is set.
HWY_INLINE void LanesIntoBlades(const float (*out)[MAX_LANES], const bool* write, std::size_t count,
                                Blade* blades) {
#if HWY_TARGET == HWY_SCALAR
    for (std::size_t l = 0; l < count; ++l) {
        if (write[l]) {
            blades[l].v1H = glm::vec4(out[0][l], out[1][l], out[2][l], out[3][l]);
            blades[l].v2W = glm::vec4(out[4][l], out[5][l], out[6][l], out[7][l]);
        }
    }
#else
    const hn::Full128<float> d4;
    for (std::size_t l = 0; l < count; l += 4) {
        for (std::size_t part = 0; part < 2; ++part) {
            const auto c0 = hn::Load(d4, out[4 * part] + l),
                       c1 = hn::Load(d4, out[4 * part + 1] + l),
                       c2 = hn::Load(d4, out[4 * part + 2] + l),
                       c3 = hn::Load(d4, out[4 * part + 3] + l);
            const auto t0 = hn::InterleaveLower(d4, c0, c1);  // x0 y0 x1 y1
            const auto t1 = hn::InterleaveLower(d4, c2, c3);  // z0 w0 z1 w1
            const auto t2 = hn::InterleaveUpper(d4, c0, c1);  // x2 y2 x3 y3
            const auto t3 = hn::InterleaveUpper(d4, c2, c3);  // z2 w2 z3 w3
            const hn::Vec128<float> blade[4] = {
                hn::ConcatLowerLower(d4, t1, t0), hn::ConcatUpperUpper(d4, t1, t0),
                hn::ConcatLowerLower(d4, t3, t2), hn::ConcatUpperUpper(d4, t3, t2)};
            for (std::size_t b = 0; b < 4; ++b) {
                if (write[l + b]) {
                    float* target = reinterpret_cast<float*>(&blades[l + b]) + 4 * (part + 1);
                    hn::StoreU(blade[b], d4, target);
                }
            }
        }
    }
#endif
}

// Blocks [firstBlock, endBlock) of Lanes(d) blades each.
void StepBlocks(const Job& job, std::size_t firstBlock, std::size_t endBlock) {
    const D d;
    const std::size_t lanes = pk::Lanes(d);
    HWY_ASSERT(lanes <= MAX_LANES);
    const PhysicsParams& params = *job.params;
    // Per lane: v0 θ | v1 h | v2 w | up s | η | rest tip | extra gravity.
    enum Field {
        V0X,
        V0Y,
        V0Z,
        THETA,
        V1X,
        V1Y,
        V1Z,
        H,
        V2X,
        V2Y,
        V2Z,
        W,
        UPX,
        UPY,
        UPZ,
        S,
        ETA,
        TIPX,
        TIPY,
        TIPZ,
        EXTRA,
        FIELD_COUNT
    };
    HWY_ALIGN float in[FIELD_COUNT][MAX_LANES];
    HWY_ALIGN float out[9][MAX_LANES];
    for (std::size_t block = firstBlock; block < endBlock; ++block) {
        const std::size_t first = block * lanes;
        // Into lanes: the blade's 16 floats, then η, the rest tip and the extra gravity.
        BladesIntoLanes(&job.blades[first], lanes, in);
        std::memcpy(in[ETA], &job.eta[first], lanes * sizeof(float));
        for (std::size_t l = 0; l < lanes; ++l) {
            const std::size_t i = first + l;
            in[TIPX][l] = job.restTips[i].x;
            in[TIPY][l] = job.restTips[i].y;
            in[TIPZ][l] = job.restTips[i].z;
            in[EXTRA][l] = job.load.at(i);
        }
        const auto load = [&](int f) HWY_ATTR { return pk::Load(d, in[f]); };
        // The lanes the reference would repair or collapse take its scalar step (all fields
        // finite, h > 0, up of unit length, s ≥ 0, η in [0, ETA_MAX], extra gravity ≥ 0 pass).
        M finite = pk::IsFinite(load(0));
        for (int f = 1; f < FIELD_COUNT; ++f)
            finite = pk::And(finite, pk::IsFinite(load(f)));
        const V upLen2 =
            pk::Add(pk::Add(pk::Mul(load(UPX), load(UPX)), pk::Mul(load(UPY), load(UPY))),
                    pk::Mul(load(UPZ), load(UPZ)));
        // The fast square root and reciprocal of the validation want normal numbers: blades
        // of denormal height and tips beyond 1e15 m take the reference's step.
        const V3 tipOffset{pk::Sub(load(V2X), load(V0X)), pk::Sub(load(V2Y), load(V0Y)),
                           pk::Sub(load(V2Z), load(V0Z))};
        const M ordinary = pk::And(pk::Ge(load(H), pk::Set(d, MIN_SIMD_HEIGHT)),
                                   pk::Lt(Dot3(tipOffset, tipOffset), pk::Set(d, 1e30f)));
        const M simdLanes = pk::And(
            pk::And(pk::And(finite, ordinary),
                    pk::Le(pk::Abs(pk::Sub(upLen2, pk::Set(d, 1.0f))), pk::Set(d, 1e-5f))),
            pk::And(
                pk::And(pk::Ge(load(S), pk::Zero(d)), pk::Ge(load(EXTRA), pk::Zero(d))),
                pk::And(pk::Ge(load(ETA), pk::Zero(d)), pk::Le(load(ETA), pk::Set(d, ETA_MAX)))));
        if (pk::AllFalse(d, simdLanes)) {
            for (std::size_t l = 0; l < lanes; ++l)
                stepScalar(job, first + l);
            continue;
        }
        bool simd[MAX_LANES];
        {
            HWY_ALIGN float bits[MAX_LANES];  // all one bits where true
            pk::Store(pk::VecFromMask(d, simdLanes), d, bits);
            for (std::size_t l = 0; l < lanes; ++l) {
                std::uint32_t word;
                std::memcpy(&word, &bits[l], sizeof word);
                simd[l] = word != 0;
                // The lane still computes, on the blade as it was; its result is not stored.
                if (!simd[l])
                    stepScalar(job, first + l);
            }
        }
        const V3 v0{load(V0X), load(V0Y), load(V0Z)};
        const V3 up{load(UPX), load(UPY), load(UPZ)};
        const V h = load(H), s = load(S);
        const V invH = pk::Div(pk::Set(d, 1.0f), h);  // for the validation's ratio lproj / h
        V3 v1{load(V1X), load(V1Y), load(V1Z)};
        V3 v2{load(V2X), load(V2Y), load(V2Z)};
        V eta = load(ETA);
        const V3 iv2{load(TIPX), load(TIPY), load(TIPZ)};
        const V3 v1Start = v1, v2Start = v2;
        const V etaStart = eta;
        // Nothing acts on a blade at rest (no wind, no colliders, no gravity, η = 0, the tip at
        // its rest): the reference leaves it as it was. A block of such blades is done.
        const V gMagnitudeStart = pk::Add(pk::Set(d, job.gravityW), load(EXTRA));
        const M atRest =
            job.restSkip
                ? pk::And(pk::And(pk::Eq(gMagnitudeStart, pk::Zero(d)), pk::Eq(eta, pk::Zero(d))),
                          pk::And(pk::And(pk::Eq(v2.x, iv2.x), pk::Eq(v2.y, iv2.y)),
                                  pk::Eq(v2.z, iv2.z)))
                : pk::Not(pk::FirstN(d, lanes));
        if (pk::AllTrue(d, pk::Or(atRest, pk::Not(simdLanes))))
            continue;

        // Gravity, constant over the step: gE plus the front gravity 0.25·|gE|·f.
        const V gMagnitude = gMagnitudeStart;
        const M pulled = pk::Ne(gMagnitude, pk::Zero(d));
        V3 gravity = Zero3(d);
        if (!pk::AllFalse(d, pulled)) {
            const V3 g = Splat3(d, glm::vec3(params.gravity));
            const V3 dir =
                SafeNormalize3(d, params.gravityMode == GravityMode::Centre ? Sub3(g, v0) : g);
            const V3 gE = Scale3(dir, gMagnitude);
            const V3 f = SafeNormalize3(d, Cross3(up, WidthDirection(d, up, load(THETA))));
            gravity =
                Add3(gE, Scale3(f, pk::Mul(pk::Set(d, params.frontGravityScale), Length3(gE))));
            gravity = Select3(pk::And(pulled, Finite3(gravity)), gravity, Zero3(d));
        }
        const V maxMove = pk::Mul(pk::Set(d, std::max(params.maxMovePerSubstep, 0.0f)), h);
        const V tau = pk::Set(d, job.tau);
        for (std::uint32_t i = 0; i < job.substeps; ++i) {
            const V3 d2 = Sub3(v2, v0);
            V3 force = gravity;
            if (!job.sources.empty()) {
                const V3 wi = WindAt(d, job, i, v0);
                const M blows = pk::Or(pk::Or(pk::Ne(wi.x, pk::Zero(d)), pk::Ne(wi.y, pk::Zero(d))),
                                       pk::Ne(wi.z, pk::Zero(d)));
                const V fd = pk::Sub(pk::Set(d, 1.0f),
                                     pk::Abs(Dot3(SafeNormalize3(d, wi), SafeNormalize3(d, d2))));
                const V fr = pk::Mul(Dot3(d2, up), invH);
                force = Select3(blows, Add3(force, Scale3(wi, pk::Mul(fd, fr))), force);
            }
            // v2 += (Iv2 − v2)·(1 − e^{−kτ}) + F·(1 − e^{−kτ})/k, and F·τ as k → 0.
            const V k = pk::Mul(s, pk::Max(pk::Sub(pk::Set(d, 1.0f), eta),
                                           pk::Set(d, params.crushedRecoveryFloor)));
            const V kTau = pk::Mul(k, tau);
            const M stiff = pk::Gt(kTau, pk::Set(d, 1e-6f));
            const V relax = pk::IfThenElse(stiff, pk::Neg(pk::Expm1(d, pk::Neg(kTau))), kTau);
            const V phi = pk::IfThenElse(stiff, pk::Div(relax, k), tau);
            V3 delta = Add3(Scale3(Sub3(iv2, v2), relax), Scale3(force, phi));
            const V move = Length3(delta);
            const V3 capped = Scale3(delta, pk::Div(maxMove, move));
            delta = Select3(pk::Gt(move, maxMove), capped, delta);
            delta = Select3(pk::IsFinite(move), delta, Zero3(d));
            v2 = Add3(v2, delta);
            eta = pk::Max(pk::Sub(eta, pk::Set(d, job.decayTau)), pk::Zero(d));
            Validate(d, v0, up, h, invH, v1, v2);
            if (!job.colliders->empty()) {
                V3 hitV2 = v2;
                const M hit = Collide(d, job, i, v0, up, h, v1, hitV2, eta);
                if (!pk::AllFalse(d, hit)) {
                    V3 hitV1 = v1;
                    Validate(d, v0, up, h, invH, hitV1, hitV2);
                    v1 = Select3(hit, hitV1, v1);
                    v2 = Select3(hit, hitV2, v2);
                }
            }
        }
        v1 = Select3(atRest, v1Start, v1);
        v2 = Select3(atRest, v2Start, v2);
        eta = pk::IfThenElse(atRest, etaStart, eta);
        // Back, where the lane was the SIMD step's: out holds the blade's floats 4–11 (v1 h,
        // v2 w, h and w as they came in) and η.
        const V results[9] = {v1.x, v1.y, v1.z, load(H), v2.x, v2.y, v2.z, load(W), eta};
        for (int f = 0; f < 9; ++f)
            pk::Store(results[f], d, out[f]);
        LanesIntoBlades(out, simd, lanes, &job.blades[first]);
        for (std::size_t l = 0; l < lanes; ++l) {
            if (simd[l])
                job.eta[first + l] = out[8][l];
        }
    }
}

std::size_t BlockLanes() {
    return pk::Lanes(D());
}

std::size_t NativeLanes() {
    return hn::Lanes(DN());
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
HWY_EXPORT(BlockLanes);
HWY_EXPORT(NativeLanes);
HWY_EXPORT(Target);

// Every call goes through these, written inside simd_step: HWY_DYNAMIC_DISPATCH names its
// function relative to where it is written, and where one target alone is compiled
// (HWY_COMPILE_ONLY_EMU128 in the sanitizer builds) it becomes N_EMU128::Name, which resolves
// only here.
std::size_t blockLanes() {
    return HWY_DYNAMIC_DISPATCH(BlockLanes)();
}
std::size_t nativeLanes() {
    return HWY_DYNAMIC_DISPATCH(NativeLanes)();
}
std::int64_t target() {
    return HWY_DYNAMIC_DISPATCH(Target)();
}
void stepBlocks(const Job& job, std::size_t firstBlock, std::size_t endBlock) {
    HWY_DYNAMIC_DISPATCH(StepBlocks)(job, firstBlock, endBlock);
}

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
    const std::size_t lanes = simd_step::blockLanes();
    const std::size_t blocks = blades.size() / lanes;
    ThreadPool& pool = ThreadPool::shared();
    const std::size_t threads = threadCount > 0 ? threadCount : pool.workerCount() + 1;
    const std::size_t tasks =
        std::clamp<std::size_t>(blocks / simd_step::MIN_BLOCKS_PER_TASK, 1, threads);
    pool.run(blocks, tasks, [&job](std::size_t begin, std::size_t end) {
        simd_step::stepBlocks(job, begin, end);
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
                   const std::vector<SphereCollider>& colliders, float timeS, unsigned threadCount,
                   GravityLoad load) {
    if (path == CpuPhysics::Scalar)
        stepPhysics(blades, eta, restTips, params, wind, colliders, timeS, threadCount, load);
    else
        stepPhysicsSimd(blades, eta, restTips, params, wind, colliders, timeS, threadCount, load);
}

std::string physicsSimdTarget() {
    return hwy::TargetName(simd_step::target());
}

std::size_t physicsSimdLanes() {
    return simd_step::nativeLanes();
}

}  // namespace grass::core
#endif
