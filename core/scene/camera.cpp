#include "scene/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "mesh/surface_bulk.h"

namespace grass::core {

namespace {
constexpr float MAX_PITCH = 1.553f;  // 89°: looking straight down flips the up vector
}

glm::vec3 OrbitCamera::position() const {
    const float cp = std::cos(pitchRad);
    return target +
           distance * glm::vec3(cp * std::sin(yawRad), std::sin(pitchRad), cp * std::cos(yawRad));
}

glm::mat4 OrbitCamera::view() const {
    return glm::lookAt(position(), target, glm::vec3(0, 1, 0));
}

glm::mat4 OrbitCamera::projection(float aspect) const {
    return glm::perspective(fovYRad, std::max(aspect, 1e-3f), nearPlane, farPlane);
}

void OrbitCamera::orbit(float dxPixels, float dyPixels) {
    constexpr float RAD_PER_PIXEL = 0.005f;
    yawRad -= dxPixels * RAD_PER_PIXEL;
    pitchRad = std::clamp(pitchRad + dyPixels * RAD_PER_PIXEL, -MAX_PITCH, MAX_PITCH);
}

void OrbitCamera::zoom(float wheelSteps) {
    // Multiplicative, so zooming feels the same at every scale.
    distance = std::clamp(distance * std::pow(0.9f, wheelSteps), 1e-3f, 1e5f);
}

void OrbitCamera::pan(float dxPixels, float dyPixels, float viewportHeightPixels) {
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]);
    const glm::vec3 up(v[0][1], v[1][1], v[2][1]);
    const float worldPerPixel =
        2.0f * distance * std::tan(0.5f * fovYRad) / std::max(viewportHeightPixels, 1.0f);
    target += (-dxPixels * right + dyPixels * up) * worldPerPixel;
}

OrbitCamera OrbitCamera::lookAt(glm::vec3 eye, glm::vec3 target, float fovYRad) {
    OrbitCamera camera;
    camera.target = target;
    const glm::vec3 offset = eye - target;
    camera.distance = std::max(glm::length(offset), 1e-6f);
    camera.yawRad = std::atan2(offset.x, offset.z);
    camera.pitchRad = std::clamp(std::asin(std::clamp(offset.y / camera.distance, -1.0f, 1.0f)),
                                 -MAX_PITCH, MAX_PITCH);
    camera.fovYRad = fovYRad;
    camera.nearPlane = std::max(camera.distance * 1e-3f, 1e-7f);
    camera.farPlane = camera.distance * 20.0f + 100.0f;
    return camera;
}

namespace {
// Same clamp as projection(): a zero-height viewport must not divide by zero.
float aspectOf(glm::vec2 viewportSizePixels) {
    return std::max(viewportSizePixels.x / std::max(viewportSizePixels.y, 1e-6f), 1e-3f);
}
}  // namespace

Ray cameraRay(const OrbitCamera& camera, glm::vec2 pixel, glm::vec2 viewportSizePixels) {
    const glm::vec2 size = glm::max(viewportSizePixels, glm::vec2(1e-6f));
    const float ndcX = 2.0f * pixel.x / size.x - 1.0f;
    const float ndcY = 1.0f - 2.0f * pixel.y / size.y;
    // The camera basis is the view matrix's rows; building the direction from it (rather than
    // unprojecting through the inverse view-projection) keeps full precision far from the eye.
    const glm::mat4 v = camera.view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]);
    const glm::vec3 up(v[0][1], v[1][1], v[2][1]);
    const glm::vec3 back(v[0][2], v[1][2], v[2][2]);
    const float tanHalfFov = std::tan(0.5f * camera.fovYRad);
    const glm::vec3 dir =
        -back + (ndcX * tanHalfFov * aspectOf(size)) * right + (ndcY * tanHalfFov) * up;
    return Ray{camera.position(), glm::normalize(dir)};
}

std::optional<glm::vec2> projectToPixel(const OrbitCamera& camera, glm::vec3 posWorld,
                                        glm::vec2 viewportSizePixels) {
    const glm::vec2 size = glm::max(viewportSizePixels, glm::vec2(1e-6f));
    const glm::vec4 clip =
        camera.projection(aspectOf(size)) * camera.view() * glm::vec4(posWorld, 1.0f);
    // clip.w is the distance in front of the eye; at or behind the eye plane there is no image.
    if (!(clip.w > 1e-6f * camera.distance))
        return std::nullopt;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return glm::vec2(0.5f * (ndc.x + 1.0f) * size.x, 0.5f * (1.0f - ndc.y) * size.y);
}

OrbitCamera frameBounds(const Bounds& bounds, float fovYRad, glm::vec3 fromDirection) {
    OrbitCamera camera = frameBounds(bounds, fovYRad);
    const float length = glm::length(fromDirection);
    if (!(length > 0.0f))
        return camera;
    const glm::vec3 d = fromDirection / length;
    camera.yawRad = std::atan2(d.x, d.z);
    camera.pitchRad = std::clamp(std::asin(std::clamp(d.y, -1.0f, 1.0f)), -1.4f, 1.4f);
    return camera;
}

OrbitCamera fitBoundsInView(OrbitCamera camera, const Bounds& bounds, float aspect, float fill) {
    const auto fits = [&](float distance) {
        OrbitCamera c = camera;
        c.distance = distance;
        const glm::mat4 viewProjection = c.projection(aspect) * c.view();
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x,
                                   (i & 2) ? bounds.max.y : bounds.min.y,
                                   (i & 4) ? bounds.max.z : bounds.min.z);
            const glm::vec4 clip = viewProjection * glm::vec4(corner, 1.0f);
            if (!(clip.w > c.nearPlane) || std::abs(clip.x) > fill * clip.w ||
                std::abs(clip.y) > fill * clip.w)
                return false;
        }
        return true;
    };
    float far = camera.distance, near = camera.distance * 1e-3f;
    if (!fits(far))
        return camera;
    for (int step = 0; step < 40; ++step) {
        const float middle = 0.5f * (near + far);
        (fits(middle) ? far : near) = middle;
    }
    camera.distance = far;
    return camera;
}

glm::vec3 preferredViewDirection(const SurfaceMesh& mesh) {
    const OrbitCamera standard;
    const glm::vec3 threeQuarter = glm::normalize(standard.position() - standard.target);
    glm::dvec3 sum(0.0);
    double area = 0.0;
    for (const auto fh : mesh.faces()) {
        const auto p = facePositions(mesh, fh);
        const glm::dvec3 a = p[0], b = p[1], c = p[2];
        const glm::dvec3 cross = glm::cross(b - a, c - a);  // 2·area·normal
        sum += cross;
        area += glm::length(cross);
    }
    if (!(area > 0.0))
        return threeQuarter;
    // |mean normal| is ~0 for closed objects (look from the default side) and 1 for a flat
    // sheet; past 0.35 most of the surface faces one way and the view turns towards it.
    const glm::vec3 mean = glm::vec3(sum / area);
    if (glm::length(mean) < 0.35f)
        return threeQuarter;
    return glm::normalize(threeQuarter + 2.0f * mean);
}

OrbitCamera frameSurface(const SurfaceMesh& mesh, float aspect) {
    const Bounds bulk = surfaceBulkBounds(mesh);
    return fitBoundsInView(frameBounds(bulk, 0.785f, preferredViewDirection(mesh)), bulk, aspect,
                           0.9f);
}

OrbitCamera frameBounds(const Bounds& bounds, float fovYRad) {
    OrbitCamera camera;
    camera.target = bounds.centre();
    // Down to micrometre objects (a millimetre CAD part, issue 26).
    const float radius = std::max(0.5f * glm::length(bounds.size()), 1e-6f);
    camera.fovYRad = fovYRad;
    // Distance at which the bounding sphere fits the vertical field of view, with a margin.
    camera.distance = 1.1f * radius / std::sin(0.5f * fovYRad);
    camera.yawRad = 0.785f;
    camera.pitchRad = 0.5f;
    camera.nearPlane = std::max(camera.distance - 2.0f * radius, camera.distance * 1e-3f);
    camera.farPlane = camera.distance + 4.0f * radius;
    return camera;
}

}  // namespace grass::core
