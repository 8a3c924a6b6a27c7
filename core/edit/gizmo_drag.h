// GizmoDrag: what a drag on a gizmo handle (edit/gizmo.h) does to the object, in world space
// (issue 8). Pure maths: begun with the handle, pivot, view and the pixel where the button went
// down, updated with the mouse pixel each frame; the editor applies the returned delta to the
// object as it was when the drag began. The camera is captured at the start (it does not move
// during a drag). Axes are the world axes.
//
//  - Translate, axis: the point of the axis line closest to the mouse ray; the delta is how far
//    that point moved since the start. Plane: where the mouse ray meets the plane through the
//    pivot. View: the same with the plane through the pivot facing the camera.
//  - Rotate: the signed angle (right-handed about the handle's axis; View: the axis towards
//    the eye, so counter-clockwise on screen is positive) between pivot→hit vectors on the
//    plane through the pivot perpendicular to the axis, accumulated frame to frame so it
//    grows past ±180° without jumps.
//  - Scale: ratios of screen distances from the projected pivot: along the axis's on-screen
//    direction for an axis; plain distances for a plane (both its axes) and View (uniform).
//
// Degenerate configurations (an axis pointing at the camera, a plane seen edge-on, a ray that
// meets the line or plane behind the eye, a grab on the pivot itself) leave the delta where it
// was instead of jumping; translations are clamped to MAX_DRAG_DEPTHS times the pivot's
// distance from the eye, scale factors to [MIN_SCALE_FACTOR, MAX_SCALE_FACTOR].
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "edit/gizmo.h"

namespace grass::core {

constexpr float MAX_DRAG_DEPTHS = 100.0f;
// No mirroring: a wind source or collider has no meaningful negative size.
constexpr float MIN_SCALE_FACTOR = 0.01f;
constexpr float MAX_SCALE_FACTOR = 100.0f;

// Snapping, when enabled. Translation snaps the delta (not the resulting position), per world
// component that the handle moves, to multiples of translateStepM: an object off the grid keeps
// its offset, as incremental snapping in DCC tools does. Rotation snaps the accumulated angle
// to multiples of rotateStepDeg; scale snaps the factor to multiples of scaleStep (never below
// one step).
struct GizmoSnap {
    bool enabled = false;
    float translateStepM = 0.25f;
    float rotateStepDeg = 15.0f;
    float scaleStep = 0.1f;
    bool operator==(const GizmoSnap&) const = default;
};

struct GizmoDelta {
    glm::vec3 translationWorld{0.0f};  // Translate: metres
    glm::vec3 rotationAxis{0.0f};      // Rotate: unit world axis (zero for other modes)
    float angleRad = 0.0f;             // Rotate: right-handed about rotationAxis
    glm::vec3 scale{1.0f};             // Scale: factor per world axis, about the pivot
    bool operator==(const GizmoDelta&) const = default;
};

class GizmoDrag {
public:
    GizmoDrag(GizmoMode mode, GizmoHandle handle, glm::vec3 pivotWorld, const GizmoView& view,
              glm::vec2 startMousePixel, const GizmoSnap& snap = {});

    // The delta from the start of the drag to `mousePixel`, snapped when snapping is on.
    const GizmoDelta& update(glm::vec2 mousePixel);
    const GizmoDelta& delta() const { return mDelta; }
    GizmoMode mode() const { return mMode; }
    GizmoHandle handle() const { return mHandle; }

private:
    void updateTranslate(glm::vec2 mousePixel);
    void updateRotate(glm::vec2 mousePixel);
    void updateScale(glm::vec2 mousePixel);
    std::optional<glm::vec3> translatePoint(glm::vec2 mousePixel) const;
    std::optional<glm::vec3> ringVector(glm::vec2 mousePixel) const;
    std::optional<float> screenDistance(glm::vec2 mousePixel) const;

    GizmoMode mMode;
    GizmoHandle mHandle;
    glm::vec3 mPivot;
    GizmoView mView;
    GizmoSnap mSnap;
    glm::vec3 mAxis{0.0f};
    float mMaxDragM = 1.0f;
    glm::vec2 mPivotPixel{0.0f};
    std::optional<glm::vec2> mScreenAxis;  // scale along an axis: its unit on-screen direction
    // Set from the first mouse position where the handle is well conditioned (normally the
    // start): translate: the grabbed point; rotate: the previous pivot→hit vector; scale: the
    // grabbed screen distance.
    std::optional<glm::vec3> mStartPoint;
    std::optional<glm::vec3> mPrevRingVector;
    std::optional<float> mStartDistance;
    float mRawAngleRad = 0.0f;
    GizmoDelta mDelta;
};

}  // namespace grass::core
