#include "growth/growth_curves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "util/rng.h"

namespace grass::core {
namespace {

constexpr float PI = std::numbers::pi_v<float>;
constexpr float NAN_F = std::numeric_limits<float>::quiet_NaN();
constexpr float INF_F = std::numeric_limits<float>::infinity();

struct NamedField {
    const char* name;
    float GrowthCurves::*member;
};

constexpr std::array<NamedField, 13> FIELDS = {{
    {"gy0", &GrowthCurves::gy0},
    {"gy1", &GrowthCurves::gy1},
    {"gy2", &GrowthCurves::gy2},
    {"wy0", &GrowthCurves::wy0},
    {"wy1", &GrowthCurves::wy1},
    {"wy2", &GrowthCurves::wy2},
    {"wy3", &GrowthCurves::wy3},
    {"wy4", &GrowthCurves::wy4},
    {"hy0", &GrowthCurves::hy0},
    {"hy1", &GrowthCurves::hy1},
    {"hy2", &GrowthCurves::hy2},
    {"hy3", &GrowthCurves::hy3},
    {"hy4", &GrowthCurves::hy4},
}};

float bezier(float y0, float y1, float y2, float t) {
    return (1 - t) * (1 - t) * y0 + 2 * (1 - t) * t * y1 + t * t * y2;
}

GrowthCurves randomCurves(std::uint64_t seed) {
    Rng rng(seed);
    GrowthCurves c;
    for (const NamedField& f : FIELDS) {
        c.*(f.member) = rng.uniform();
    }
    return c;
}

GrowthCurves uniformCurves(float gy, float wy, float hy) {
    return GrowthCurves{gy, gy, gy, wy, wy, wy, wy, wy, hy, hy, hy, hy, hy};
}

// The paper's θ before our clamp, from the unclamped gamma that growthParams reports.
float rawTheta(const GrowthParams& p) {
    return PI * p.gamma / 1.75f / 3.0f;
}

// The paper's evaluation of a two-piece light curve: both pieces take the raw l.
float paperTwoPiece(float y0, float y1, float y2, float y3, float y4, float l) {
    return l <= 0.3f ? bezier(y0, y1, y2, l) : bezier(y2, y3, y4, l);
}

// Control sets at the corners of [0, 1]: every curve constant 0 or 1, plus mixed patterns.
std::vector<GrowthCurves> extremeCurves() {
    std::vector<GrowthCurves> sets;
    for (int mask = 0; mask < 8; ++mask) {
        sets.push_back(
            uniformCurves(float(mask & 1), float((mask >> 1) & 1), float((mask >> 2) & 1)));
    }
    sets.push_back(GrowthCurves{1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1});
    sets.push_back(GrowthCurves{0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0});
    sets.push_back(GrowthCurves{0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1});
    sets.push_back(GrowthCurves{1, 1, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0});
    sets.push_back(GrowthCurves{});
    return sets;
}

void expectParamsInRange(const GrowthParams& p, const std::string& where) {
    EXPECT_TRUE(std::isfinite(p.alpha) && std::isfinite(p.beta) && std::isfinite(p.theta) &&
                std::isfinite(p.b))
        << where;
    EXPECT_GE(p.alpha, 0.0f) << where;
    EXPECT_LE(p.alpha, 0.25f) << where;
    EXPECT_GE(p.beta, 0.0f) << where;
    EXPECT_LE(p.beta, 1.0f) << where;
    EXPECT_GE(p.theta, 0.0f) << where;
    EXPECT_LE(p.theta, PI / 3.0f) << where;
    EXPECT_GE(p.b, 0.0f) << where;
    EXPECT_LE(p.b, 1.0f) << where;
}

TEST(GrowthCurves, DefaultsAreValid) {
    EXPECT_TRUE(validate(GrowthCurves{}).ok());
}

TEST(GrowthCurves, EqualityComparesEveryField) {
    for (const NamedField& f : FIELDS) {
        GrowthCurves c;
        EXPECT_EQ(c, GrowthCurves{});
        c.*(f.member) += 0.01f;
        EXPECT_NE(c, GrowthCurves{}) << f.name;
    }
}

TEST(GrowthCurves, SoilCurveIsTheBezierThroughItsEnds) {
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        const GrowthCurves c = randomCurves(seed);
        EXPECT_FLOAT_EQ(soilCurve(c, 0.0f), c.gy0) << "seed " << seed;
        EXPECT_FLOAT_EQ(soilCurve(c, 1.0f), c.gy2) << "seed " << seed;
        EXPECT_NEAR(soilCurve(c, 0.5f), 0.25f * c.gy0 + 0.5f * c.gy1 + 0.25f * c.gy2, 1e-6f)
            << "seed " << seed;
        EXPECT_NEAR(soilCurve(c, 0.2f), bezier(c.gy0, c.gy1, c.gy2, 0.2f), 1e-6f)
            << "seed " << seed;
    }
}

TEST(GrowthCurves, LightCurvesPassThroughEndsAndJoint) {
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        const GrowthCurves c = randomCurves(seed);
        EXPECT_FLOAT_EQ(widthLightCurve(c, 0.0f), c.wy0) << "seed " << seed;
        EXPECT_NEAR(widthLightCurve(c, 0.3f), c.wy2, 1e-6f) << "seed " << seed;
        EXPECT_FLOAT_EQ(widthLightCurve(c, 1.0f), c.wy4) << "seed " << seed;
        EXPECT_FLOAT_EQ(heightLightCurve(c, 0.0f), c.hy0) << "seed " << seed;
        EXPECT_NEAR(heightLightCurve(c, 0.3f), c.hy2, 1e-6f) << "seed " << seed;
        EXPECT_FLOAT_EQ(heightLightCurve(c, 1.0f), c.hy4) << "seed " << seed;
    }
}

TEST(GrowthCurves, LightCurvePiecesAreReparameterisedBeziers) {
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        const GrowthCurves c = randomCurves(seed);
        // l = 0.15 is the middle of piece 1 (t = 0.5), l = 0.65 the middle of piece 2.
        EXPECT_NEAR(widthLightCurve(c, 0.15f), bezier(c.wy0, c.wy1, c.wy2, 0.5f), 1e-6f);
        EXPECT_NEAR(widthLightCurve(c, 0.65f), bezier(c.wy2, c.wy3, c.wy4, 0.5f), 1e-6f);
        EXPECT_NEAR(heightLightCurve(c, 0.15f), bezier(c.hy0, c.hy1, c.hy2, 0.5f), 1e-6f);
        EXPECT_NEAR(heightLightCurve(c, 0.65f), bezier(c.hy2, c.hy3, c.hy4, 0.5f), 1e-6f);
        // l = 0.5 is t = 2/7 on piece 2.
        EXPECT_NEAR(heightLightCurve(c, 0.5f), bezier(c.hy2, c.hy3, c.hy4, 2.0f / 7.0f), 1e-6f)
            << "seed " << seed;
    }
}

TEST(GrowthCurves, LightCurvesAreContinuousAtTheJoint) {
    // |f'| <= 2/0.3 on piece 1 and 2/0.7 on piece 2 for control values in [0, 1], so a step of
    // eps either side moves f by at most eps·(2/0.3 + 2/0.7) < 1e-3; float rounding adds ~1e-6.
    const float eps = 1e-4f;
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        const GrowthCurves c = randomCurves(seed);
        EXPECT_LT(std::abs(widthLightCurve(c, 0.3f - eps) - widthLightCurve(c, 0.3f + eps)), 1e-3f)
            << "seed " << seed;
        EXPECT_LT(std::abs(heightLightCurve(c, 0.3f - eps) - heightLightCurve(c, 0.3f + eps)),
                  1e-3f)
            << "seed " << seed;
    }
}

TEST(GrowthCurves, PaperRawParameterJumpsAtTheJoint) {
    // Why we re-parameterise: with the raw l the default width curve jumps by ~0.39 at 0.3.
    const GrowthCurves c;
    const float eps = 1e-4f;
    const float before = paperTwoPiece(c.wy0, c.wy1, c.wy2, c.wy3, c.wy4, 0.3f - eps);
    const float after = paperTwoPiece(c.wy0, c.wy1, c.wy2, c.wy3, c.wy4, 0.3f + eps);
    EXPECT_GT(std::abs(after - before), 0.3f);
    EXPECT_LT(std::abs(widthLightCurve(c, 0.3f - eps) - widthLightCurve(c, 0.3f + eps)), 1e-3f);
}

// Kim & Cho §3.2: little light, narrow and relatively tall grass; strong light, wide and short.
TEST(GrowthCurves, DefaultsWidenAndShortenWithLightAndAreSmoothAtTheJoint) {
    const GrowthCurves c;
    for (int i = 1; i <= 100; ++i) {
        const float x0 = float(i - 1) / 100.0f, x1 = float(i) / 100.0f;
        EXPECT_GT(soilCurve(c, x1), soilCurve(c, x0)) << x1;
        EXPECT_GT(widthLightCurve(c, x1), widthLightCurve(c, x0)) << x1;
        EXPECT_LT(heightLightCurve(c, x1), heightLightCurve(c, x0)) << x1;
    }
    // One-sided slopes at the joint agree (C1): the defaults have no kink at l = 0.3.
    const float h = 1e-3f;
    const float leftW = (widthLightCurve(c, 0.3f) - widthLightCurve(c, 0.3f - h)) / h;
    const float rightW = (widthLightCurve(c, 0.3f + h) - widthLightCurve(c, 0.3f)) / h;
    EXPECT_NEAR(leftW, rightW, 0.02f);
    const float leftH = (heightLightCurve(c, 0.3f) - heightLightCurve(c, 0.3f - h)) / h;
    const float rightH = (heightLightCurve(c, 0.3f + h) - heightLightCurve(c, 0.3f)) / h;
    EXPECT_NEAR(leftH, rightH, 0.02f);
}

TEST(GrowthCurves, OutOfRangeAndNanInputsAreClamped) {
    const GrowthCurves c = randomCurves(7);
    for (const float low : {-1.0f, -1e-6f, -INF_F, NAN_F}) {
        EXPECT_EQ(soilCurve(c, low), soilCurve(c, 0.0f)) << low;
        EXPECT_EQ(widthLightCurve(c, low), widthLightCurve(c, 0.0f)) << low;
        EXPECT_EQ(heightLightCurve(c, low), heightLightCurve(c, 0.0f)) << low;
    }
    for (const float high : {1.0f + 1e-6f, 2.0f, INF_F}) {
        EXPECT_EQ(soilCurve(c, high), soilCurve(c, 1.0f)) << high;
        EXPECT_EQ(widthLightCurve(c, high), widthLightCurve(c, 1.0f)) << high;
        EXPECT_EQ(heightLightCurve(c, high), heightLightCurve(c, 1.0f)) << high;
    }
    EXPECT_EQ(growthParams(c, NAN_F, 5.0f), growthParams(c, 0.0f, 1.0f));
}

TEST(GrowthCurves, ValidateRejectsBadValuesNamingTheField) {
    for (const NamedField& f : FIELDS) {
        for (const float bad : {NAN_F, INF_F, -INF_F, -0.01f, 1.01f, 5.0f}) {
            GrowthCurves c;
            c.*(f.member) = bad;
            const Result<void> r = validate(c);
            ASSERT_FALSE(r.ok()) << f.name << " = " << bad;
            EXPECT_EQ(r.error().path, f.name) << bad;
            EXPECT_NE(r.error().message.find("[0, 1]"), std::string::npos) << r.error().str();
        }
        for (const float good : {0.0f, 1.0f}) {
            GrowthCurves c;
            c.*(f.member) = good;
            EXPECT_TRUE(validate(c).ok()) << f.name << " = " << good;
        }
    }
}

TEST(GrowthParams, FormulasMatchSpec) {
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        const GrowthCurves c = randomCurves(seed);
        Rng rng(seed, 1);
        const float g = rng.uniform(), l = rng.uniform();
        const float f1 = soilCurve(c, g), f2 = widthLightCurve(c, l), f3 = heightLightCurve(c, l);
        const GrowthParams p = growthParams(c, g, l);
        const float alpha = (f1 + f2) / 8.0f, beta = (f1 + f3) / 2.0f;
        EXPECT_NEAR(p.alpha, alpha, 1e-6f) << "seed " << seed;
        EXPECT_NEAR(p.beta, beta, 1e-6f) << "seed " << seed;
        EXPECT_NEAR(p.gamma, beta - alpha + f3, 1e-6f) << "seed " << seed;
        EXPECT_NEAR(p.theta, std::clamp(PI * (beta - alpha + f3) / 1.75f / 3.0f, 0.0f, PI / 3),
                    1e-6f)
            << "seed " << seed;
        EXPECT_NEAR(p.b, (f1 + (f2 + f3) / 2.0f) / 2.0f, 1e-6f) << "seed " << seed;
    }
}

TEST(GrowthParams, RangesHoldOverADenseGrid) {
    std::vector<GrowthCurves> sets = extremeCurves();
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        sets.push_back(randomCurves(seed));
    }
    for (std::size_t s = 0; s < sets.size(); ++s) {
        for (int i = 0; i <= 100; ++i) {
            for (int j = 0; j <= 100; ++j) {
                const float g = float(i) / 100.0f, l = float(j) / 100.0f;
                expectParamsInRange(growthParams(sets[s], g, l), "set " + std::to_string(s) +
                                                                     " g " + std::to_string(g) +
                                                                     " l " + std::to_string(l));
            }
        }
    }
}

TEST(GrowthParams, ThetaClampIsExercisedAtTheExtremes) {
    // f1 = 0, f2 = 1, f3 = 0: gamma = −1/8, the paper's θ = −π/42 ≈ −0.024π (SPEC: −0.02π).
    const GrowthParams low = growthParams(uniformCurves(0, 1, 0), 0.5f, 0.5f);
    EXPECT_NEAR(low.gamma, -0.125f, 1e-6f);
    EXPECT_NEAR(rawTheta(low) / PI, -1.0f / 42.0f, 1e-6f);
    EXPECT_LT(rawTheta(low), 0.0f);
    EXPECT_EQ(low.theta, 0.0f);
    // f1 = 1, f2 = 0, f3 = 1: gamma = 15/8, the paper's θ = 5π/14 ≈ 0.357π > π/3.
    const GrowthParams high = growthParams(uniformCurves(1, 0, 1), 0.5f, 0.5f);
    EXPECT_NEAR(high.gamma, 1.875f, 1e-6f);
    EXPECT_NEAR(rawTheta(high) / PI, 0.357f, 5e-4f);
    EXPECT_GT(rawTheta(high), PI / 3.0f);
    EXPECT_FLOAT_EQ(high.theta, PI / 3.0f);
    // And these are the extremes: over all extreme sets and the grid, the raw θ stays within them.
    for (const GrowthCurves& c : extremeCurves()) {
        for (int i = 0; i <= 20; ++i) {
            for (int j = 0; j <= 20; ++j) {
                const float raw = rawTheta(growthParams(c, float(i) / 20, float(j) / 20));
                EXPECT_GE(raw, rawTheta(low) - 1e-6f);
                EXPECT_LE(raw, rawTheta(high) + 1e-6f);
            }
        }
    }
}

TEST(GrowthParams, UnvalidatedControlValuesStayInRange) {
    const std::vector<GrowthCurves> bad = {
        uniformCurves(5, 5, 5),       uniformCurves(-3, -3, -3),  uniformCurves(NAN_F, 0, 0),
        uniformCurves(0, NAN_F, 0),   uniformCurves(0, 0, NAN_F), uniformCurves(INF_F, 1, 1),
        uniformCurves(-INF_F, -1, 2), uniformCurves(1, -10, 10),
    };
    for (std::size_t s = 0; s < bad.size(); ++s) {
        EXPECT_FALSE(validate(bad[s]).ok()) << "set " << s;
        for (const float g : {0.0f, 0.3f, 1.0f}) {
            for (const float l : {0.0f, 0.3f, 0.7f, 1.0f}) {
                expectParamsInRange(growthParams(bad[s], g, l), "bad set " + std::to_string(s));
            }
        }
    }
}

// Soil: taller, wider, healthier. Light (Kim & Cho §3.2): wider and shorter; b stays, since the
// default f2 and f3 mirror each other (f2 + f3 = 1.1 at every l) and b averages them.
TEST(GrowthParams, DefaultsGrowTallerWiderHealthierWithSoilAndWiderShorterWithLight) {
    const GrowthCurves c;
    for (int i = 1; i <= 20; ++i) {
        const float lo = float(i - 1) / 20, hi = float(i) / 20;
        for (const float other : {0.0f, 0.5f, 1.0f}) {
            const GrowthParams soilLo = growthParams(c, lo, other),
                               soilHi = growthParams(c, hi, other);
            EXPECT_GT(soilHi.alpha, soilLo.alpha);
            EXPECT_GT(soilHi.beta, soilLo.beta);
            EXPECT_GT(soilHi.b, soilLo.b);
            const GrowthParams lightLo = growthParams(c, other, lo);
            const GrowthParams lightHi = growthParams(c, other, hi);
            EXPECT_GT(lightHi.alpha, lightLo.alpha);
            EXPECT_LT(lightHi.beta, lightLo.beta);
            EXPECT_NEAR(lightHi.b, lightLo.b, 1e-6f);
        }
    }
}

TEST(GrowthBlade, MapsParamsToBladeScales) {
    const GrowthParams p = growthParams(GrowthCurves{}, 0.6f, 0.8f);
    const BladeGrowth blade = bladeGrowth(p);
    EXPECT_FLOAT_EQ(blade.heightScale, p.beta);
    EXPECT_FLOAT_EQ(blade.widthScale, p.alpha / 0.25f);
    EXPECT_FLOAT_EQ(blade.restLeanRad, p.theta);
    EXPECT_FLOAT_EQ(blade.colourBlend, p.b);
    // Best conditions give the layer's full height and width and the healthy colour.
    const BladeGrowth best = bladeGrowth(growthParams(uniformCurves(1, 1, 1), 1, 1));
    EXPECT_FLOAT_EQ(best.heightScale, 1.0f);
    EXPECT_FLOAT_EQ(best.widthScale, 1.0f);
    EXPECT_FLOAT_EQ(best.colourBlend, 1.0f);
    const BladeGrowth worst = bladeGrowth(growthParams(uniformCurves(0, 0, 0), 0, 0));
    EXPECT_EQ(worst, (BladeGrowth{0.0f, 0.0f, 0.0f, 0.0f}));
}

TEST(GrowthBlade, ClampsHandFilledParams) {
    const BladeGrowth blade = bladeGrowth(GrowthParams{-1.0f, 2.0f, 0.0f, 5.0f, NAN_F});
    EXPECT_EQ(blade, (BladeGrowth{1.0f, 0.0f, PI / 3.0f, 0.0f}));
    const BladeGrowth other = bladeGrowth(GrowthParams{1.0f, NAN_F, 0.0f, -1.0f, 3.0f});
    EXPECT_EQ(other, (BladeGrowth{0.0f, 1.0f, 0.0f, 1.0f}));
}

// The paper's stated behaviour at the extremes of light, on every soil: in the dark (l = 0) the
// blade is narrower (α) and taller (β) than in full light (l = 1), and it bends more (θ: the
// paper's taller grass bends more); good soil grows taller than poor soil in any light.
TEST(GrowthParams, DefaultsGrowNarrowTallGrassInTheDarkAndWideShortGrassInTheLight) {
    const GrowthCurves c;
    for (const float g : {0.0f, 0.5f, 1.0f}) {
        const GrowthParams dark = growthParams(c, g, 0.0f);
        const GrowthParams bright = growthParams(c, g, 1.0f);
        EXPECT_LT(dark.alpha, bright.alpha) << "soil " << g;
        EXPECT_GT(dark.beta, bright.beta) << "soil " << g;
        EXPECT_GE(dark.theta, bright.theta) << "soil " << g;
    }
    for (const float l : {0.0f, 0.3f, 1.0f})
        EXPECT_GT(growthParams(c, 1.0f, l).beta, growthParams(c, 0.0f, l).beta) << "light " << l;
}

}  // namespace
}  // namespace grass::core
