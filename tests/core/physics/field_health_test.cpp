#include "physics/field_health.h"
#include "physics/physics.h"

#include <gtest/gtest.h>

#include <limits>

namespace grass::core {
namespace {

TEST(FieldHealth, RestFieldIsHealthyAndStill) {
    const std::vector<Blade> blades{makeRestBlade({0, 0, 0}, {0, 1, 0}, 0.5f, 0.01f, 10.0f, 0.0f),
                                    makeRestBlade({1, 0, 0}, {0, 1, 0}, 0.3f, 0.01f, 10.0f, 1.0f)};
    const std::vector<float> eta(2, 0.0f);
    const FieldHealth health = measureHealth(blades, eta, restTips(blades));
    EXPECT_EQ(health.blades, 2u);
    EXPECT_EQ(health.nonfinite, 0u);
    EXPECT_EQ(health.belowGround, 0u);
    EXPECT_EQ(health.crushed, 0u);
    EXPECT_LT(health.maxRelLengthError, 1e-6);
    EXPECT_EQ(health.maxTipDisplacementM, 0.0);
}

TEST(FieldHealth, CountsEveryProblem) {
    Blade bent = makeRestBlade({0, 0, 0}, {0, 1, 0}, 1.0f, 0.01f, 10.0f, 0.0f);
    const glm::vec3 rest = bent.v2();
    bent.v2W = glm::vec4(0.6f, -0.1f, 0.0f, bent.w());  // below ground, and too short
    bent.v1H = glm::vec4(0.0f, 0.2f, 0.0f, bent.h());
    Blade broken = bent;
    broken.v1H.x = std::numeric_limits<float>::quiet_NaN();
    Blade padding = makeRestBlade({0, 0, 0}, {0, 1, 0}, 0.0f, 0.0f, 0.0f, 0.0f);
    const std::vector<Blade> blades{bent, broken, padding};
    const std::vector<float> eta{0.5f, 0.0f, 0.0f};
    const std::vector<glm::vec3> tips{rest, rest, padding.v0()};
    const FieldHealth health = measureHealth(blades, eta, tips);
    EXPECT_EQ(health.blades, 1u);  // the NaN blade and the padding are not live
    EXPECT_EQ(health.nonfinite, 1u);
    EXPECT_EQ(health.belowGround, 1u);
    EXPECT_EQ(health.crushed, 1u);
    EXPECT_DOUBLE_EQ(health.crushedShare(), 1.0);
    const double expectedLength = bladeLengthEstimate(bent);
    EXPECT_NEAR(health.maxRelLengthError, std::abs(expectedLength - 1.0), 1e-6);
    EXPECT_NEAR(health.meanRelLengthError(), std::abs(expectedLength - 1.0), 1e-6);
    EXPECT_NEAR(health.maxLengthErrorPerTolerance,
                std::abs(expectedLength - 1.0) / lengthTolerance(bent), 1e-3);
    EXPECT_NEAR(health.maxTipDisplacementM, glm::length(bent.v2() - rest), 1e-6);
    EXPECT_NEAR(health.meanTipDisplacementM(), glm::length(bent.v2() - rest), 1e-6);
}

TEST(FieldHealth, LengthToleranceGrowsWithDistanceFromOrigin) {
    const Blade nearOrigin = makeRestBlade({0, 0, 0}, {0, 1, 0}, 0.5f, 0.01f, 10.0f, 0.0f);
    const Blade farAway = makeRestBlade({-1000, 2, 30}, {0, 1, 0}, 0.5f, 0.01f, 10.0f, 0.0f);
    const float eps = std::numeric_limits<float>::epsilon();
    EXPECT_FLOAT_EQ(lengthTolerance(nearOrigin), 1e-4f * 0.5f + 4.0f * eps * 0.5f);
    EXPECT_FLOAT_EQ(lengthTolerance(farAway), 1e-4f * 0.5f + 4.0f * eps * 1000.5f);
    // A blade stretched by twice its tolerance reads 2; a rest blade well under 1.
    Blade stretched = nearOrigin;
    const float scale = 1.0f + 2.0f * lengthTolerance(nearOrigin) / 0.5f;
    stretched.v1H = glm::vec4(scale * glm::vec3(stretched.v1H), stretched.h());
    stretched.v2W = glm::vec4(scale * glm::vec3(stretched.v2W), stretched.w());
    const std::vector<Blade> blades{nearOrigin, stretched};
    const std::vector<float> eta(2, 0.0f);
    const FieldHealth health = measureHealth(blades, eta, restTips(blades));
    EXPECT_NEAR(health.maxLengthErrorPerTolerance, 2.0, 1e-2);
    const FieldHealth rest = measureHealth(std::span(blades).first(1), std::span(eta).first(1),
                                           restTips(std::vector<Blade>{nearOrigin}));
    EXPECT_LT(rest.maxLengthErrorPerTolerance, 0.1);
}

TEST(FieldHealth, AddCombinesLayers) {
    FieldHealth a;
    a.blades = 2;
    a.crushed = 1;
    a.sumTipDisplacementM = 1.0;
    a.maxTipDisplacementM = 0.7;
    FieldHealth b;
    b.blades = 2;
    b.sumTipDisplacementM = 0.2;
    b.maxTipDisplacementM = 0.1;
    b.maxRelLengthError = 1e-5;
    b.sumRelLengthError = 4e-5;
    b.maxLengthErrorPerTolerance = 0.2;
    a.add(b);
    EXPECT_EQ(a.blades, 4u);
    EXPECT_DOUBLE_EQ(a.crushedShare(), 0.25);
    EXPECT_DOUBLE_EQ(a.meanTipDisplacementM(), 0.3);
    EXPECT_DOUBLE_EQ(a.maxTipDisplacementM, 0.7);
    EXPECT_DOUBLE_EQ(a.maxRelLengthError, 1e-5);
    EXPECT_DOUBLE_EQ(a.meanRelLengthError(), 1e-5);
    EXPECT_DOUBLE_EQ(a.maxLengthErrorPerTolerance, 0.2);
}

}  // namespace
}  // namespace grass::core
