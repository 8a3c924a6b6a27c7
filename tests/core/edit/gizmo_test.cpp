#include "edit/gizmo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "edit/gizmo_drag.h"

namespace grass::core {
namespace {

constexpr glm::vec3 AXES[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
constexpr GizmoHandle AXIS_HANDLES[3] = {GizmoHandle::X, GizmoHandle::Y, GizmoHandle::Z};
const glm::vec3 PIVOT(1.0f, 0.5f, -2.0f);

struct Angles {
    float yawRad, pitchRad;
};
// 3/4 view, from below, from behind, straight down (the camera's 89° limit), level along −Z,
// and nearly along +X (the X axis 17° off the view direction).
constexpr Angles ANGLES[] = {{0.785f, 0.45f}, {1.2f, -0.3f}, {2.5f, 1.0f},
                             {-0.7f, 1.553f}, {0.0f, 0.0f},  {1.571f - 0.3f, 0.1f}};

GizmoView viewAt(Angles angles) {
    GizmoView view;
    view.camera.target = glm::vec3(0.0f);
    view.camera.distance = 12.0f;
    view.camera.yawRad = angles.yawRad;
    view.camera.pitchRad = angles.pitchRad;
    view.camera.fovYRad = 0.9f;
    view.viewportSizePixels = glm::vec2(1280.0f, 720.0f);
    return view;
}

std::string describe(Angles angles) {
    return "yaw " + std::to_string(angles.yawRad) + " pitch " + std::to_string(angles.pitchRad);
}

glm::vec2 pixelOf(const GizmoView& view, glm::vec3 p) {
    const auto pixel = projectToPixel(view.camera, p, view.viewportSizePixels);
    EXPECT_TRUE(pixel) << "point behind the camera";
    return pixel.value_or(glm::vec2(0.0f));
}

// |cos| between a direction and the line of sight to the pivot.
float alongSight(const GizmoView& view, glm::vec3 direction) {
    return std::abs(glm::dot(direction, glm::normalize(view.camera.position() - PIVOT)));
}

TEST(GizmoDrag, AxisDragMovesByTheWorldDistance) {
    for (const Angles angles : ANGLES) {
        const GizmoView view = viewAt(angles);
        for (int axis = 0; axis < 3; ++axis) {
            // An axis within ~10° of the line of sight is hidden and not pickable.
            if (alongSight(view, AXES[axis]) > 0.985f)
                continue;
            for (const float d : {1.5f, -0.4f, 3.0f}) {
                for (const float grab : {0.0f, 0.6f}) {
                    const glm::vec3 start = PIVOT + grab * AXES[axis];
                    GizmoDrag drag(GizmoMode::Translate, AXIS_HANDLES[axis], PIVOT, view,
                                   pixelOf(view, start));
                    const glm::vec3 moved =
                        drag.update(pixelOf(view, start + d * AXES[axis])).translationWorld;
                    EXPECT_LT(glm::length(moved - d * AXES[axis]), 1e-3f * std::abs(d))
                        << describe(angles) << " axis " << axis << " d " << d << " grab " << grab;
                }
            }
        }
    }
}

TEST(GizmoDrag, PlaneAndViewDragsMoveByTheVectorInThePlane) {
    const GizmoHandle planes[3] = {GizmoHandle::PlaneXY, GizmoHandle::PlaneYZ,
                                   GizmoHandle::PlaneZX};
    const int spans[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (const Angles angles : ANGLES) {
        const GizmoView view = viewAt(angles);
        for (int p = 0; p < 3; ++p) {
            const glm::vec3 a = AXES[spans[p][0]], b = AXES[spans[p][1]];
            if (alongSight(view, glm::cross(a, b)) < 0.2f)
                continue;  // edge-on: hidden
            const glm::vec3 start = PIVOT + 0.3f * (a + b);
            const glm::vec3 move = 1.2f * a - 0.7f * b;
            GizmoDrag drag(GizmoMode::Translate, planes[p], PIVOT, view, pixelOf(view, start));
            const glm::vec3 moved = drag.update(pixelOf(view, start + move)).translationWorld;
            EXPECT_LT(glm::length(moved - move), 1e-3f * glm::length(move))
                << describe(angles) << " plane " << p;
        }
        // View: the plane through the pivot facing the eye.
        const glm::vec3 n = glm::normalize(view.camera.position() - PIVOT);
        const glm::vec3 u = glm::normalize(glm::cross(n, glm::vec3(0.3f, 0.2f, 1.0f)));
        const glm::vec3 move = 0.8f * u + 0.5f * glm::cross(n, u);
        GizmoDrag drag(GizmoMode::Translate, GizmoHandle::View, PIVOT, view, pixelOf(view, PIVOT));
        const glm::vec3 moved = drag.update(pixelOf(view, PIVOT + move)).translationWorld;
        EXPECT_LT(glm::length(moved - move), 1e-3f * glm::length(move)) << describe(angles);
    }
}

// Drags the mouse around the ring of `axis` (unit, with e1 × e2 = axis) from angle a to b in
// small steps, as a user would.
float dragAround(const GizmoView& view, GizmoHandle handle, glm::vec3 e1, glm::vec3 e2, float a,
                 float b) {
    const auto at = [&](float angleRad) {
        return pixelOf(view, PIVOT + 1.5f * (std::cos(angleRad) * e1 + std::sin(angleRad) * e2));
    };
    GizmoDrag drag(GizmoMode::Rotate, handle, PIVOT, view, at(a));
    constexpr int STEPS = 40;
    for (int i = 1; i <= STEPS; ++i)
        drag.update(at(a + (b - a) * float(i) / float(STEPS)));
    return drag.delta().angleRad;
}

TEST(GizmoDrag, RotationIsTheSweptAngle) {
    for (const Angles angles : ANGLES) {
        const GizmoView view = viewAt(angles);
        for (int axis = 0; axis < 3; ++axis) {
            if (alongSight(view, AXES[axis]) < 0.2f)
                continue;  // ring seen edge-on
            const glm::vec3 e1 = AXES[(axis + 1) % 3], e2 = AXES[(axis + 2) % 3];
            // Including more than half a turn, and more than a full turn backwards.
            for (const auto& [a, b] : {std::pair{0.3f, 1.1f}, {2.0f, 6.2f}, {1.0f, -6.0f}}) {
                EXPECT_NEAR(dragAround(view, AXIS_HANDLES[axis], e1, e2, a, b), b - a, 1e-3f)
                    << describe(angles) << " axis " << axis << " from " << a << " to " << b;
            }
        }
        const glm::vec3 n = glm::normalize(view.camera.position() - PIVOT);
        const glm::vec3 e1 = glm::normalize(glm::cross(n, glm::vec3(0.3f, 0.2f, 1.0f)));
        EXPECT_NEAR(dragAround(view, GizmoHandle::View, e1, glm::cross(n, e1), 0.5f, 2.0f), 1.5f,
                    1e-3f)
            << describe(angles);
    }
}

TEST(GizmoDrag, ViewRotationIsCounterClockwiseOnScreen) {
    const GizmoView view = viewAt(ANGLES[0]);
    const glm::vec2 c = pixelOf(view, PIVOT);
    // Screen y points down: from +x to −y on screen is a counter-clockwise quarter turn.
    GizmoDrag drag(GizmoMode::Rotate, GizmoHandle::View, PIVOT, view, c + glm::vec2(80, 0));
    drag.update(c + glm::vec2(60, -60));
    EXPECT_NEAR(drag.update(c + glm::vec2(0, -80)).angleRad, 1.5708f, 0.05f);
}

TEST(GizmoDrag, ScaleIsTheRatioOfScreenDistances) {
    for (const Angles angles : ANGLES) {
        const GizmoView view = viewAt(angles);
        const glm::vec2 c = pixelOf(view, PIVOT);
        for (int axis = 0; axis < 3; ++axis) {
            if (alongSight(view, AXES[axis]) > 0.985f)
                continue;
            const glm::vec2 grab = pixelOf(view, PIVOT + 0.8f * AXES[axis]);
            GizmoDrag drag(GizmoMode::Scale, AXIS_HANDLES[axis], PIVOT, view, grab);
            glm::vec3 expected(1.0f);
            expected[axis] = 2.0f;
            const glm::vec3 scale = drag.update(c + 2.0f * (grab - c)).scale;
            EXPECT_LT(glm::length(scale - expected), 1e-4f) << describe(angles) << " " << axis;
        }
        GizmoDrag uniform(GizmoMode::Scale, GizmoHandle::View, PIVOT, view, c + glm::vec2(30, 40));
        EXPECT_LT(glm::length(uniform.update(c + glm::vec2(-36, 48)).scale - glm::vec3(1.2f)),
                  1e-5f);
        GizmoDrag plane(GizmoMode::Scale, GizmoHandle::PlaneZX, PIVOT, view, c + glm::vec2(50, 0));
        EXPECT_LT(glm::length(plane.update(c + glm::vec2(100, 0)).scale - glm::vec3(2, 1, 2)),
                  1e-5f);
    }
}

TEST(GizmoDrag, SnappingRoundsTheDeltaToSteps) {
    const GizmoView view = viewAt(ANGLES[0]);
    GizmoSnap snap;
    snap.enabled = true;
    snap.translateStepM = 0.25f;
    for (const auto& [d, snapped] : {std::pair{1.1f, 1.0f}, {1.2f, 1.25f}, {-0.37f, -0.25f}}) {
        GizmoDrag drag(GizmoMode::Translate, GizmoHandle::X, PIVOT, view, pixelOf(view, PIVOT),
                       snap);
        const glm::vec3 moved =
            drag.update(pixelOf(view, PIVOT + glm::vec3(d, 0, 0))).translationWorld;
        EXPECT_NEAR(moved.x, snapped, 1e-6f) << d;
        EXPECT_EQ(moved.y, 0.0f);
        EXPECT_EQ(moved.z, 0.0f);
    }
    // The delta snaps, not the position: an object at x = 1 (off the 0.25 grid) stays off it.
    snap.rotateStepDeg = 15.0f;
    for (const auto& [deg, snappedDeg] :
         {std::pair{37.0f, 30.0f}, {38.0f, 45.0f}, {-8.0f, -15.0f}}) {
        const auto at = [&](float angleRad) {
            return pixelOf(view,
                           PIVOT + 1.5f * glm::vec3(std::cos(angleRad), 0, -std::sin(angleRad)));
        };
        // About +Y, angle θ turns +X towards −Z.
        GizmoDrag drag(GizmoMode::Rotate, GizmoHandle::Y, PIVOT, view, at(0.0f), snap);
        drag.update(at(glm::radians(0.5f * deg)));
        EXPECT_NEAR(drag.update(at(glm::radians(deg))).angleRad, glm::radians(snappedDeg), 1e-5f)
            << deg;
    }
    snap.scaleStep = 0.1f;
    const glm::vec2 c = pixelOf(view, PIVOT);
    for (const auto& [ratio, snapped] : {std::pair{1.26f, 1.3f}, {0.02f, 0.1f}, {2.04f, 2.0f}}) {
        GizmoDrag drag(GizmoMode::Scale, GizmoHandle::View, PIVOT, view, c + glm::vec2(100, 0),
                       snap);
        EXPECT_NEAR(drag.update(c + glm::vec2(100.0f * ratio, 0)).scale.x, snapped, 1e-5f) << ratio;
    }
}

TEST(GizmoDrag, AxisPointingAtTheCameraDoesNotJump) {
    // Looking straight along −X at the pivot: the X axis is seen end-on.
    GizmoView view = viewAt({1.5708f, 0.0f});
    view.camera.target = PIVOT;
    const glm::vec2 c = pixelOf(view, PIVOT);
    GizmoDrag drag(GizmoMode::Translate, GizmoHandle::X, PIVOT, view, c);
    for (const glm::vec2 offset : {glm::vec2(1, 0), glm::vec2(50, 30), glm::vec2(-400, 200)})
        EXPECT_EQ(drag.update(c + offset).translationWorld, glm::vec3(0.0f)) << offset.x;
    GizmoDrag scale(GizmoMode::Scale, GizmoHandle::X, PIVOT, view, c + glm::vec2(20, 0));
    EXPECT_EQ(scale.update(c + glm::vec2(200, 0)).scale, glm::vec3(1.0f));
    // Slightly off the line of sight the drag is bounded however far the mouse goes.
    view.camera.target = glm::vec3(0.0f);
    GizmoDrag near(GizmoMode::Translate, GizmoHandle::X, PIVOT, view, pixelOf(view, PIVOT));
    for (float x = -2000.0f; x <= 2000.0f; x += 37.0f) {
        const glm::vec3 moved = near.update(glm::vec2(x, 360.0f)).translationWorld;
        ASSERT_TRUE(std::isfinite(moved.x));
        EXPECT_LE(glm::length(moved), MAX_DRAG_DEPTHS * 15.0f);
    }
}

TEST(Gizmo, WorldLengthAppearsAsThePixelCount) {
    GizmoView view = viewAt(ANGLES[0]);
    view.camera.target = PIVOT;
    const float lengthM = worldLengthForPixels(view, PIVOT, 100.0f);
    const glm::mat4 v = view.camera.view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]);
    const glm::vec2 a = pixelOf(view, PIVOT), b = pixelOf(view, PIVOT + lengthM * right);
    EXPECT_NEAR(glm::length(b - a), 100.0f, 0.5f);
}

TEST(Gizmo, PickingFindsTheHandleUnderTheMouse) {
    const GizmoView view = viewAt(ANGLES[0]);
    const GizmoStyle style;
    const float armM = worldLengthForPixels(view, PIVOT, style.armPixels);
    const glm::vec2 c = pixelOf(view, PIVOT);
    for (const GizmoMode mode : {GizmoMode::Translate, GizmoMode::Scale}) {
        for (int axis = 0; axis < 3; ++axis)
            EXPECT_EQ(
                pickGizmoHandle(mode, view, PIVOT, pixelOf(view, PIVOT + 0.7f * armM * AXES[axis])),
                AXIS_HANDLES[axis])
                << axis;
        EXPECT_EQ(pickGizmoHandle(mode, view, PIVOT, c + glm::vec2(2, -3)), GizmoHandle::View);
        EXPECT_EQ(pickGizmoHandle(mode, view, PIVOT,
                                  pixelOf(view, PIVOT + 0.32f * armM * glm::vec3(1, 0, 1))),
                  GizmoHandle::PlaneZX);
        EXPECT_EQ(pickGizmoHandle(mode, view, PIVOT, c + glm::vec2(250, 250)), GizmoHandle::None);
    }
    for (int axis = 0; axis < 3; ++axis) {
        const glm::vec3 e1 = AXES[(axis + 1) % 3], e2 = AXES[(axis + 2) % 3];
        const glm::vec3 onRing = PIVOT + armM * (std::cos(0.6f) * e1 + std::sin(0.6f) * e2);
        EXPECT_EQ(pickGizmoHandle(GizmoMode::Rotate, view, PIVOT, pixelOf(view, onRing)),
                  AXIS_HANDLES[axis])
            << axis;
    }
    EXPECT_EQ(pickGizmoHandle(GizmoMode::Rotate, view, PIVOT,
                              c + style.viewRingFraction * style.armPixels * glm::vec2(0.6f, 0.8f)),
              GizmoHandle::View);
    EXPECT_EQ(pickGizmoHandle(GizmoMode::Rotate, view, PIVOT, c + glm::vec2(400, 0)),
              GizmoHandle::None);
}

TEST(Gizmo, WhatIsDrawnIsWhatIsPicked) {
    for (const Angles angles : ANGLES) {
        const GizmoView view = viewAt(angles);
        for (const GizmoMode mode : {GizmoMode::Translate, GizmoMode::Rotate, GizmoMode::Scale}) {
            const auto lines = gizmoPolylines(mode, view, PIVOT);
            ASSERT_FALSE(lines.empty());
            for (const GizmoPolyline& line : lines) {
                ASSERT_NE(line.handle, GizmoHandle::None);
                ASSERT_GE(line.pointsPixels.size(), 2u);
                // Every drawn point picks something (overlaps may pick a neighbour).
                for (const glm::vec2 p : line.pointsPixels)
                    EXPECT_NE(pickGizmoHandle(mode, view, PIVOT, p), GizmoHandle::None)
                        << describe(angles);
            }
        }
    }
    // Looking straight down, Y points at the camera: neither drawn nor picked.
    GizmoView down = viewAt(ANGLES[3]);
    down.camera.target = PIVOT;
    for (const GizmoPolyline& line : gizmoPolylines(GizmoMode::Translate, down, PIVOT))
        EXPECT_NE(line.handle, GizmoHandle::Y);
    // Behind the camera, nothing.
    EXPECT_TRUE(
        gizmoPolylines(GizmoMode::Translate, down, down.camera.position() + glm::vec3(0, 5, 0))
            .empty());
}

}  // namespace
}  // namespace grass::core
