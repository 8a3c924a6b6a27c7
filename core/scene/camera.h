// Cameras: an orbit camera (target, distance, yaw, pitch) for the editor's viewport and for
// framing any mesh, and the view/projection matrices both renderers use. Right-handed, +Y up,
// metres, angles in radians; projection to OpenGL clip space (z in [−1, 1]).
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "mesh/ray.h"
#include "mesh/surface_mesh.h"

namespace grass::core {

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float distance = 10.0f;
    float yawRad = 0.785f;   // about +Y, 0 looks along −Z from +Z
    float pitchRad = 0.45f;  // above the horizon, clamped to (−89°, 89°)
    float fovYRad = 0.785f;
    float nearPlane = 0.05f;
    float farPlane = 500.0f;
    bool operator==(const OrbitCamera&) const = default;

    glm::vec3 position() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;

    // Mouse interaction (pixels): drag orbits, wheel zooms, pan moves the target in the
    // view plane by the amount that keeps the point under the cursor under it.
    void orbit(float dxPixels, float dyPixels);
    void zoom(float wheelSteps);
    void pan(float dxPixels, float dyPixels, float viewportHeightPixels);

    static OrbitCamera lookAt(glm::vec3 eye, glm::vec3 target, float fovYRad);
};

// Screen <-> world for picking and gizmos. Pixel coordinates: origin at the top-left corner of
// the viewport, x right, y down, in the same units as viewportSizePixels (GLFW cursor positions
// and window sizes, or framebuffer pixels: the caller keeps them consistent). The centre of the
// top-left pixel is (0.5, 0.5): adding that half pixel is the caller's business. The aspect is
// width / height and the projection is exactly OrbitCamera::projection's.
//
// The ray from the eye (camera.position()) through `pixel`; direction normalized. A ray starts
// at the eye rather than on the near plane, so picking also finds what is nearer than nearPlane.
Ray cameraRay(const OrbitCamera& camera, glm::vec2 pixel, glm::vec2 viewportSizePixels);
// Where `posWorld` appears on screen, in the convention above (it may lie outside the
// viewport); nullopt when the point is behind the camera or in the eye's plane.
std::optional<glm::vec2> projectToPixel(const OrbitCamera& camera, glm::vec3 posWorld,
                                        glm::vec2 viewportSizePixels);

// A camera that sees the whole box from a 3/4 view above, near/far fitted to it.
OrbitCamera frameBounds(const Bounds& bounds, float fovYRad);
// The same, looking from `fromDirection` (towards the camera, need not be normalized).
OrbitCamera frameBounds(const Bounds& bounds, float fovYRad, glm::vec3 fromDirection);

// `camera` moved along its view direction (target, angles and field of view kept) to the
// nearest distance at which every corner of `bounds` lies in front of it and inside `fill` of
// the view's half-width and half-height at `aspect`: a flat field seen from above fills the
// picture instead of its bounding sphere. Never farther than it was.
OrbitCamera fitBoundsInView(OrbitCamera camera, const Bounds& bounds, float aspect, float fill);

// Where to look at a mesh from: the default 3/4 view above, turned towards the side most of
// the surface faces (an open surface standing upright, like a wall or a glTF quad in the XY
// plane, is seen from its grassy front instead of edge-on from above).
glm::vec3 preferredViewDirection(const SurfaceMesh& mesh);

// The first view of a surface: the bulk of it (surface_bulk.h: a far cloud or a stray part of
// the file left out) from its preferred side, filling 90 % of a picture of `aspect` (a 45° field
// of view). What a project made from a mesh and an imported mesh start with.
OrbitCamera frameSurface(const SurfaceMesh& mesh, float aspect);

}  // namespace grass::core
