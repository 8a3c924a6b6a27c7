// Blade shading bake (SPEC §10, grass lighting): per-blade terms the grass shaders read next to
// the blades, computed once when a layer is scattered and patched, on the CPU, without GL.
//   - grass AO: a Gaussian kernel estimate of the grass density around the blade's root
//     (blades per m²), mapped to a darkening factor;
//   - blurred terrain normal: a Gaussian-weighted average of the neighbours' up vectors, the
//     normal the SSS term bends the shading normal towards;
//   - water and age: a per-blade hash, young blades wet, old blades dry.
// Positions are world space, metres; distances are 3D Euclidean, so the bake works on any mesh
// (spheres, tori, Möbius strips) without a parametrisation. Each neighbour counts by how far its
// up vector faces the blade's own: fully within 90° (a right-angled crease blends both faces),
// fading to nothing at 120° (the other face of a thin sheet, the seam of a Möbius strip, a sharp
// fold): the surface between them hides one from the other.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "blade/blade.h"
#include "mesh/surface_mesh.h"
#include "util/result.h"

namespace grass::core {

// One per blade slot of a patched blade array (padding included), uploaded as an SSBO next to
// the blades, index for index. std430: two vec4.
struct BladeShading {
    glm::vec4 blurredNormalAo{0.0f, 1.0f, 0.0f, 1.0f};  // xyz blurred normal (unit), w grass AO
    glm::vec4 waterAge{0.0f};  // x water, y age, both in [0, 1]; z the slot's wilt (scene.h); w 0

    glm::vec3 blurredNormal() const { return glm::vec3(blurredNormalAo); }
    float ao() const { return blurredNormalAo.w; }
    float water() const { return waterAge.x; }
    float age() const { return waterAge.y; }

    bool operator==(const BladeShading&) const = default;
};

static_assert(sizeof(BladeShading) == 32, "BladeShading must be two vec4 (std430)");
static_assert(offsetof(BladeShading, waterAge) == 16, "BladeShading layout must match GLSL");

// Kernel radii below a tenth of a millimetre cover no neighbour (and push σ² out of float
// range): 0 turns a term off instead. The project reader refuses them with their JSON pointer.
inline constexpr float MIN_KERNEL_RADIUS_M = 1e-4f;

struct BladeShadingParams {
    // Gaussian sigma (metres) of the neighbour-density kernel; 0 turns AO off (AO = 1).
    float aoRadiusM = 0.15f;
    // Occluding cross-section of one neighbour (m²): AO follows Beer–Lambert transmittance
    // exp(-density · aoStrength) from 1 down to aoFloor. 0.007 m² puts a 144 blades/m² meadow
    // at AO ≈ 0.59 and the default 300 blades/m² field at ≈ 0.43, while a blade alone stays at 1.
    float aoStrength = 0.007f;
    // The darkest AO: even the densest turf gets sky light from above, and a black blade base
    // would read as a hole.
    float aoFloor = 0.35f;
    // Gaussian sigma (metres) of the terrain-normal blur; 0 keeps each blade's own up.
    float normalBlurRadiusM = 0.75f;
    // Side of the clustering cells in σ of each kernel (the bake's speed/accuracy knob, issue 10):
    // neighbours in other cells are summed per cluster at its centroid. 0 sums every neighbour
    // on its own (exact, and slow in dense fields); otherwise in [0.05, 4].
    float cellSigmas = 0.5f;
    // Water of the oldest (age 1) and the youngest (age 0) blade, each in [0, 1].
    glm::vec2 waterRange{0.15f, 0.6f};

    bool operator==(const BladeShadingParams&) const = default;
};

// Per-blade shading of `blades` (the patched array: v0 root, h height, up surface normal).
// Padding and unusable blades (h <= 0 or not finite, root or up not finite) get
// BladeShading{} and are nobody's neighbour.
// AO: density = Σ_j f_j·k(|v0_j - v0_i|) / (2πσ²·c) over the other blades within 3σ, with
// k(r) = exp(-r²/2σ²) - exp(-4.5) (zero at the 3σ cutoff, so no blade pops in or out), f_j the
// facing weight above (smoothstep of dot(up_j, up_i) from -0.5 to 0) and c normalising k so that
// a uniform field of ρ blades/m² has density ρ; neighbours count by number, not by height (see
// the .cpp). AO = aoFloor + (1 - aoFloor)·exp(-density·aoStrength).
// Blurred normal: normalize(Σ_j f_j·k(r)·up_j) over the blades within 3σ including the blade
// itself; its own up where that sum vanishes or faces away from it.
// Neighbours in other cells (σ/2 wide) are summed per cluster (the cell's blades with up within
// 15° of each other) at its centroid, which keeps 1 M blades at 2500/m² near 2 s of CPU time;
// against the exact sums the AO errs by < 0.003 and the normal by < 1°
// (tests/core/scene/blade_shading_test.cpp measures both).
// water/age: age = uniform [0, 1) from Rng(seed, blade index), water = mix(waterRange.y,
// waterRange.x, age).
// Deterministic for a given seed and identical for any threadCount (0: hardware concurrency).
// Errors: a parameter that is NaN, infinite or out of range (the path names the field): radii
// must be 0 (off) or in [1e-4, 1e5] m, aoFloor and waterRange in [0, 1], aoStrength >= 0,
// cellSigmas 0 (exact) or in [0.05, 4].
Result<std::vector<BladeShading>> bakeBladeShading(const std::vector<Blade>& blades,
                                                   const BladeShadingParams& params,
                                                   std::uint64_t seed, unsigned threadCount = 0);

// Re-bakes, in place, the blades whose root lies inside `region` (a repainted area), summing over
// the live blades within 3σ of it; other entries are left alone. Slots inside that are padding
// (a blade the map removed) get BladeShading{}. The grid is built from the neighbourhood only, so
// its cells and clusters differ from a full bake's: results agree within the clustering error of
// the header comment (tests/core/scene/blade_shading_test.cpp compares them), not bit for bit.
// Returns the number of blades re-baked.
Result<std::size_t> rebakeBladeShading(const std::vector<Blade>& blades,
                                       const BladeShadingParams& params, std::uint64_t seed,
                                       const Bounds& region, std::vector<BladeShading>& shading,
                                       unsigned threadCount = 0);

// Blade slots [first, end).
struct SlotRange {
    std::uint32_t first = 0;
    std::uint32_t end = 0;
};

// The same re-bake, looking only at the blades in `slots`: the caller knows where the blades
// near `region` lie (a patched field's patches near it) and so spares the scan of every blade,
// which on a 1M-blade layer costs more than the dab's own re-bake. Every live blade within 3σ of
// `region` must lie in `slots`; blades outside them are neither re-baked nor summed. Ranges may
// not overlap.
Result<std::size_t> rebakeBladeShading(const std::vector<Blade>& blades,
                                       const BladeShadingParams& params, std::uint64_t seed,
                                       const Bounds& region, const std::vector<SlotRange>& slots,
                                       std::vector<BladeShading>& shading, unsigned threadCount = 0);

// The re-bake of every live blade in the `targets` slots (padding among them gets
// BladeShading{}), summing over the live blades of `slots`, which must hold every live blade
// within 3σ of a target (and the targets themselves). For a dab's own patches: the box around
// them also holds blades of patches the dab did not touch, which need no re-bake.
Result<std::size_t> rebakeBladeShading(const std::vector<Blade>& blades,
                                       const BladeShadingParams& params, std::uint64_t seed,
                                       const std::vector<SlotRange>& targets,
                                       const std::vector<SlotRange>& slots,
                                       std::vector<BladeShading>& shading, unsigned threadCount = 0);

}  // namespace grass::core
