// Blade instances: a layer's live blades as transforms of a unit blade (gltf_export.h), what
// EXT_mesh_gpu_instancing stores per instance. The unit blade stands along +Y with its edges at
// x = ±1 and faces −Z; an instance places it with
//   TRANSLATION = v0 (the root, metres),
//   ROTATION    = the unit quaternion taking +X to the blade's width direction
//                 (widthDirection(up, θ), blade.h) and +Y to its up,
//   SCALE       = (w, h, h): the renderer puts the edges at c ± w·t1 (shaders/include/
//                 blade_geometry.glsl), so a blade is 2w wide and h tall at rest; z scales the
//                 bend of a leaning blade's mesh, which lies in the blade's y–z plane.
// A blade leans towards its front (up × t1 = −Z of that frame; the growth model's rest lean,
// layer_growth.cpp), so its resting curve is one of a one-parameter family: the export draws it
// with the mesh of the nearest of LEAN_BIN_COUNT pre-bent unit blades (issue 25), which stock
// glTF loaders can draw, and keeps the exact v2 in _TIP_OFFSET for runtimes that bend blades.
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

// Lean bins: 0°, 5°, …, 60° (the growth model's rest lean is at most π/3, growth_curves.h).
// A 5° step puts a blade's tip within h·2·sin(1.25°) ≈ 0.044·h of its own.
inline constexpr int LEAN_BIN_COUNT = 13;
inline constexpr float LEAN_BIN_STEP_RAD = 0.0872664626f;  // 5°

// Wilt bins: 0, ¼, ½, ¾, 1. The blade meshes' root-to-tip COLOR_0 is the root's share of the tip
// colour, which depends on the wilt (the growth model blends both ends towards their poor
// colours); one mesh per wilt bin puts every blade's root within a ⅛ step of wilt of its own.
inline constexpr int WILT_BIN_COUNT = 5;

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
    // What the renderer bakes per blade for the grass lighting (blade_shading.h, SPEC §10): the
    // blurred terrain normal, the grass AO at the root and the water term.
    glm::vec3 blurredNormal{0.0f, 1.0f, 0.0f};
    float ao = 1.0f;
    float water = 0.0f;
    // The lean of the resting blade towards its front (bladeLeanRad) and its bin.
    float leanRad = 0.0f;
    int leanBin = 0;
    // The growth model's wilt (0 healthy … 1 poor; 0 without growth) and its bin.
    float wilt = 0.0f;
    int wiltBin = 0;
};

// The angle between up and the resting blade's chord v2 − v0, measured towards the blade's
// front (up × t1) in the plane of up and front: 0 for a straight blade; a sideways component,
// which the growth model never makes, is left out. Clamped to the bins' range.
float bladeLeanRad(const Blade& blade);
// The nearest bin of `leanRad` (clamped to 0..LEAN_BIN_COUNT − 1), and a bin's angle.
int leanBinOf(float leanRad);
float leanBinRad(int bin);
// The same for wilt.
int wiltBinOf(float wilt);
float wiltBinValue(int bin);

// Padding and thinned slots hold null blades (h = w = 0, layer_growth.h).
bool isLiveBlade(const Blade& blade);

// The rotation of the header comment; `up` need not be unit.
glm::quat bladeRotation(glm::vec3 up, float theta);

// The instances of `layer` at `lod` (0..MAX_EXPORT_LOD), in patch order.
std::vector<BladeInstance> bladeInstances(const LayerField& layer, int lod);

// Instances are split into the cells of a grid of CELLS_PER_AXIS³ over their roots' box, one
// node per cell (and lean and wilt bin) in an export, so an engine can cull them (issue 25); the cells
// are cubes, so a flat field gets CELLS_PER_AXIS² of them over its longer side.
inline constexpr int CELLS_PER_AXIS = 4;

struct InstanceGroup {
    int cell = 0;  // (z · CELLS_PER_AXIS + y) · CELLS_PER_AXIS + x
    int bin = 0;   // lean bin
    int wiltBin = 0;
    std::vector<std::uint32_t> members;  // indices into the instances, ascending
};

// The non-empty (cell, lean bin, wilt bin) groups of `instances`, ordered by cell, then lean,
// then wilt.
std::vector<InstanceGroup> groupInstances(const std::vector<BladeInstance>& instances);

}  // namespace grass::core
