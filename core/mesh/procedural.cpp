#include "mesh/procedural.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

#include "util/rng.h"

namespace grass::core {

namespace {

constexpr double PI = 3.14159265358979323846;
constexpr int MAX_RESOLUTION = 1024;
// Octaves of the hills' fractal noise: the fifth has 1/16 of the lowest wavelength, finer than
// one quad at the default resolution, so more would only add aliasing.
constexpr int HILL_OCTAVES = 5;
// Gain of the tanh that spreads the noise over the height range (hillsNoise).
constexpr double TANH_GAIN = 1.5;

struct ShapeName {
    ProceduralShape shape;
    std::string_view name;
};

constexpr std::array<ShapeName, 5> SHAPE_NAMES{{{ProceduralShape::Plane, "plane"},
                                                {ProceduralShape::Hills, "hills"},
                                                {ProceduralShape::Sphere, "sphere"},
                                                {ProceduralShape::Torus, "torus"},
                                                {ProceduralShape::Moebius, "moebius"}}};

// 16 unit gradient directions, every 22.5°: more than Perlin's 4/8 so the hills show no
// axis-aligned ridges.
constexpr double C1 = 0.92387953251128674;  // cos 22.5°
constexpr double S1 = 0.38268343236508978;  // sin 22.5°
constexpr double H1 = 0.70710678118654752;  // cos 45°
constexpr std::array<std::array<double, 2>, 16> GRADIENTS{{{1, 0},
                                                           {C1, S1},
                                                           {H1, H1},
                                                           {S1, C1},
                                                           {0, 1},
                                                           {-S1, C1},
                                                           {-H1, H1},
                                                           {-C1, S1},
                                                           {-1, 0},
                                                           {-C1, -S1},
                                                           {-H1, -H1},
                                                           {-S1, -C1},
                                                           {0, -1},
                                                           {S1, -C1},
                                                           {H1, -H1},
                                                           {C1, -S1}}};

// Hash of a lattice point, so the noise needs no permutation table (hillsHeight is called per
// query; building a table per call would dominate).
const std::array<double, 2>& latticeGradient(std::int64_t ix, std::int64_t iy, std::uint64_t seed) {
    std::uint64_t h = Rng::splitMix(seed ^ static_cast<std::uint64_t>(ix) * 0x9E3779B97F4A7C15ULL);
    h = Rng::splitMix(h ^ static_cast<std::uint64_t>(iy) * 0xC2B2AE3D27D4EB4FULL);
    return GRADIENTS[static_cast<std::size_t>(h >> 60u)];
}

struct NoiseValue {
    double value = 0.0;
    double dx = 0.0;
    double dy = 0.0;
};

// 2D gradient (Perlin) noise with quintic fade and its analytic derivative. With unit
// gradients |value| ≤ √2/2.
NoiseValue gradientNoise(double x, double y, std::uint64_t seed) {
    const double fx0 = std::floor(x), fy0 = std::floor(y);
    const auto ix = static_cast<std::int64_t>(fx0), iy = static_cast<std::int64_t>(fy0);
    const double fx = x - fx0, fy = y - fy0;
    const auto& g00 = latticeGradient(ix, iy, seed);
    const auto& g10 = latticeGradient(ix + 1, iy, seed);
    const auto& g01 = latticeGradient(ix, iy + 1, seed);
    const auto& g11 = latticeGradient(ix + 1, iy + 1, seed);
    const double n00 = g00[0] * fx + g00[1] * fy;
    const double n10 = g10[0] * (fx - 1) + g10[1] * fy;
    const double n01 = g01[0] * fx + g01[1] * (fy - 1);
    const double n11 = g11[0] * (fx - 1) + g11[1] * (fy - 1);
    const double u = fx * fx * fx * (fx * (fx * 6 - 15) + 10);
    const double v = fy * fy * fy * (fy * (fy * 6 - 15) + 10);
    const double du = 30 * fx * fx * (fx * (fx - 2) + 1);
    const double dv = 30 * fy * fy * (fy * (fy - 2) + 1);
    const double k = n00 - n10 - n01 + n11;
    NoiseValue n;
    n.value = n00 + u * (n10 - n00) + v * (n01 - n00) + u * v * k;
    const auto gradient = [&](std::size_t c) {
        return g00[c] + u * (g10[c] - g00[c]) + v * (g01[c] - g00[c]) +
               u * v * (g00[c] - g10[c] - g01[c] + g11[c]);
    };
    n.dx = gradient(0) + du * ((n10 - n00) + v * k);
    n.dy = gradient(1) + dv * ((n01 - n00) + u * k);
    return n;
}

// Fractal sum, |height| ≤ hillHeight / 2 (peak-to-trough at most hillHeight).
// Returns the height and its gradient in metres per metre.
NoiseValue hillsNoise(const ProceduralMeshParams& params, double x, double z) {
    const double scale = params.hillScale > 0.0f ? static_cast<double>(params.hillScale) : 1.0;
    double frequency = 1.0 / scale;
    double amplitude = 1.0, amplitudeSum = 0.0;
    NoiseValue sum;
    for (int octave = 0; octave < HILL_OCTAVES; ++octave) {
        const std::uint64_t octaveSeed =
            Rng::splitMix(params.noiseSeed + static_cast<std::uint64_t>(octave));
        // An offset per octave: gradient noise is 0 at lattice points, and without it every
        // octave would vanish at the origin together.
        const double ox = static_cast<double>(octaveSeed & 0xFFFFu) / 65536.0 * 97.0;
        const double oz = static_cast<double>((octaveSeed >> 16u) & 0xFFFFu) / 65536.0 * 97.0;
        const NoiseValue n = gradientNoise(x * frequency + ox, z * frequency + oz, octaveSeed);
        sum.value += amplitude * n.value;
        sum.dx += amplitude * n.dx * frequency;
        sum.dy += amplitude * n.dy * frequency;
        amplitudeSum += amplitude;
        amplitude *= 0.5;
        frequency *= 2.0;
    }
    // sum / (Σ amplitude · √2/2) lies in [−1, 1] but rarely leaves ±0.7, so a linear map
    // would give hills a third lower than asked. A tanh curve stretches the middle and keeps
    // the bound: |height| ≤ hillHeight / 2 still holds, and over a wide area the relief spans
    // about 0.85 · hillHeight (measured: 200 m × 200 m, hillScale 4, five seeds).
    const double v = sum.value / (amplitudeSum * H1);
    const double t = std::tanh(TANH_GAIN * v);
    const double half = 0.5 * static_cast<double>(params.hillHeight);
    const double slope =
        half * TANH_GAIN * (1.0 - t * t) / (std::tanh(TANH_GAIN) * amplitudeSum * H1);
    return {half * t / std::tanh(TANH_GAIN), sum.dx * slope, sum.dy * slope};
}

// A parametric surface sampled on an (nu + 1) × (nv + 1) grid. Seams keep their own vertices
// (their UVs differ). Each triangle is wound so its face normal agrees with its vertex normals:
// that makes every shape outward-facing (and the Möbius strip consistent away from its seam)
// without per-shape winding rules.
struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 normal;
};

using Parametrisation = std::function<SurfacePoint(double u, double v)>;

void addOrientedTriangle(SurfaceMeshBuilder& builder, const std::vector<SurfacePoint>& points,
                         std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const glm::vec3 face = glm::cross(points[b].position - points[a].position,
                                      points[c].position - points[a].position);
    const glm::vec3 normals = points[a].normal + points[b].normal + points[c].normal;
    if (glm::dot(face, normals) < 0.0f)
        std::swap(b, c);
    builder.addTriangle(a, b, c);
}

// collapseV0/collapseV1: the v = 0 / v = 1 row is a single point (a sphere's pole); the quads
// touching it become one triangle each instead of a degenerate pair.
MovableSurfaceMesh buildGrid(int nu, int nv, const Parametrisation& surface,
                             bool collapseV0 = false, bool collapseV1 = false) {
    SurfaceMeshBuilder builder;
    std::vector<SurfacePoint> points;
    points.reserve(static_cast<std::size_t>((nu + 1) * (nv + 1)));
    const auto index = [nu](int i, int j) { return static_cast<std::uint32_t>(j * (nu + 1) + i); };
    for (int j = 0; j <= nv; ++j) {
        const double v = static_cast<double>(j) / nv;
        for (int i = 0; i <= nu; ++i) {
            double u = static_cast<double>(i) / nu;
            // A pole vertex takes the u of its triangle's centre so the UV is not skewed.
            if ((j == 0 && collapseV0) || (j == nv && collapseV1))
                u = std::min(1.0, (i + 0.5) / nu);
            const SurfacePoint p = surface(u, v);
            points.push_back(p);
            builder.addVertex(p.position, p.normal,
                              glm::vec2(static_cast<float>(u), static_cast<float>(v)));
        }
    }
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            const std::uint32_t a = index(i, j), b = index(i + 1, j);
            const std::uint32_t c = index(i, j + 1), d = index(i + 1, j + 1);
            if (j == 0 && collapseV0) {
                addOrientedTriangle(builder, points, a, c, d);
            } else if (j == nv - 1 && collapseV1) {
                addOrientedTriangle(builder, points, a, c, b);
            } else {
                addOrientedTriangle(builder, points, a, c, d);
                addOrientedTriangle(builder, points, a, d, b);
            }
        }
    }
    return builder.take();
}

glm::vec3 toVec3(double x, double y, double z) {
    return {static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
}

glm::vec3 safeNormalize(glm::dvec3 v, glm::vec3 fallback) {
    const double length = glm::length(v);
    return length > 1e-12 ? glm::vec3(v / length) : fallback;
}

}  // namespace

Result<ProceduralShape> parseProceduralShape(std::string_view name) {
    for (const ShapeName& entry : SHAPE_NAMES) {
        if (entry.name == name)
            return entry.shape;
    }
    std::string valid;
    for (const ShapeName& entry : SHAPE_NAMES) {
        valid += (valid.empty() ? "" : ", ") + std::string(entry.name);
    }
    return makeError(
        "", "unknown procedural shape \"" + std::string(name) + "\"; valid shapes: " + valid);
}

std::string_view proceduralShapeName(ProceduralShape shape) {
    for (const ShapeName& entry : SHAPE_NAMES) {
        if (entry.shape == shape)
            return entry.name;
    }
    return "plane";
}

std::vector<std::string_view> proceduralShapeNames() {
    std::vector<std::string_view> names;
    for (const ShapeName& entry : SHAPE_NAMES)
        names.push_back(entry.name);
    return names;
}

float hillsHeight(const ProceduralMeshParams& params, float x, float z) {
    return static_cast<float>(hillsNoise(params, x, z).value);
}

MovableSurfaceMesh makeProceduralMesh(const ProceduralMeshParams& params) {
    const double size = static_cast<double>(params.size);
    const double minor = static_cast<double>(params.minorSize);
    const int res = std::clamp(params.resolution, 1, MAX_RESOLUTION);
    // Closed shapes need three segments around to enclose any volume.
    const int resClosed = std::clamp(params.resolution, 3, MAX_RESOLUTION);
    switch (params.shape) {
        case ProceduralShape::Plane:
            return buildGrid(res, res, [size](double u, double v) {
                return SurfacePoint{toVec3((u - 0.5) * size, 0.0, (v - 0.5) * size), {0, 1, 0}};
            });
        case ProceduralShape::Hills:
            return buildGrid(res, res, [&params, size](double u, double v) {
                const double x = (u - 0.5) * size, z = (v - 0.5) * size;
                const NoiseValue h = hillsNoise(params, x, z);
                const glm::vec3 n = safeNormalize(glm::dvec3(-h.dx, 1.0, -h.dy), {0, 1, 0});
                return SurfacePoint{toVec3(x, h.value, z), n};
            });
        case ProceduralShape::Sphere:
            // u: longitude, v: polar angle from the north pole (v = 0 is the image's top row).
            return buildGrid(
                resClosed, resClosed,
                [size](double u, double v) {
                    const double phi = 2.0 * PI * u, theta = PI * v;
                    const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                                       -std::sin(theta) * std::sin(phi));
                    return SurfacePoint{glm::vec3(n * size), glm::vec3(n)};
                },
                true, true);
        case ProceduralShape::Torus:
            // u around the Y axis, v around the tube.
            return buildGrid(resClosed, resClosed, [size, minor](double u, double v) {
                const double phi = 2.0 * PI * u, psi = 2.0 * PI * v;
                const glm::dvec3 n(std::cos(psi) * std::cos(phi), std::sin(psi),
                                   -std::cos(psi) * std::sin(phi));
                const glm::dvec3 centre(size * std::cos(phi), 0.0, -size * std::sin(phi));
                return SurfacePoint{glm::vec3(centre + minor * n), glm::vec3(n)};
            });
        case ProceduralShape::Moebius:
            // The centre circle lies in the XZ plane; across the strip t ∈ [−minor, minor] the
            // ruling turns half a revolution over one loop. Normals come from the
            // parametrisation, so they flip across the u = 0/1 seam (the surface is one-sided).
            return buildGrid(resClosed, resClosed, [size, minor](double u, double v) {
                const double phi = 2.0 * PI * u, t = (2.0 * v - 1.0) * minor;
                const double c = std::cos(phi), s = std::sin(phi);
                const double ch = std::cos(0.5 * phi), sh = std::sin(0.5 * phi);
                const double r = size + t * ch;
                const glm::dvec3 p(r * c, t * sh, -r * s);
                const glm::dvec3 dPhi(-0.5 * t * sh * c - r * s, 0.5 * t * ch,
                                      0.5 * t * sh * s - r * c);
                const glm::dvec3 dT(ch * c, sh, -ch * s);
                return SurfacePoint{glm::vec3(p), safeNormalize(glm::cross(dPhi, dT), {0, 1, 0})};
            });
    }
    return MovableSurfaceMesh{};
}

}  // namespace grass::core
