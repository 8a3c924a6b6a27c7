#include "edit/gizmo.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace grass::core {

namespace {

constexpr glm::vec3 AXES[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
constexpr GizmoHandle AXIS_HANDLES[3] = {GizmoHandle::X, GizmoHandle::Y, GizmoHandle::Z};
// Plane handles with the two axes they span (their normal is the third).
struct PlaneSpec {
    GizmoHandle handle;
    int a, b;
};
constexpr PlaneSpec PLANES[3] = {
    {GizmoHandle::PlaneXY, 0, 1}, {GizmoHandle::PlaneYZ, 1, 2}, {GizmoHandle::PlaneZX, 2, 0}};

glm::vec3 forwardOf(const OrbitCamera& camera) {
    return glm::normalize(camera.target - camera.position());
}

// Projects all points, or nothing when one is behind the eye.
std::optional<std::vector<glm::vec2>> projectAll(const GizmoView& view,
                                                 const std::vector<glm::vec3>& pointsWorld) {
    std::vector<glm::vec2> out;
    out.reserve(pointsWorld.size());
    for (const glm::vec3 p : pointsWorld) {
        const auto pixel = projectToPixel(view.camera, p, view.viewportSizePixels);
        if (!pixel)
            return std::nullopt;
        out.push_back(*pixel);
    }
    return out;
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float lengthSq = glm::dot(ab, ab);
    const float s = lengthSq > 0.0f ? std::clamp(glm::dot(p - a, ab) / lengthSq, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + s * ab));
}

float distanceToPolyline(glm::vec2 p, const GizmoPolyline& line) {
    const auto& pts = line.pointsPixels;
    float best = std::numeric_limits<float>::infinity();
    if (pts.size() == 1)
        return glm::length(p - pts[0]);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        best = std::min(best, distanceToSegment(p, pts[i], pts[i + 1]));
    if (line.closed && pts.size() > 2)
        best = std::min(best, distanceToSegment(p, pts.back(), pts.front()));
    return best;
}

// Crossing-number test; the shapes are small convex polygons, but this takes any simple one.
bool insidePolygon(glm::vec2 p, const std::vector<glm::vec2>& pts) {
    bool inside = false;
    for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
        const glm::vec2 a = pts[i], b = pts[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
            inside = !inside;
    }
    return inside;
}

std::vector<glm::vec2> screenSquare(glm::vec2 centre, float halfSide) {
    return {centre + glm::vec2(-halfSide, -halfSide), centre + glm::vec2(halfSide, -halfSide),
            centre + glm::vec2(halfSide, halfSide), centre + glm::vec2(-halfSide, halfSide)};
}

std::vector<glm::vec2> screenCircle(glm::vec2 centre, float radius, int segments) {
    std::vector<glm::vec2> pts;
    for (int i = 0; i < segments; ++i) {
        const float angleRad = 2.0f * float(M_PI) * float(i) / float(segments);
        pts.push_back(centre + radius * glm::vec2(std::cos(angleRad), std::sin(angleRad)));
    }
    return pts;
}

void addPlanes(std::vector<GizmoPolyline>& out, const GizmoView& view, glm::vec3 pivot, float armM,
               const GizmoStyle& style) {
    const glm::vec3 forward = forwardOf(view.camera);
    for (const PlaneSpec& plane : PLANES) {
        const glm::vec3 a = AXES[plane.a], b = AXES[plane.b];
        if (std::abs(glm::dot(glm::cross(a, b), forward)) < style.minPlaneCos)
            continue;
        const float n = style.planeNearFraction * armM, f = style.planeFarFraction * armM;
        const auto pts = projectAll(view, {pivot + n * a + n * b, pivot + f * a + n * b,
                                           pivot + f * a + f * b, pivot + n * a + f * b});
        if (pts)
            out.push_back({plane.handle, *pts, true, true});
    }
}

void addAxes(std::vector<GizmoPolyline>& out, GizmoMode mode, const GizmoView& view,
             glm::vec3 pivot, glm::vec2 pivotPixel, float armM, const GizmoStyle& style) {
    for (int axis = 0; axis < 3; ++axis) {
        const auto end =
            projectToPixel(view.camera, pivot + armM * AXES[axis], view.viewportSizePixels);
        if (!end || glm::length(*end - pivotPixel) < style.minAxisFraction * style.armPixels)
            continue;
        const GizmoHandle handle = AXIS_HANDLES[axis];
        out.push_back({handle, {pivotPixel, *end}, false, false});
        const glm::vec2 u = glm::normalize(*end - pivotPixel);
        const glm::vec2 w(-u.y, u.x);
        const float tip = style.tipPixels;
        if (mode == GizmoMode::Translate)
            out.push_back({handle,
                           {*end + 1.8f * tip * u, *end + 0.6f * tip * w, *end - 0.6f * tip * w},
                           true,
                           true});
        else
            out.push_back({handle, screenSquare(*end, 0.6f * tip), true, true});
    }
}

void addRings(std::vector<GizmoPolyline>& out, const GizmoView& view, glm::vec3 pivot,
              glm::vec2 pivotPixel, float armM, const GizmoStyle& style) {
    for (int axis = 0; axis < 3; ++axis) {
        const glm::vec3 b1 = AXES[(axis + 1) % 3], b2 = AXES[(axis + 2) % 3];
        std::vector<glm::vec3> ring;
        for (int i = 0; i < style.ringSegments; ++i) {
            const float angleRad = 2.0f * float(M_PI) * float(i) / float(style.ringSegments);
            ring.push_back(pivot + armM * (std::cos(angleRad) * b1 + std::sin(angleRad) * b2));
        }
        if (const auto pts = projectAll(view, ring))
            out.push_back({AXIS_HANDLES[axis], *pts, true, false});
    }
    out.push_back(
        {GizmoHandle::View,
         screenCircle(pivotPixel, style.viewRingFraction * style.armPixels, style.ringSegments),
         true, false});
}

}  // namespace

float worldLengthForPixels(const GizmoView& view, glm::vec3 posWorld, float pixels) {
    const OrbitCamera& camera = view.camera;
    const float depth = std::max(glm::dot(posWorld - camera.position(), forwardOf(camera)),
                                 std::max(camera.nearPlane, 1e-6f));
    const float worldPerPixel =
        2.0f * depth * std::tan(0.5f * camera.fovYRad) / std::max(view.viewportSizePixels.y, 1.0f);
    return pixels * worldPerPixel;
}

glm::vec3 gizmoHandleAxis(GizmoHandle handle, const GizmoView& view, glm::vec3 pivotWorld) {
    switch (handle) {
        case GizmoHandle::X:
        case GizmoHandle::PlaneYZ:
            return AXES[0];
        case GizmoHandle::Y:
        case GizmoHandle::PlaneZX:
            return AXES[1];
        case GizmoHandle::Z:
        case GizmoHandle::PlaneXY:
            return AXES[2];
        case GizmoHandle::View: {
            const glm::vec3 toEye = view.camera.position() - pivotWorld;
            const float length = glm::length(toEye);
            return length > 0.0f ? toEye / length : -forwardOf(view.camera);
        }
        case GizmoHandle::None:
            break;
    }
    return glm::vec3(0.0f);
}

std::vector<GizmoPolyline> gizmoPolylines(GizmoMode mode, const GizmoView& view,
                                          glm::vec3 pivotWorld, const GizmoStyle& style) {
    std::vector<GizmoPolyline> out;
    const auto pivotPixel = projectToPixel(view.camera, pivotWorld, view.viewportSizePixels);
    if (!pivotPixel)
        return out;
    const float armM = worldLengthForPixels(view, pivotWorld, style.armPixels);
    if (mode == GizmoMode::Rotate) {
        addRings(out, view, pivotWorld, *pivotPixel, armM, style);
        return out;
    }
    addPlanes(out, view, pivotWorld, armM, style);
    addAxes(out, mode, view, pivotWorld, *pivotPixel, armM, style);
    out.push_back({GizmoHandle::View, screenSquare(*pivotPixel, style.centrePixels), true, true});
    return out;
}

GizmoHandle pickGizmoHandle(GizmoMode mode, const GizmoView& view, glm::vec3 pivotWorld,
                            glm::vec2 mousePixel, const GizmoStyle& style) {
    const std::vector<GizmoPolyline> lines = gizmoPolylines(mode, view, pivotWorld, style);
    // Topmost (drawn last) filled shape first: the centre square wins over the planes.
    for (auto it = lines.rbegin(); it != lines.rend(); ++it)
        if (it->filled && insidePolygon(mousePixel, it->pointsPixels))
            return it->handle;
    GizmoHandle best = GizmoHandle::None;
    float bestDistance = style.pickTolerancePixels;
    for (const GizmoPolyline& line : lines) {
        const float distance = distanceToPolyline(mousePixel, line);
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = line.handle;
        }
    }
    return best;
}

}  // namespace grass::core
