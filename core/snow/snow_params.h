// SnowParams: the snow accumulation settings of a project (SPEC §11, paper 004, issue 9), as the
// snow passes receive them. World space, metres, seconds, +Y up; colours are linear RGB.
// std430-compatible (vec3 + float pairs, 4-byte scalars) so the GPU passes can upload it as is
// and mirror the fields in this order; the `static_assert`s pin the layout.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace grass::core {

inline constexpr int SNOW_MAX_OCTAVES = 8;
inline constexpr int SNOW_MAX_SAMPLES = 32;
// The sides of the depth map a project may ask for.
inline constexpr std::array<int, 3> SNOW_MAP_RESOLUTIONS{512, 1024, 2048};

struct SnowParams {
    // Where snow falls TO (normalized on use, like the sun direction); −fallDirection is "up" as
    // the snow sees it (φ of Fi is measured from it).
    glm::vec3 fallDirection{0.0f, -1.0f, 0.0f};
    // As: snow depth in metres on a fully exposed, flat surface at Zn = 1 (paper eq. 5).
    float amountM = 0.15f;
    glm::vec3 snowColor{0.92f, 0.94f, 0.98f};  // Cs (paper eq. 3)
    // A of Σ A^i noise(B^i x) (paper eq. 4: 0 < A ≤ 1; the paper's pseudo-code halves it).
    float noiseAmplitude = 0.5f;
    // B of eq. 4 (B > 1; the paper doubles the frequency per octave).
    float noiseFrequency = 2.0f;
    // World size of the lowest octave: x in eq. 4 is posWorld / noiseScaleM.
    float noiseScaleM = 2.0f;
    // Strength of n in Fi = cos φ + n: n = inclineNoise · fractal noise ∈ [−inclineNoise, ...].
    float inclineNoise = 0.2f;
    // Radius of the jittered sample disc around a point's depth-map position, in texels.
    float sampleRadiusTexels = 1.5f;
    // Width of the smooth rise of the snow surface at a shelter edge (the paper's future work).
    float boundaryFalloffM = 0.25f;
    // With --time, As(t) = clamp(As + (accumulationRate − meltRate)·t, 0, maxAmountM), in m/s.
    float accumulationRate = 0.0f;
    float meltRate = 0.0f;
    // Extra downward acceleration on exposed blades per metre of snow: (m/s²)/m.
    float loadGravity = 20.0f;
    float maxAmountM = 1.0f;
    // A depth-map sample occludes only when it is this much nearer the sky than the point
    // (plus a slope term, see exposureCoefficient): rasterised depth is exact only at texel
    // centres.
    float depthBiasM = 0.02f;
    int noiseOctaves = 4;  // 1..SNOW_MAX_OCTAVES
    // 1..SNOW_MAX_SAMPLES. The paper uses 18; 8 sits on the measured front at a third less cost
    // (docs/snow.md).
    int samples = 8;
    // Side of the orthographic depth map: 512, 1024 (the paper's) or 2048.
    int mapResolution = 1024;
    // 0 or 1 (a uint, not bool, to keep the std430 layout). Off: no snow pass runs.
    std::uint32_t enabled = 0;
    // Drift with the wind (snow_drift.h): the snow depth is scaled by 1 + drift·(shelter
    // upwind within driftReachM), in [1 − drift, 1 + drift]; 0: none.
    float drift = 0.0f;
    float driftReachM = 4.0f;
    // Where the snow drifts to when driftFollowsWind is 0; with it (1), the scene's directional
    // winds decide.
    glm::vec3 driftDirection{1.0f, 0.0f, 0.0f};
    std::uint32_t driftFollowsWind = 1;

    bool operator==(const SnowParams&) const = default;
};

static_assert(sizeof(SnowParams) == 112, "SnowParams must be seven vec4 (std430)");
static_assert(offsetof(SnowParams, amountM) == 12 && offsetof(SnowParams, noiseAmplitude) == 28 &&
                  offsetof(SnowParams, noiseFrequency) == 32 &&
                  offsetof(SnowParams, boundaryFalloffM) == 48 &&
                  offsetof(SnowParams, maxAmountM) == 64 &&
                  offsetof(SnowParams, mapResolution) == 80 && offsetof(SnowParams, enabled) == 84 &&
                  offsetof(SnowParams, drift) == 88 && offsetof(SnowParams, driftDirection) == 96,
              "SnowParams offsets must match the snow shaders");

}  // namespace grass::core
