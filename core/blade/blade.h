// Blade: the GPU layout of one grass blade (SPEC §1, Jahrmann §4). Four vec4, 64 bytes, std430:
//   (v0, theta) (v1, h) (v2, w) (up, s)
// v0 root, v1 derived control point, v2 tip (world space, metres); theta rotates the width
// direction about up (radians); h height, w width (metres); s stiffness.
// This struct is the one definition of the layout; shaders/include/blade.glsl mirrors it.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>

namespace grass::core {

struct Blade {
    glm::vec4 v0Theta{0.0f};
    glm::vec4 v1H{0.0f};
    glm::vec4 v2W{0.0f};
    glm::vec4 upS{0.0f, 1.0f, 0.0f, 1.0f};

    glm::vec3 v0() const { return glm::vec3(v0Theta); }
    glm::vec3 v1() const { return glm::vec3(v1H); }
    glm::vec3 v2() const { return glm::vec3(v2W); }
    glm::vec3 up() const { return glm::vec3(upS); }
    float theta() const { return v0Theta.w; }
    float h() const { return v1H.w; }
    float w() const { return v2W.w; }
    float s() const { return upS.w; }

    bool operator==(const Blade&) const = default;
};

static_assert(sizeof(Blade) == 64, "Blade must be four vec4 (std430)");
static_assert(offsetof(Blade, v1H) == 16 && offsetof(Blade, v2W) == 32 &&
                  offsetof(Blade, upS) == 48,
              "Blade field offsets must match shaders/include/blade.glsl");

// A blade standing straight in its rest pose: v1 = v0 + h·up, v2 = v0 + h·up (SPEC §1; the
// validation of §3 places v1 from v2, and for a straight blade that is the same point).
Blade makeRestBlade(glm::vec3 v0, glm::vec3 up, float h, float w, float s, float theta);

// The unit width direction: perpendicular to up, rotated by theta (SPEC §1).
glm::vec3 widthDirection(glm::vec3 up, float theta);

// The inverse of widthDirection: the theta whose width direction about unit `up` is `direction`
// (projected onto the plane perpendicular to up).
float widthAngle(glm::vec3 up, glm::vec3 direction);

}  // namespace grass::core
