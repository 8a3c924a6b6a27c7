// Wind sources (SPEC §4): analytic functions of world position (metres) and time (seconds),
// summed. A wind value is the displacement rate wi of SPEC §3 (m/s), applied at the blade root.
// Every source is deterministic and stateless: the gust noise is a hashed lattice value noise,
// so the CPU reference and the compute shader evaluate the same field without shared RNG state.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace grass::core {

// One key of a piecewise-linear path: at timeS the source (or collider) is at posWorld.
struct PathKey {
    float timeS = 0.0f;
    glm::vec3 posWorld{0.0f};
    bool operator==(const PathKey&) const = default;
};

// Position on a path at timeS: piecewise-linear between keys, clamped to the first and last key;
// `fallback` when the path is empty. Precondition: keys sorted by non-decreasing timeS.
glm::vec3 samplePath(const std::vector<PathKey>& path, float timeS, glm::vec3 fallback);

enum class WindKind : std::uint32_t {
    Directional = 0,  // a travelling wave along `direction`, with gusts
    Point = 1,        // blows radially outwards from `position` (the paper's helicopter)
    Vortex = 2,       // blows tangentially around the axis through `position` (a tornado)
};

struct WindSource {
    WindKind kind = WindKind::Directional;
    // Centre of the falloff, of the point source and of the vortex axis (overridden by `path`).
    glm::vec3 position{0.0f};
    // Directional: where the wind blows to. Vortex: the axis (counter-clockwise seen from +axis).
    glm::vec3 direction{1.0f, 0.0f, 0.0f};
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    // Peak magnitude of the displacement rate (m/s).
    float strength = 1.0f;
    // Smooth falloff (1 − (r/R)²)² to exactly 0 at r = R; R ≤ 0 means the source reaches
    // everywhere.
    float radiusM = 0.0f;
    // Point and vortex: inside the core the magnitude rises linearly from 0 on the axis/centre
    // (a Rankine core), so the field is continuous where its direction is undefined.
    float coreRadiusM = 1.0f;
    // Directional wave: magnitude strength·(0.5 + 0.5·sin(2π(direction·p − speed·t)/wavelength));
    // wavelength ≤ 0 gives a constant wind.
    float wavelengthM = 10.0f;
    float speedMps = 2.0f;
    // Directional gusts in [0, 1]: the magnitude is scaled by (1 − gust + gust·n), n ∈ [0, 1] a
    // smooth value noise advected with the wind (cells of one wavelength, or 10 m when constant).
    float gust = 0.0f;
    // Optional keyed positions over time; when non-empty it replaces `position`.
    std::vector<PathKey> path;

    bool operator==(const WindSource&) const = default;
};

// Smooth value noise in [0, 1], C² (quintic fade), deterministic across platforms.
float valueNoise3(glm::vec3 p);

// The wind of one source at p and timeS (m/s); zero for non-finite input.
glm::vec3 windAt(const WindSource& source, glm::vec3 p, float timeS);

// The sum of all sources.
glm::vec3 windAt(const std::vector<WindSource>& sources, glm::vec3 p, float timeS);

}  // namespace grass::core
