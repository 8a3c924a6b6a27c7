// The width correction of SPEC §7 (core::widthCorrectedT, twin of shapes.glsl): far blades blend
// their shape towards the quad, on both edges, and near blades keep their shape.
#include <gtest/gtest.h>

#include "blade/blade_shape.h"

namespace grass::core {
namespace {

float triangleT(float u, float v) {
    return u + 0.5f * v - u * v;  // SPEC §7's triangle
}

// The blade's area as a share of the quad's: the mean over v of the distance between its edges
// (u = 1 and u = 0), midpoint rule.
float areaShare(float widthPx) {
    constexpr int ROWS = 1000;
    float sum = 0.0f;
    for (int i = 0; i < ROWS; ++i) {
        const float v = (float(i) + 0.5f) / float(ROWS);
        sum += widthCorrectedT(triangleT(1.0f, v), 1.0f, widthPx) -
               widthCorrectedT(triangleT(0.0f, v), 0.0f, widthPx);
    }
    return sum / float(ROWS);
}

TEST(WidthCorrection, ASubPixelTriangleBecomesTheWholeQuad) {
    // Below w_min (1 px) Φ = 1: both edges are the quad's. SPEC's max(t, Φ·u) moved the u = 1
    // edge alone and left 0.75 of the area.
    EXPECT_FLOAT_EQ(widthCorrectionPhi(0.4f), 1.0f);
    for (const float v : {0.0f, 0.3f, 0.9f, 1.0f}) {
        EXPECT_FLOAT_EQ(widthCorrectedT(triangleT(0.0f, v), 0.0f, 0.4f), 0.0f) << v;
        EXPECT_FLOAT_EQ(widthCorrectedT(triangleT(1.0f, v), 1.0f, 0.4f), 1.0f) << v;
    }
    EXPECT_NEAR(areaShare(0.4f), 1.0f, 1e-4f);
}

TEST(WidthCorrection, AWideBladeKeepsItsShapeAndTheBlendIsLinearBetween) {
    // At w_min + span (3 px) and beyond Φ = 0: the triangle keeps its half area.
    EXPECT_FLOAT_EQ(widthCorrectionPhi(3.0f), 0.0f);
    EXPECT_NEAR(areaShare(3.0f), 0.5f, 1e-4f);
    EXPECT_NEAR(areaShare(50.0f), 0.5f, 1e-4f);
    // Halfway (2 px) the area is halfway, and both edges moved alike: the blade stays centred.
    EXPECT_FLOAT_EQ(widthCorrectionPhi(2.0f), 0.5f);
    EXPECT_NEAR(areaShare(2.0f), 0.75f, 1e-4f);
    for (const float v : {0.2f, 0.7f}) {
        const float left = widthCorrectedT(triangleT(0.0f, v), 0.0f, 2.0f);
        const float right = widthCorrectedT(triangleT(1.0f, v), 1.0f, 2.0f);
        EXPECT_NEAR(left + right, 1.0f, 1e-6f) << v;
    }
    // Wider on screen never means wider in the blend.
    float previous = 2.0f;
    for (float px = 0.0f; px < 4.0f; px += 0.25f) {
        const float share = areaShare(px);
        EXPECT_LE(share, previous + 1e-6f) << px;
        previous = share;
    }
}

TEST(WidthCorrection, AnUnknownWidthLeavesTheShapeAlone) {
    EXPECT_FLOAT_EQ(widthCorrectedT(0.35f, 0.0f, -1.0f), 0.35f);
}

}  // namespace
}  // namespace grass::core
