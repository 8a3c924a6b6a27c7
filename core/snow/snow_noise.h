// Deterministic noise for snow (SPEC §11, paper 004 §3.2): an integer hash, Perlin's improved
// gradient noise on it, and the fractal sum of eq. 4. Only uint arithmetic and float maths a
// GLSL port copies line for line (uint wraps mod 2³² in both); no tables, no global state, so the
// CPU reference and the snow shaders give the same values for the same input.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace grass::core {

// pcg3d of Jarzynski & Olano, "Hash Functions for GPU Rendering" (JCGT 2020): three well-mixed
// 32-bit outputs from three inputs with 6 multiplies. GLSL: `uvec3 pcg3d(uvec3 v)`.
glm::uvec3 pcg3d(glm::uvec3 v);

// The top 24 bits of a hash as a float in [0, 1): exact in float on CPU and GPU.
float hashToUnit(std::uint32_t h);

// Improved Perlin noise (Perlin 2002: quintic fade, 12 edge gradients) with the lattice gradient
// picked by pcg3d of the integer cell corner instead of a permutation table. Zero at every
// lattice point; in [−1, 1] (4 M random points reach ±0.984; a clamp makes the bound exact).
float perlinNoise3(glm::vec3 p);

// Paper eq. 4: Σ_{i<octaves} A^i · noise(B^i · p + i·OCTAVE_SHIFT), divided by Σ A^i so the sum
// stays in [−1, 1] for any octave count (the paper's sum grows with the octaves). The per-octave
// shift keeps the lattice zeros of the octaves from lining up at the origin. octaves ≥ 1, A > 0.
float fractalNoise(glm::vec3 p, int octaves, float amplitudeA, float frequencyB);

}  // namespace grass::core
