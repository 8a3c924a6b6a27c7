#include "scene/camera.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace grass::core {
namespace {

// Projects a world point to normalized device coordinates.
glm::vec3 toNdc(const OrbitCamera& camera, glm::vec3 p, float aspect) {
    const glm::vec4 clip = camera.projection(aspect) * camera.view() * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
}

TEST(Camera, LookAtReproducesEyeAndTarget) {
    const glm::vec3 eye(14, 7, 14), target(0, 0.5f, 0);
    const OrbitCamera camera = OrbitCamera::lookAt(eye, target, 0.8f);
    EXPECT_NEAR(glm::length(camera.position() - eye), 0.0f, 1e-4f);
    const glm::vec3 ndc = toNdc(camera, target, 16.0f / 9.0f);
    EXPECT_NEAR(ndc.x, 0.0f, 1e-5f);
    EXPECT_NEAR(ndc.y, 0.0f, 1e-5f);
}

TEST(Camera, FramedBoundsAreInsideTheView) {
    const Bounds bounds{{-3, -1, -2}, {5, 4, 7}};
    const OrbitCamera camera = frameBounds(bounds, 0.785f);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1 ? bounds.max.x : bounds.min.x,
                          corner & 2 ? bounds.max.y : bounds.min.y,
                          corner & 4 ? bounds.max.z : bounds.min.z);
        const glm::vec3 ndc = toNdc(camera, p, 1.0f);
        EXPECT_LE(std::abs(ndc.x), 1.0f) << corner;
        EXPECT_LE(std::abs(ndc.y), 1.0f) << corner;
        EXPECT_GE(ndc.z, -1.0f) << "behind the near plane, corner " << corner;
        EXPECT_LE(ndc.z, 1.0f) << "beyond the far plane, corner " << corner;
    }
}

TEST(Camera, OrbitKeepsDistanceAndClampsPitch) {
    OrbitCamera camera;
    const float distance = glm::length(camera.position() - camera.target);
    camera.orbit(300.0f, 100000.0f);
    EXPECT_NEAR(glm::length(camera.position() - camera.target), distance, 1e-3f);
    EXPECT_LT(camera.pitchRad, 1.5708f);
    camera.orbit(0.0f, -200000.0f);
    EXPECT_GT(camera.pitchRad, -1.5708f);
}

TEST(Camera, ZoomIsMultiplicativeAndBounded) {
    OrbitCamera camera;
    camera.distance = 10.0f;
    camera.zoom(1.0f);
    EXPECT_NEAR(camera.distance, 9.0f, 1e-4f);
    camera.zoom(-1.0f);
    EXPECT_NEAR(camera.distance, 10.0f, 1e-4f);
    camera.zoom(1e6f);
    EXPECT_GE(camera.distance, 1e-3f);
}

TEST(Camera, PanKeepsThePointUnderTheCursor) {
    OrbitCamera camera = OrbitCamera::lookAt({0, 0, 10}, {0, 0, 0}, 0.785f);
    const float viewportHeight = 600.0f;
    // A world point 100 px to the right of the centre must be at the centre after panning
    // the cursor 100 px to the left... i.e. the scene follows the cursor.
    const glm::vec3 before = toNdc(camera, {1, 0, 0}, 1.0f);
    camera.pan(-100.0f, 0.0f, viewportHeight);
    const glm::vec3 after = toNdc(camera, {1, 0, 0}, 1.0f);
    const float movedPixels = (after.x - before.x) * 0.5f * viewportHeight;
    EXPECT_NEAR(movedPixels, -100.0f, 1.0f);
}

TEST(Camera, UprightSheetIsSeenFromTheFrontItFaces) {
    // A quad in the XY plane facing +Z (as glTF samples often are).
    SurfaceMeshBuilder builder;
    const auto a = builder.addVertex({0, 0, 0}, {0, 0, 1}, {0, 0});
    const auto b = builder.addVertex({1, 0, 0}, {0, 0, 1}, {1, 0});
    const auto c = builder.addVertex({1, 1, 0}, {0, 0, 1}, {1, 1});
    const auto d = builder.addVertex({0, 1, 0}, {0, 0, 1}, {0, 1});
    builder.addTriangle(a, b, c);
    builder.addTriangle(a, c, d);
    const SurfaceMesh mesh = builder.take();
    const glm::vec3 direction = preferredViewDirection(mesh);
    EXPECT_GT(direction.z, 0.7f) << "the camera must be in front of the sheet";
    const OrbitCamera camera = frameBounds(meshBounds(mesh), 0.785f, direction);
    EXPECT_GT(camera.position().z, camera.target.z);
}

TEST(Camera, ClosedObjectKeepsTheThreeQuarterView) {
    SurfaceMeshBuilder builder;
    // A tetrahedron: face normals sum to zero.
    const glm::vec3 p[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    std::uint32_t v[4];
    for (int i = 0; i < 4; ++i)
        v[i] = builder.addVertex(p[i], {}, {});
    builder.addTriangle(v[0], v[1], v[2]);
    builder.addTriangle(v[0], v[3], v[1]);
    builder.addTriangle(v[0], v[2], v[3]);
    builder.addTriangle(v[1], v[3], v[2]);
    const OrbitCamera standard;
    const glm::vec3 expected = glm::normalize(standard.position() - standard.target);
    EXPECT_NEAR(glm::length(preferredViewDirection(builder.take()) - expected), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace grass::core
