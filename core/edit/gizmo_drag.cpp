#include "edit/gizmo_drag.h"

#include <algorithm>
#include <cmath>

namespace grass::core {

namespace {

// Below this sine between the mouse ray and an axis (about 3°), the closest point on the axis
// runs off to infinity with sub-pixel mouse motion: the axis points at the camera.
constexpr float MIN_AXIS_SIN = 0.05f;
// Below this cosine between the mouse ray and a plane's normal the plane is seen edge-on.
constexpr float MIN_PLANE_COS = 0.05f;
// A scale grab this close to the pivot on screen has no distance to take a ratio of.
constexpr float MIN_GRAB_PIXELS = 3.0f;
// Screen length, at the pivot, of the world length used to find an axis's screen direction,
// and the shortest it may appear before the axis counts as pointing at the camera.
constexpr float AXIS_PROBE_PIXELS = 100.0f;
constexpr float MIN_AXIS_PROBE_PIXELS = 5.0f;

// Which world components a handle moves or scales.
glm::vec3 movedComponents(GizmoHandle handle) {
    switch (handle) {
        case GizmoHandle::X:
            return {1, 0, 0};
        case GizmoHandle::Y:
            return {0, 1, 0};
        case GizmoHandle::Z:
            return {0, 0, 1};
        case GizmoHandle::PlaneXY:
            return {1, 1, 0};
        case GizmoHandle::PlaneYZ:
            return {0, 1, 1};
        case GizmoHandle::PlaneZX:
            return {1, 0, 1};
        case GizmoHandle::View:
            return {1, 1, 1};
        case GizmoHandle::None:
            break;
    }
    return glm::vec3(0.0f);
}

bool isAxisHandle(GizmoHandle handle) {
    return handle == GizmoHandle::X || handle == GizmoHandle::Y || handle == GizmoHandle::Z;
}

float roundToStep(float value, float step) {
    return step > 0.0f ? step * std::round(value / step) : value;
}

// Where the ray meets the plane through `point` with unit normal `n`, in front of the eye.
std::optional<glm::vec3> hitPlane(const Ray& ray, glm::vec3 point, glm::vec3 n) {
    const float cosine = glm::dot(ray.direction, n);
    if (!(std::abs(cosine) >= MIN_PLANE_COS))
        return std::nullopt;
    const float t = glm::dot(point - ray.origin, n) / cosine;
    if (!(t > 0.0f) || !std::isfinite(t))
        return std::nullopt;
    return ray.at(t);
}

}  // namespace

GizmoDrag::GizmoDrag(GizmoMode mode, GizmoHandle handle, glm::vec3 pivotWorld,
                     const GizmoView& view, glm::vec2 startMousePixel, const GizmoSnap& snap)
    : mMode(mode), mHandle(handle), mPivot(pivotWorld), mView(view), mSnap(snap) {
    mAxis = gizmoHandleAxis(handle, view, pivotWorld);
    const float depthM = glm::length(pivotWorld - view.camera.position());
    mMaxDragM = MAX_DRAG_DEPTHS * std::max(depthM, view.camera.nearPlane);
    mPivotPixel =
        projectToPixel(view.camera, pivotWorld, view.viewportSizePixels).value_or(startMousePixel);
    if (isAxisHandle(handle)) {
        const float probeM = worldLengthForPixels(view, pivotWorld, AXIS_PROBE_PIXELS);
        const auto end =
            projectToPixel(view.camera, pivotWorld + probeM * mAxis, view.viewportSizePixels);
        if (end && glm::length(*end - mPivotPixel) >= MIN_AXIS_PROBE_PIXELS)
            mScreenAxis = glm::normalize(*end - mPivotPixel);
    }
    if (mode == GizmoMode::Rotate)
        mDelta.rotationAxis = mAxis;
    // Sets the references; the delta stays at identity.
    update(startMousePixel);
}

const GizmoDelta& GizmoDrag::update(glm::vec2 mousePixel) {
    if (mHandle == GizmoHandle::None)
        return mDelta;
    switch (mMode) {
        case GizmoMode::Translate:
            updateTranslate(mousePixel);
            break;
        case GizmoMode::Rotate:
            updateRotate(mousePixel);
            break;
        case GizmoMode::Scale:
            updateScale(mousePixel);
            break;
    }
    return mDelta;
}

std::optional<glm::vec3> GizmoDrag::translatePoint(glm::vec2 mousePixel) const {
    const Ray ray = cameraRay(mView.camera, mousePixel, mView.viewportSizePixels);
    if (!isAxisHandle(mHandle))
        return hitPlane(ray, mPivot, mAxis);
    // Closest points of the axis line pivot + s·axis and the ray origin + t·direction (both
    // unit): s = (b·e − d)/(1 − b²), t = (e − b·d)/(1 − b²).
    const glm::vec3 w0 = mPivot - ray.origin;
    const float b = glm::dot(mAxis, ray.direction);
    const float d = glm::dot(mAxis, w0), e = glm::dot(ray.direction, w0);
    const float sinSq = 1.0f - b * b;
    if (!(sinSq >= MIN_AXIS_SIN * MIN_AXIS_SIN))
        return std::nullopt;
    const float s = (b * e - d) / sinSq, t = (e - b * d) / sinSq;
    // The line must cross in front of the eye, not through it: an axis through the eye is seen
    // end-on and its closest point is the eye itself, whatever the mouse does.
    if (!(t > mView.camera.nearPlane) || !std::isfinite(s))
        return std::nullopt;
    return mPivot + s * mAxis;
}

void GizmoDrag::updateTranslate(glm::vec2 mousePixel) {
    const auto point = translatePoint(mousePixel);
    if (!point)
        return;
    if (!mStartPoint) {
        mStartPoint = point;
        return;
    }
    // Masking zeroes the components the handle does not move exactly, not just to rounding.
    const glm::vec3 mask = movedComponents(mHandle);
    glm::vec3 delta = (*point - *mStartPoint) * mask;
    const float length = glm::length(delta);
    if (length > mMaxDragM)
        delta *= mMaxDragM / length;
    if (mSnap.enabled)
        for (int i = 0; i < 3; ++i)
            delta[i] = roundToStep(delta[i], mSnap.translateStepM) * mask[i];
    mDelta.translationWorld = delta;
}

std::optional<glm::vec3> GizmoDrag::ringVector(glm::vec2 mousePixel) const {
    const Ray ray = cameraRay(mView.camera, mousePixel, mView.viewportSizePixels);
    const auto hit = hitPlane(ray, mPivot, mAxis);
    if (!hit)
        return std::nullopt;
    glm::vec3 v = *hit - mPivot;
    v -= glm::dot(v, mAxis) * mAxis;
    // On the pivot itself the direction, and so the angle, is undefined.
    if (!(glm::length(v) > 1e-6f * mMaxDragM))
        return std::nullopt;
    return v;
}

void GizmoDrag::updateRotate(glm::vec2 mousePixel) {
    const auto v = ringVector(mousePixel);
    if (!v)
        return;
    // Accumulating the step from the previous vector (each within ±180°) lets the angle grow
    // past a full turn without the jump at ±180° that an angle from the start vector has.
    if (mPrevRingVector)
        mRawAngleRad += std::atan2(glm::dot(glm::cross(*mPrevRingVector, *v), mAxis),
                                   glm::dot(*mPrevRingVector, *v));
    mPrevRingVector = v;
    mDelta.angleRad =
        mSnap.enabled ? roundToStep(mRawAngleRad, glm::radians(mSnap.rotateStepDeg)) : mRawAngleRad;
}

std::optional<float> GizmoDrag::screenDistance(glm::vec2 mousePixel) const {
    if (!isAxisHandle(mHandle))
        return glm::length(mousePixel - mPivotPixel);
    if (!mScreenAxis)
        return std::nullopt;
    return glm::dot(mousePixel - mPivotPixel, *mScreenAxis);
}

void GizmoDrag::updateScale(glm::vec2 mousePixel) {
    const auto distance = screenDistance(mousePixel);
    if (!distance)
        return;
    if (!mStartDistance) {
        if (std::abs(*distance) >= MIN_GRAB_PIXELS)
            mStartDistance = distance;
        return;
    }
    float factor = std::clamp(*distance / *mStartDistance, MIN_SCALE_FACTOR, MAX_SCALE_FACTOR);
    if (mSnap.enabled && mSnap.scaleStep > 0.0f)
        factor = std::clamp(std::max(roundToStep(factor, mSnap.scaleStep), mSnap.scaleStep),
                            MIN_SCALE_FACTOR, MAX_SCALE_FACTOR);
    const glm::vec3 mask = movedComponents(mHandle);
    mDelta.scale = mask * factor + (glm::vec3(1.0f) - mask);
}

}  // namespace grass::core
