// K native Highway vectors driven as one wide vector (a "pack"): every operation issues on each
// of the K parts in turn. The physics step is long dependency chains (the validation's square
// roots and divisions, the gust noise's hashes) whose latency, not the vector units, bounds one
// vector of blades; K independent vectors in flight let the core overlap the chains. Measured in
// docs/physics.md (bench_physics, BM_PhysicsSimd_*).
//
// The functions carry Highway's names and argument order, so the step reads as Highway code with
// `pk::` for `hn::`. Only what the step uses is here.
//
// Highway's per-target include guard: this file is included once for every target by
// foreach_target (physics_simd.cpp), inside no namespace.
#if defined(GRASS_CORE_PHYSICS_SIMD_PACK_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef GRASS_CORE_PHYSICS_SIMD_PACK_INL_H_
#undef GRASS_CORE_PHYSICS_SIMD_PACK_INL_H_
#else
#define GRASS_CORE_PHYSICS_SIMD_PACK_INL_H_
#endif

#include <cstddef>

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace grass::core::simd_pack {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The descriptor of a pack of K vectors of the native descriptor DN.
template <class DN, std::size_t K>
struct Tag {
    using Native = DN;
    using T = hn::TFromD<DN>;
    static constexpr std::size_t PARTS = K;
};
template <class DN, std::size_t K>
struct Vec {
    hn::Vec<DN> part[K];
};
template <class DN, std::size_t K>
struct Mask {
    hn::Mask<DN> part[K];
};

// The pack's counterpart of Highway's RebindToSigned / RebindToUnsigned.
template <class D>
using RebindToSigned = Tag<hn::RebindToSigned<typename D::Native>, D::PARTS>;
template <class D>
using RebindToUnsigned = Tag<hn::RebindToUnsigned<typename D::Native>, D::PARTS>;

#define GRASS_PACK_EACH(K) _Pragma("GCC unroll 8") for (std::size_t k = 0; k < (K); ++k)

// Highway's emulated targets (EMU128, SCALAR) convert float to int with a C++ cast, which is
// undefined for NaN; the native instructions define it (the lowest int). The sanitizer builds
// compile EMU128 alone and UBSan stops on it: a degenerate blade's NaN reaches the noise's
// lattice index and the gusts' Sin, whose lanes are then thrown away (such blades take the
// reference's step). So there, and only there, a NaN converts as the native targets convert it
// and the math functions see 0 in its place and hand the NaN back.
#if HWY_TARGET == HWY_EMU128 || HWY_TARGET == HWY_SCALAR
template <class DN, class VN>
HWY_INLINE VN NaNAs(DN dn, VN a, float value) {
    return hn::IfThenElse(hn::Eq(a, a), a, hn::Set(dn, value));
}
template <class VN>
HWY_INLINE VN KeepNaN(VN a, VN r) {
    return hn::IfThenElse(hn::Eq(a, a), r, a);
}
#else
template <class DN, class VN>
HWY_INLINE VN NaNAs(DN, VN a, float) {
    return a;
}
template <class VN>
HWY_INLINE VN KeepNaN(VN, VN r) {
    return r;
}
#endif

template <class DN, std::size_t K>
HWY_INLINE std::size_t Lanes(Tag<DN, K>) {
    return K * hn::Lanes(DN());
}
template <class DN, std::size_t K>
HWY_INLINE Vec<DN, K> Set(Tag<DN, K>, hn::TFromD<DN> value) {
    Vec<DN, K> r;
    const hn::Vec<DN> v = hn::Set(DN(), value);
    GRASS_PACK_EACH(K) r.part[k] = v;
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE Vec<DN, K> Zero(Tag<DN, K> d) {
    return Set(d, hn::TFromD<DN>(0));
}
template <class DN, std::size_t K>
HWY_INLINE Vec<DN, K> Load(Tag<DN, K>, const hn::TFromD<DN>* HWY_RESTRICT aligned) {
    const DN dn;
    Vec<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::Load(dn, aligned + k * hn::Lanes(dn));
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE void Store(Vec<DN, K> v, Tag<DN, K>, hn::TFromD<DN>* HWY_RESTRICT aligned) {
    const DN dn;
    GRASS_PACK_EACH(K) hn::Store(v.part[k], dn, aligned + k * hn::Lanes(dn));
}
template <class DN, std::size_t K>
HWY_INLINE Mask<DN, K> FirstN(Tag<DN, K>, std::size_t n) {
    const DN dn;
    const std::size_t lanes = hn::Lanes(dn);
    Mask<DN, K> r;
    GRASS_PACK_EACH(K) {
        const std::size_t start = k * lanes;
        r.part[k] = hn::FirstN(dn, n > start ? n - start : 0);
    }
    return r;
}

#define GRASS_PACK_UNARY(Op)                              \
    template <class DN, std::size_t K>                    \
    HWY_INLINE Vec<DN, K> Op(Vec<DN, K> a) {              \
        Vec<DN, K> r;                                     \
        GRASS_PACK_EACH(K) r.part[k] = hn::Op(a.part[k]); \
        return r;                                         \
    }
#define GRASS_PACK_BINARY(Op)                                        \
    template <class DN, std::size_t K>                               \
    HWY_INLINE Vec<DN, K> Op(Vec<DN, K> a, Vec<DN, K> b) {           \
        Vec<DN, K> r;                                                \
        GRASS_PACK_EACH(K) r.part[k] = hn::Op(a.part[k], b.part[k]); \
        return r;                                                    \
    }
#define GRASS_PACK_TERNARY(Op)                                                  \
    template <class DN, std::size_t K>                                          \
    HWY_INLINE Vec<DN, K> Op(Vec<DN, K> a, Vec<DN, K> b, Vec<DN, K> c) {        \
        Vec<DN, K> r;                                                           \
        GRASS_PACK_EACH(K) r.part[k] = hn::Op(a.part[k], b.part[k], c.part[k]); \
        return r;                                                               \
    }
#define GRASS_PACK_COMPARE(Op)                                       \
    template <class DN, std::size_t K>                               \
    HWY_INLINE Mask<DN, K> Op(Vec<DN, K> a, Vec<DN, K> b) {          \
        Mask<DN, K> r;                                               \
        GRASS_PACK_EACH(K) r.part[k] = hn::Op(a.part[k], b.part[k]); \
        return r;                                                    \
    }
#define GRASS_PACK_MASK_BINARY(Op)                                   \
    template <class DN, std::size_t K>                               \
    HWY_INLINE Mask<DN, K> Op(Mask<DN, K> a, Mask<DN, K> b) {        \
        Mask<DN, K> r;                                               \
        GRASS_PACK_EACH(K) r.part[k] = hn::Op(a.part[k], b.part[k]); \
        return r;                                                    \
    }
#define GRASS_PACK_MATH(Op)                                   \
    template <class DN, std::size_t K>                        \
    HWY_INLINE Vec<DN, K> Op(Tag<DN, K>, Vec<DN, K> a) {      \
        const DN dn;                                          \
        Vec<DN, K> r;                                         \
        GRASS_PACK_EACH(K) r.part[k] =                        \
            KeepNaN(a.part[k], hn::Op(dn, NaNAs(dn, a.part[k], 0.0f)));               \
        return r;                                             \
    }

GRASS_PACK_UNARY(Neg)
GRASS_PACK_UNARY(Abs)
GRASS_PACK_UNARY(Sqrt)
GRASS_PACK_UNARY(Floor)
GRASS_PACK_UNARY(Trunc)
GRASS_PACK_UNARY(ApproximateReciprocal)
GRASS_PACK_UNARY(ApproximateReciprocalSqrt)
GRASS_PACK_BINARY(Add)
GRASS_PACK_BINARY(Sub)
GRASS_PACK_BINARY(Mul)
GRASS_PACK_BINARY(Div)
GRASS_PACK_BINARY(Min)
GRASS_PACK_BINARY(Max)
GRASS_PACK_BINARY(Xor)
GRASS_PACK_TERNARY(MulAdd)
GRASS_PACK_TERNARY(NegMulAdd)
GRASS_PACK_COMPARE(Eq)
GRASS_PACK_COMPARE(Ne)
GRASS_PACK_COMPARE(Lt)
GRASS_PACK_COMPARE(Le)
GRASS_PACK_COMPARE(Gt)
GRASS_PACK_COMPARE(Ge)
GRASS_PACK_MASK_BINARY(And)
GRASS_PACK_MASK_BINARY(Or)
GRASS_PACK_MATH(Sin)
GRASS_PACK_MATH(Cos)
GRASS_PACK_MATH(Expm1)

#undef GRASS_PACK_UNARY
#undef GRASS_PACK_BINARY
#undef GRASS_PACK_TERNARY
#undef GRASS_PACK_COMPARE
#undef GRASS_PACK_MASK_BINARY
#undef GRASS_PACK_MATH

template <int BITS, class DN, std::size_t K>
HWY_INLINE Vec<DN, K> ShiftRight(Vec<DN, K> a) {
    Vec<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::ShiftRight<BITS>(a.part[k]);
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE Mask<DN, K> IsFinite(Vec<DN, K> a) {
    Mask<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::IsFinite(a.part[k]);
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE Mask<DN, K> Not(Mask<DN, K> a) {
    Mask<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::Not(a.part[k]);
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE Vec<DN, K> IfThenElse(Mask<DN, K> m, Vec<DN, K> yes, Vec<DN, K> no) {
    Vec<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::IfThenElse(m.part[k], yes.part[k], no.part[k]);
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE Vec<DN, K> IfThenElseZero(Mask<DN, K> m, Vec<DN, K> yes) {
    Vec<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::IfThenElseZero(m.part[k], yes.part[k]);
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE Vec<DN, K> IfThenZeroElse(Mask<DN, K> m, Vec<DN, K> no) {
    Vec<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::IfThenZeroElse(m.part[k], no.part[k]);
    return r;
}
template <class DN, std::size_t K>
HWY_INLINE bool AllFalse(Tag<DN, K>, Mask<DN, K> m) {
    bool all = true;
    GRASS_PACK_EACH(K) all = all && hn::AllFalse(DN(), m.part[k]);
    return all;
}
template <class DN, std::size_t K>
HWY_INLINE bool AllTrue(Tag<DN, K>, Mask<DN, K> m) {
    bool all = true;
    GRASS_PACK_EACH(K) all = all && hn::AllTrue(DN(), m.part[k]);
    return all;
}
// Lanes of the mask as vectors of all-one bits (true) or zero (false).
template <class DN, std::size_t K>
HWY_INLINE Vec<DN, K> VecFromMask(Tag<DN, K>, Mask<DN, K> m) {
    Vec<DN, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::VecFromMask(DN(), m.part[k]);
    return r;
}
template <class DTo, class DFrom, std::size_t K>
HWY_INLINE Vec<DTo, K> ConvertTo(Tag<DTo, K>, Vec<DFrom, K> a) {
    Vec<DTo, K> r;
    if constexpr (hwy::IsFloat<hn::TFromD<DFrom>>()) {
        const DFrom from;
        GRASS_PACK_EACH(K) r.part[k] = hn::ConvertTo(DTo(), NaNAs(from, a.part[k], -2147483648.0f));
    } else {
        GRASS_PACK_EACH(K) r.part[k] = hn::ConvertTo(DTo(), a.part[k]);
    }
    return r;
}
template <class DTo, class DFrom, std::size_t K>
HWY_INLINE Vec<DTo, K> BitCast(Tag<DTo, K>, Vec<DFrom, K> a) {
    Vec<DTo, K> r;
    GRASS_PACK_EACH(K) r.part[k] = hn::BitCast(DTo(), a.part[k]);
    return r;
}

#undef GRASS_PACK_EACH

}  // namespace HWY_NAMESPACE
}  // namespace grass::core::simd_pack
HWY_AFTER_NAMESPACE();

#endif  // per-target include guard
