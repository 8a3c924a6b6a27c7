// Blade instances: a layer's live blades as transforms of a unit blade (gltf_export.h), what
// EXT_mesh_gpu_instancing stores per instance. The unit blade stands along +Y with its edges at
// x = ±1 and faces −Z; an instance places it with
//   TRANSLATION = v0 (the root, metres),
//   ROTATION    = the unit quaternion taking +X to the blade's width direction
//                 (widthDirection(up, θ), blade.h) and +Y to its up,
//   SCALE       = (w, h, w): the renderer puts the edges at c ± w·t1 (shaders/include/
//                 blade_geometry.glsl), so a blade is 2w wide and h tall at rest.
// LOD N > 0 thins the field for distant or lightweight use: of the live blades in patch order
// (patches are compact and Morton-sorted inside, patches.h, so every k-th blade is spread
// evenly over the surface) it keeps every 2^N-th, and widens each kept blade 2^N times so the
// summed blade area, the coverage a distant viewer sees, stays the same.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "blade/blade.h"
#include "scene/scene.h"

namespace grass::core {

struct BladeInstance {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    float stiffness = 1.0f;
    // The blade's colours after the growth model's wilt (scene.h), linear RGB.
    glm::vec3 rootColor{0.0f};
    glm::vec3 tipColor{0.0f};
    // v2 − v0 in metres: where the tip hangs (rest lean of the growth model), for runtimes that
    // bend the blade instead of drawing it straight.
    glm::vec3 tipOffset{0.0f};
};

// Padding and thinned slots hold null blades (h = w = 0, layer_growth.h).
bool isLiveBlade(const Blade& blade);

// The rotation of the header comment; `up` need not be unit.
glm::quat bladeRotation(glm::vec3 up, float theta);

// The instances of `layer` at `lod` (0..MAX_EXPORT_LOD), in patch order.
std::vector<BladeInstance> bladeInstances(const LayerField& layer, int lod);

}  // namespace grass::core
