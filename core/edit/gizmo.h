// Gizmo geometry and handle picking for placing wind sources and colliders in the viewport
// (issue 8): translate, rotate and scale along world axes, planes and the screen. Pure maths;
// the editor draws gizmoPolylines() and asks pickGizmoHandle() what is under the mouse, so what
// is drawn is exactly what can be picked. Drags are in gizmo_drag.h.
//
// Spaces: world positions in metres; screen positions in pixels with the origin at the
// viewport's top-left and y down (the cameraRay/projectToPixel convention, scene/camera.h).
// The gizmo keeps a constant size on screen: its arms are `armPixels` long at the pivot.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.h"

namespace grass::core {

enum class GizmoMode { Translate, Rotate, Scale };
// View: the screen plane for Translate, the ring about the view axis for Rotate, uniform scale
// for Scale. Plane handles are named by the axes they move (PlaneXY moves X and Y).
enum class GizmoHandle { None, X, Y, Z, PlaneXY, PlaneYZ, PlaneZX, View };

// The camera and viewport the gizmo is seen through.
struct GizmoView {
    OrbitCamera camera;
    glm::vec2 viewportSizePixels{1280.0f, 720.0f};
};

struct GizmoStyle {
    float armPixels = 110.0f;          // axis arms; rotate rings have this radius
    float pickTolerancePixels = 7.0f;  // how far from a line the mouse still grabs it
    float tipPixels = 9.0f;            // arrow heads (translate) and boxes (scale)
    float planeNearFraction = 0.22f;   // plane squares span [near, far]·arm along both axes
    float planeFarFraction = 0.42f;
    float centrePixels = 9.0f;      // half side of the View square (translate, scale)
    float viewRingFraction = 1.2f;  // rotate: the View ring's radius, in arms
    // An axis whose arm shows shorter than this fraction of armPixels points (nearly) at the
    // camera: it is neither drawn nor picked, since dragging it would be ill-conditioned.
    float minAxisFraction = 0.15f;
    // The same for a plane square seen edge-on: minimum |cos| between its normal and the view.
    float minPlaneCos = 0.2f;
    int ringSegments = 64;
    bool operator==(const GizmoStyle&) const = default;
};

// One thing the editor draws: a screen polyline belonging to a handle. `filled` shapes (plane
// squares, arrow heads, boxes, the centre square) are picked anywhere inside; the rest
// within pickTolerancePixels of a segment.
struct GizmoPolyline {
    GizmoHandle handle = GizmoHandle::None;
    std::vector<glm::vec2> pointsPixels;
    bool closed = false;
    bool filled = false;
};

// The world length that appears `pixels` long at `posWorld` (at its depth, across the view):
// the gizmo's world size. Positive for any input; a point at or behind the eye uses the
// near plane's depth.
float worldLengthForPixels(const GizmoView& view, glm::vec3 posWorld, float pixels);

// Unit world direction of an axis handle; the normal of a plane handle (PlaneXY → +Z); for
// View, the direction from the pivot towards the eye. Zero for None.
glm::vec3 gizmoHandleAxis(GizmoHandle handle, const GizmoView& view, glm::vec3 pivotWorld);

// Everything to draw for `mode`, in drawing order (planes first, then axes, then the centre
// or view ring). Parts with a point behind the eye, axes pointing at the camera and planes
// seen edge-on are left out.
std::vector<GizmoPolyline> gizmoPolylines(GizmoMode mode, const GizmoView& view,
                                          glm::vec3 pivotWorld, const GizmoStyle& style = {});

// The handle under the mouse: filled shapes containing it first, then the nearest line within
// the tolerance; None when nothing is that close.
GizmoHandle pickGizmoHandle(GizmoMode mode, const GizmoView& view, glm::vec3 pivotWorld,
                            glm::vec2 mousePixel, const GizmoStyle& style = {});

}  // namespace grass::core
