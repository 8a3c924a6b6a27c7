// cameraRay and projectToPixel (core/scene/camera.h): screen <-> world for picking and gizmos.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/bvh.h"
#include "mesh/procedural.h"
#include "scene/camera.h"
#include "util/rng.h"

namespace grass::core {
namespace {

struct View {
    float yawRad, pitchRad;
};
// Side, 3/4 above, nearly straight down, from below, from behind.
constexpr View VIEWS[] = {
    {0.0f, 0.0f}, {0.785f, 0.45f}, {2.0f, 1.55f}, {-1.2f, -0.7f}, {3.1f, 0.2f}};
const glm::vec2 VIEWPORT(1280.0f, 720.0f);

OrbitCamera cameraAt(View view) {
    OrbitCamera camera;
    camera.target = glm::vec3(1.0f, 0.5f, -2.0f);
    camera.distance = 12.0f;
    camera.yawRad = view.yawRad;
    camera.pitchRad = view.pitchRad;
    camera.fovYRad = 0.9f;
    return camera;
}

float distanceToRay(const Ray& ray, glm::vec3 p) {
    const glm::vec3 d = p - ray.origin;
    return glm::length(d - glm::dot(d, ray.direction) * ray.direction);
}

TEST(CameraRay, PixelToRayToPixelRoundTrips) {
    for (const View view : VIEWS) {
        const OrbitCamera camera = cameraAt(view);
        Rng rng(5);
        for (int i = 0; i < 200; ++i) {
            const glm::vec2 pixel(rng.uniform(0.0f, VIEWPORT.x), rng.uniform(0.0f, VIEWPORT.y));
            const Ray ray = cameraRay(camera, pixel, VIEWPORT);
            EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-5f);
            EXPECT_NEAR(glm::length(ray.origin - camera.position()), 0.0f, 1e-5f);
            const float t = rng.uniform(0.5f, 40.0f);
            const auto back = projectToPixel(camera, ray.at(t), VIEWPORT);
            ASSERT_TRUE(back) << "yaw " << view.yawRad << " pitch " << view.pitchRad;
            EXPECT_NEAR(back->x, pixel.x, 2e-2f) << "yaw " << view.yawRad << " t " << t;
            EXPECT_NEAR(back->y, pixel.y, 2e-2f) << "yaw " << view.yawRad << " t " << t;
        }
    }
}

TEST(CameraRay, WorldToPixelToRayPassesThroughThePoint) {
    for (const View view : VIEWS) {
        const OrbitCamera camera = cameraAt(view);
        Rng rng(6);
        for (int i = 0; i < 200; ++i) {
            const glm::vec3 p = camera.target + glm::vec3(rng.uniform(-4, 4), rng.uniform(-4, 4),
                                                          rng.uniform(-4, 4));
            const auto pixel = projectToPixel(camera, p, VIEWPORT);
            ASSERT_TRUE(pixel);
            const Ray ray = cameraRay(camera, *pixel, VIEWPORT);
            EXPECT_LT(distanceToRay(ray, p), 1e-4f * glm::length(p - ray.origin))
                << "yaw " << view.yawRad << " pitch " << view.pitchRad << " i " << i;
            EXPECT_GT(glm::dot(p - ray.origin, ray.direction), 0.0f);
        }
    }
}

TEST(CameraRay, MatchesTheProjectionMatrix) {
    // The pixel of a point is where the renderer's matrices put it (GL: y up, so flipped).
    const OrbitCamera camera = cameraAt(VIEWS[1]);
    const glm::vec3 p(2.0f, 1.0f, -3.0f);
    const glm::vec4 clip =
        camera.projection(VIEWPORT.x / VIEWPORT.y) * camera.view() * glm::vec4(p, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const auto pixel = projectToPixel(camera, p, VIEWPORT);
    ASSERT_TRUE(pixel);
    EXPECT_NEAR(pixel->x, (ndc.x + 1.0f) * 0.5f * VIEWPORT.x, 1e-3f);
    EXPECT_NEAR(pixel->y, (1.0f - ndc.y) * 0.5f * VIEWPORT.y, 1e-3f);
    // The top-left corner of the viewport is up and to the left of the view direction.
    const Ray corner = cameraRay(camera, {0.0f, 0.0f}, VIEWPORT);
    const glm::mat4 v = camera.view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
    EXPECT_LT(glm::dot(corner.direction, right), 0.0f);
    EXPECT_GT(glm::dot(corner.direction, up), 0.0f);
    // Its vertical half-angle is half the field of view.
    const Ray top = cameraRay(camera, {0.5f * VIEWPORT.x, 0.0f}, VIEWPORT);
    const glm::vec3 forward = glm::normalize(camera.target - camera.position());
    EXPECT_NEAR(std::acos(glm::dot(top.direction, forward)), 0.5f * camera.fovYRad, 1e-4f);
}

TEST(CameraRay, BehindTheCameraHasNoPixel) {
    const OrbitCamera camera = cameraAt(VIEWS[1]);
    const glm::vec3 eye = camera.position();
    const glm::vec3 behind = eye + (eye - camera.target);
    EXPECT_FALSE(projectToPixel(camera, behind, VIEWPORT));
    EXPECT_FALSE(projectToPixel(camera, eye, VIEWPORT));
}

TEST(CameraRay, ScreenCentreHitsTheTargetOnAPlane) {
    const TriangleBvh plane(makeProceduralMesh(ProceduralMeshParams{}));
    // From below too: the plane's underside is hit (no backface culling). A level camera sees
    // the plane edge-on: no hit to test.
    for (const View view : VIEWS) {
        if (view.pitchRad == 0.0f)
            continue;
        OrbitCamera camera = cameraAt(view);
        camera.target = glm::vec3(1.5f, 0.0f, -2.5f);
        const auto hit = plane.intersect(cameraRay(camera, 0.5f * VIEWPORT, VIEWPORT));
        ASSERT_TRUE(hit) << "pitch " << view.pitchRad;
        EXPECT_NEAR(glm::length(hit->posWorld - camera.target), 0.0f, 1e-4f)
            << "yaw " << view.yawRad << " pitch " << view.pitchRad;
        EXPECT_NEAR(hit->t, camera.distance, 1e-4f);
    }
}

}  // namespace
}  // namespace grass::core
