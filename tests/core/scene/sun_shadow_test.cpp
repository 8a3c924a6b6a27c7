// Sun shadows' CPU side (core/scene/sun_shadow.h, issue 30 item 11): the sun's depth map over a
// plane with a ball above it, and the filtered lookup: the ground in the ball's geometric shadow
// is dark, the open ground lit with no self-shadowing, and the penumbra of the filter lies only
// within a texel or two of the shadow's edge. The GPU draws with the same lookup
// (tests/gl/sun_shadow_gl_test.cpp).
#include "scene/sun_shadow.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.h"
#include "support/plane_project.h"

namespace grass::core {
namespace {

constexpr glm::vec3 BALL{0.0f, 1.5f, 0.0f};
constexpr float RADIUS = 0.5f;

Scene ballOverPlane() {
    LoadedProject loaded = test::planeFieldProject({6.0f, 4, 1.0f});
    test::addBall(loaded, BALL, RADIUS);
    auto scene = buildScene(loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return std::move(*scene);
}

// Where the ray from ground point p towards the sun passes nearest the ball's centre.
float missDistance(glm::vec3 p, glm::vec3 toSun) {
    const glm::vec3 d = BALL - p;
    return glm::length(d - toSun * glm::dot(d, toSun));
}

TEST(SunShadow, GroundUnderTheBallIsDarkOpenGroundLit) {
    const Scene scene = ballOverPlane();
    SunDesc sun;
    sun.direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.2f));
    sun.shadowResolution = 512;
    const SnowDepthMap map = sceneSunDepthMap(scene, sun, 0.0f);
    const float bias = sunShadowBiasM(map.view, map.resolution);
    const float texel = map.texelSizeM();
    const glm::vec3 toSun = -sun.direction;
    int shaded = 0, lit = 0;
    for (float x = -2.8f; x <= 2.8f; x += 0.05f)
        for (float z = -2.8f; z <= 2.8f; z += 0.05f) {
            const glm::vec3 p(x, 0.0f, z);
            const float miss = missDistance(p, toSun);
            const float v = sunVisibility(map, p, bias);
            ASSERT_GE(v, 0.0f);
            ASSERT_LE(v, 1.0f);
            // The filter spreads the edge over about two texels of the map (plus the ball's
            // silhouette rasterised to texel centres); beyond that the answer is exact.
            if (miss < RADIUS - 3.0f * texel) {
                EXPECT_EQ(v, 0.0f) << "in the ball's shadow at " << x << ", " << z;
                ++shaded;
            } else if (miss > RADIUS + 3.0f * texel) {
                EXPECT_EQ(v, 1.0f) << "open ground at " << x << ", " << z;
                ++lit;
            }
        }
    EXPECT_GT(shaded, 100);
    EXPECT_GT(lit, 10000);
}

TEST(SunShadow, BladeTipsUnderTheBallAreShadedTheBallsTopIsLit) {
    const Scene scene = ballOverPlane();
    SunDesc sun;
    sun.direction = {0.0f, -1.0f, 0.0f};
    const SnowDepthMap map = sceneSunDepthMap(scene, sun, 0.0f);
    const float bias = sunShadowBiasM(map.view, map.resolution);
    EXPECT_EQ(sunVisibility(map, {0.05f, 0.4f, 0.0f}, bias), 0.0f) << "a tip under the ball";
    EXPECT_EQ(sunVisibility(map, {0.0f, BALL.y + RADIUS, 0.0f}, bias), 1.0f) << "the ball's top";
    EXPECT_EQ(sunVisibility(map, {0.0f, BALL.y - RADIUS, 0.0f}, bias), 0.0f) << "its underside";
    EXPECT_EQ(sunVisibility(map, {2.0f, 0.4f, 2.0f}, bias), 1.0f);
}

TEST(SunShadow, BiasIsTwoTexelsAndTheBlockCarriesTheView) {
    const Scene scene = ballOverPlane();
    SunDesc sun;
    sun.shadowResolution = 1024;
    const OrthoSnowView view = sceneSunView(scene, sun, 0.0f);
    EXPECT_NEAR(sunShadowBiasM(view, 1024), 2.0f * view.sizeM / 1024.0f, 1e-7f);
    LightingBlock block;
    EXPECT_EQ(block.sunShadows, 0) << "off unless enabled";
    enableSunShadows(block, view, 1024);
    EXPECT_EQ(block.sunShadows, 1);
    EXPECT_EQ(block.sunShadowOrigin, view.origin);
    EXPECT_EQ(block.sunShadowForward, view.forward);
    EXPECT_EQ(block.sunShadowSizeM, view.sizeM);
    EXPECT_EQ(block.sunShadowDepthRangeM, view.depthRangeM);
    // The view looks along the light and covers the ball and the plane.
    EXPECT_NEAR(glm::dot(view.forward, glm::normalize(sun.direction)), 1.0f, 1e-6f);
    for (const glm::vec3 p : {glm::vec3(-3, 0, -3), glm::vec3(3, 0, 3), BALL + RADIUS}) {
        const glm::vec3 c = snowMapCoords(view, p);
        EXPECT_GT(c.x, 0.0f);
        EXPECT_LT(c.x, 1.0f);
        EXPECT_GT(c.y, 0.0f);
        EXPECT_LT(c.y, 1.0f);
    }
}

TEST(SunShadow, OutsideTheMapIsLit) {
    SnowDepthMap empty;
    EXPECT_EQ(sunVisibility(empty, glm::vec3(0.0f), 0.01f), 1.0f);
    const Scene scene = ballOverPlane();
    const SnowDepthMap map = sceneSunDepthMap(scene, SunDesc{}, 0.0f);
    EXPECT_EQ(sunVisibility(map, {100.0f, 0.0f, 100.0f}, 0.01f), 1.0f);
}

}  // namespace
}  // namespace grass::core
