#include "snow/snow_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "snow/snow_noise.h"
#include "util/assert.h"

namespace grass::core {

// Texel positions far outside any map are clamped so float → int stays defined (the samples
// there read SNOW_MAP_EMPTY either way).
int snowTexelIndex(float t) {
    const float clamped = std::clamp(t, -SNOW_MAX_TEXEL_COORD, SNOW_MAX_TEXEL_COORD);
    return static_cast<int>(std::floor(clamped));
}

namespace {

// Twice the signed area of (a, b, p) in the map plane.
double edge(const glm::dvec3& a, const glm::dvec3& b, double px, double py) {
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

void rasterise(SnowDepthMap& map, const std::array<glm::vec3, 3>& triangle) {
    const double res = map.resolution;
    std::array<glm::dvec3, 3> t{};
    for (std::size_t i = 0; i < 3; ++i) {
        const glm::vec3 c = snowMapCoords(map.view, triangle[i]);
        t[i] = {c.x * res, c.y * res, c.z};
    }
    const double area = edge(t[0], t[1], t[2].x, t[2].y);
    if (std::abs(area) < 1e-12)
        return;
    const double minX = std::min({t[0].x, t[1].x, t[2].x});
    const double maxX = std::max({t[0].x, t[1].x, t[2].x});
    const double minY = std::min({t[0].y, t[1].y, t[2].y});
    const double maxY = std::max({t[0].y, t[1].y, t[2].y});
    // Texels whose centre (i + ½) lies in [min, max].
    const int x0 = std::max(0, static_cast<int>(std::ceil(minX - 0.5)));
    const int x1 = std::min(map.resolution - 1, static_cast<int>(std::floor(maxX - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(minY - 0.5)));
    const int y1 = std::min(map.resolution - 1, static_cast<int>(std::floor(maxY - 0.5)));
    for (int iy = y0; iy <= y1; ++iy) {
        for (int ix = x0; ix <= x1; ++ix) {
            const double px = ix + 0.5, py = iy + 0.5;
            // Barycentric weights, positive inside whichever way the triangle winds.
            const double w0 = edge(t[1], t[2], px, py) / area;
            const double w1 = edge(t[2], t[0], px, py) / area;
            const double w2 = edge(t[0], t[1], px, py) / area;
            if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0)
                continue;
            const auto depth = static_cast<float>(w0 * t[0].z + w1 * t[1].z + w2 * t[2].z);
            float& stored =
                map.depthM[static_cast<std::size_t>(iy) * static_cast<std::size_t>(map.resolution) +
                           static_cast<std::size_t>(ix)];
            stored = std::min(stored, depth);
        }
    }
}

}  // namespace

OrthoSnowView makeOrthoSnowView(glm::vec3 fallDirection, const Bounds& bounds, float marginM) {
    GRASS_ASSERT(glm::length(fallDirection) > 0.0f && marginM >= 0.0f);
    OrthoSnowView view;
    view.forward = glm::normalize(fallDirection);
    const glm::vec3 helper =
        std::abs(view.forward.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    view.right = glm::normalize(helper - view.forward * glm::dot(helper, view.forward));
    view.up = glm::cross(view.forward, view.right);
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(-std::numeric_limits<float>::max());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{(corner & 1) ? bounds.max.x : bounds.min.x,
                          (corner & 2) ? bounds.max.y : bounds.min.y,
                          (corner & 4) ? bounds.max.z : bounds.min.z};
        const glm::vec3 q{glm::dot(p, view.right), glm::dot(p, view.up), glm::dot(p, view.forward)};
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    // Square texels: the longer side sets the size, the shorter one is centred.
    view.sizeM = std::max({hi.x - lo.x, hi.y - lo.y, 1e-3f}) + 2.0f * marginM;
    view.depthRangeM = std::max(hi.z - lo.z, 1e-3f) + 2.0f * marginM;
    const glm::vec2 centre = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
    view.origin = view.right * (centre.x - 0.5f * view.sizeM) +
                  view.up * (centre.y - 0.5f * view.sizeM) + view.forward * (lo.z - marginM);
    return view;
}

glm::vec3 snowMapCoords(const OrthoSnowView& view, glm::vec3 posWorld) {
    const glm::vec3 d = posWorld - view.origin;
    return {glm::dot(d, view.right) / view.sizeM, glm::dot(d, view.up) / view.sizeM,
            glm::dot(d, view.forward)};
}

glm::vec3 snowMapToWorld(const OrthoSnowView& view, glm::vec3 mapCoords) {
    return view.origin + view.right * (mapCoords.x * view.sizeM) +
           view.up * (mapCoords.y * view.sizeM) + view.forward * mapCoords.z;
}

float SnowDepthMap::at(int ix, int iy) const {
    if (ix < 0 || iy < 0 || ix >= resolution || iy >= resolution)
        return SNOW_MAP_EMPTY;
    return depthM[static_cast<std::size_t>(iy) * static_cast<std::size_t>(resolution) +
                  static_cast<std::size_t>(ix)];
}

SnowDepthMap renderSnowDepthMap(std::span<const std::array<glm::vec3, 3>> triangles,
                                const OrthoSnowView& view, int resolution) {
    GRASS_ASSERT(resolution > 0);
    SnowDepthMap map;
    map.view = view;
    map.resolution = resolution;
    map.depthM.assign(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution),
                      SNOW_MAP_EMPTY);
    for (const auto& triangle : triangles)
        rasterise(map, triangle);
    return map;
}

std::vector<std::array<glm::vec3, 3>> snowTriangles(const SurfaceMesh& mesh) {
    std::vector<std::array<glm::vec3, 3>> out;
    out.reserve(mesh.n_faces());
    for (const auto face : mesh.faces())
        out.push_back(facePositions(mesh, face));
    return out;
}

float exposureCoefficient(const SnowDepthMap& map, glm::vec3 posWorld, glm::vec3 normal,
                          int samples, float radiusTexels, float biasM) {
    GRASS_ASSERT(samples >= 1 && radiusTexels >= 0.0f && map.resolution > 0);
    const glm::vec3 c = snowMapCoords(map.view, posWorld);
    const float res = static_cast<float>(map.resolution);
    const glm::vec2 centre{c.x * res, c.y * res};
    const auto ix = static_cast<std::uint32_t>(snowTexelIndex(centre.x));
    const auto iy = static_cast<std::uint32_t>(snowTexelIndex(centre.y));
    // tan φ from cos φ without a division by zero: vertical and overhanging faces get the cap.
    const float cosPhi = glm::dot(glm::normalize(normal), -map.view.forward);
    const float sinPhi = std::sqrt(std::max(0.0f, 1.0f - cosPhi * cosPhi));
    const float slope =
        sinPhi < SNOW_MAX_SLOPE_BIAS * cosPhi ? sinPhi / cosPhi : SNOW_MAX_SLOPE_BIAS;
    const float texelM = map.texelSizeM();
    const float twoPi = 2.0f * std::numbers::pi_v<float>;
    const float n = static_cast<float>(samples);
    const float rotation = twoPi * hashToUnit(pcg3d(glm::uvec3(ix, iy, 0u)).x);
    int exposed = 0;
    for (int k = 0; k < samples; ++k) {
        const glm::uvec3 h = pcg3d(glm::uvec3(ix, iy, static_cast<std::uint32_t>(k) + 1u));
        const float fk = static_cast<float>(k);
        const float r = radiusTexels * std::sqrt((fk + hashToUnit(h.x)) / n);
        const float angle =
            rotation + fk * SNOW_GOLDEN_ANGLE + (hashToUnit(h.y) - 0.5f) * (twoPi / n);
        const glm::vec2 s = centre + r * glm::vec2(std::cos(angle), std::sin(angle));
        const float stored = map.at(snowTexelIndex(s.x), snowTexelIndex(s.y));
        // The texel's depth was taken at its centre, up to half a diagonal from the sample.
        const float bias = biasM + (r + SNOW_HALF_TEXEL_DIAGONAL) * texelM * slope;
        if (stored >= c.z - bias)
            ++exposed;
    }
    return static_cast<float>(exposed) / n;
}

}  // namespace grass::core
