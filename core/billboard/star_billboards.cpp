#include "billboard/star_billboards.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "scatter/surface_sampler.h"
#include "util/rng.h"

namespace grass::core {

namespace {

constexpr float TWO_PI = 6.28318530717958647692f;
// The three quads of a star, 60° apart (GPU Gems 1 ch. 7, fig. 7-5).
constexpr float QUAD_STEP_RAD = TWO_PI / 6.0f;
// Wind wave: the main sway travels downwind with this wave number (rad/m, a ~5 m wavelength, so
// neighbouring tufts move nearly but not quite together); the cross sway runs 1.7× faster so
// the motion never looks like a single pendulum.
constexpr float WIND_WAVE_NUMBER = 1.3f;
constexpr float WIND_CROSS_RATE = 1.7f;
constexpr float WIND_MAIN_SHARE = 0.8f;
constexpr float WIND_CROSS_SHARE = 0.2f;

using Cell = std::array<std::int64_t, 3>;

Cell cellOf(glm::vec3 p, float size) {
    if (!(size > 0.0f))
        return {0, 0, 0};
    const glm::vec3 c = glm::floor(p / size);
    return {static_cast<std::int64_t>(c.x), static_cast<std::int64_t>(c.y),
            static_cast<std::int64_t>(c.z)};
}

// Two unit vectors spanning the plane perpendicular to `up`.
void tangentFrame(glm::vec3 up, glm::vec3& tangent, glm::vec3& bitangent) {
    const glm::vec3 helper = std::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    tangent = glm::normalize(glm::cross(helper, up));
    bitangent = glm::cross(up, tangent);
}

// Uniform in [0, 1) from the seed and an index: the top 24 bits of a SplitMix64 hash.
float keepOf(std::uint64_t seed, std::size_t index) {
    const std::uint64_t h = Rng::splitMix(seed ^ (0xD1B54A32D192ED03ULL * (index + 1)));
    return static_cast<float>(h >> 40) * (1.0f / 16777216.0f);
}

float ramp(float start, float end, float d) {
    if (!(end > start))
        return d >= start ? 1.0f : 0.0f;
    const float t = std::clamp((d - start) / (end - start), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

std::vector<GrassObject> placeGrassObjects(const SurfaceMesh& mesh,
                                           const StarBillboardParams& params, std::uint64_t seed) {
    std::vector<GrassObject> objects;
    const SurfaceSampler sampler(mesh);
    const double density = static_cast<double>(params.density);
    if (sampler.empty() || !(density > 0.0) || !std::isfinite(density))
        return objects;
    Rng rng(seed);
    const double expected = density * sampler.totalArea();
    const auto count = static_cast<std::size_t>(std::floor(expected + rng.uniformDouble()));
    const float heightMin = std::min(params.heightRangeM.x, params.heightRangeM.y);
    const float heightMax = std::max(params.heightRangeM.x, params.heightRangeM.y);
    objects.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const SurfaceSample at = sampler.sample(rng);
        GrassObject object;
        object.centre = at.position;
        object.up = at.normal;
        object.height = rng.uniform(heightMin, heightMax);
        object.width = object.height * params.widthToHeight;
        object.rotationRad = rng.uniform(0.0f, TWO_PI);
        object.uv = at.uv;
        object.face = at.triangle;
        object.keep = keepOf(seed, i);
        objects.push_back(object);
    }
    // Clusters in lexicographic cell order (std::map: ordered, so the numbering is deterministic).
    std::map<Cell, std::uint32_t> clusterOfCell;
    for (const GrassObject& object : objects)
        clusterOfCell.emplace(cellOf(object.centre, params.clusterSizeM), 0u);
    std::uint32_t next = 0;
    for (auto& entry : clusterOfCell)
        entry.second = next++;
    for (GrassObject& object : objects)
        object.cluster = clusterOfCell.at(cellOf(object.centre, params.clusterSizeM));
    std::stable_sort(
        objects.begin(), objects.end(),
        [](const GrassObject& a, const GrassObject& b) { return a.cluster < b.cluster; });
    return objects;
}

StarMesh buildStarVertices(const std::vector<GrassObject>& objects) {
    StarMesh mesh;
    std::uint32_t clusterCount = 0;
    for (const GrassObject& object : objects)
        clusterCount = std::max(clusterCount, object.cluster + 1);
    mesh.clusters.resize(clusterCount);
    // Counting sort by cluster, keeping input order within a cluster.
    std::vector<std::uint32_t> objectsIn(clusterCount, 0);
    for (const GrassObject& object : objects)
        ++objectsIn[object.cluster];
    std::vector<std::uint32_t> nextObject(clusterCount, 0);
    std::uint32_t first = 0;
    for (std::uint32_t c = 0; c < clusterCount; ++c) {
        nextObject[c] = first;
        mesh.clusters[c].firstVertex = first * STAR_VERTICES_PER_OBJECT;
        mesh.clusters[c].vertexCount = objectsIn[c] * STAR_VERTICES_PER_OBJECT;
        first += objectsIn[c];
    }
    for (const GrassObject& object : objects)
        mesh.clusters[object.cluster].centre += object.centre;
    for (std::uint32_t c = 0; c < clusterCount; ++c)
        if (objectsIn[c] > 0)
            mesh.clusters[c].centre /= static_cast<float>(objectsIn[c]);

    mesh.vertices.resize(objects.size() * STAR_VERTICES_PER_OBJECT);
    for (const GrassObject& object : objects) {
        const glm::vec3 up = glm::normalize(object.up);
        glm::vec3 tangent, bitangent;
        tangentFrame(up, tangent, bitangent);
        const glm::vec3 top = up * object.height;
        StarVertex* out = &mesh.vertices[nextObject[object.cluster]++ * STAR_VERTICES_PER_OBJECT];
        for (std::uint32_t q = 0; q < STAR_QUADS; ++q) {
            const float angle = object.rotationRad + static_cast<float>(q) * QUAD_STEP_RAD;
            const glm::vec3 across =
                (std::cos(angle) * tangent + std::sin(angle) * bitangent) * (0.5f * object.width);
            const std::array<glm::vec3, 4> corners = {
                object.centre - across, object.centre + across, object.centre + across + top,
                object.centre - across + top};
            const std::array<glm::vec2, 4> uvs = {glm::vec2(0, 1), glm::vec2(1, 1), glm::vec2(1, 0),
                                                  glm::vec2(0, 0)};
            for (std::size_t k = 0; k < 4; ++k) {
                StarVertex& v = out[4 * q + k];
                v.position = corners[k];
                v.uv = uvs[k];
                v.normal = up;
                v.objectCentre = object.centre;
                v.sway = k >= 2 ? 1.0f : 0.0f;
                v.tint = object.tint;
                v.objectHeight = object.height;
            }
        }
    }
    for (StarCluster& cluster : mesh.clusters)
        for (std::uint32_t v = 0; v < cluster.vertexCount; ++v)
            cluster.radius = std::max(
                cluster.radius,
                glm::length(mesh.vertices[cluster.firstVertex + v].position - cluster.centre));
    return mesh;
}

std::vector<std::uint32_t> starQuadIndices(std::size_t objectCount, std::uint32_t keepEvery) {
    const std::size_t every = std::max<std::uint32_t>(keepEvery, 1);
    const std::size_t kept = (objectCount + every - 1) / every;
    std::vector<std::uint32_t> indices;
    indices.reserve(kept * STAR_INDICES_PER_OBJECT);
    for (std::size_t j = 0; j < kept; ++j)
        for (std::size_t q = j * every * STAR_QUADS; q < (j * every + 1) * STAR_QUADS; ++q) {
            const auto base = static_cast<std::uint32_t>(4 * q);
            for (const std::uint32_t corner : {0u, 1u, 2u, 0u, 2u, 3u})
                indices.push_back(base + corner);
        }
    return indices;
}

KeptObjects keptObjects(std::uint32_t first, std::uint32_t count, std::uint32_t keepEvery) {
    const std::uint64_t every = std::max<std::uint32_t>(keepEvery, 1);
    // The multiples of `every` in [first, first + count): j from ⌈first / every⌉ to
    // ⌈(first + count) / every⌉, exclusive.
    const std::uint64_t begin = (first + every - 1) / every;
    const std::uint64_t end = (std::uint64_t(first) + count + every - 1) / every;
    return {static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end - begin)};
}

glm::vec3 billboardWindOffset(glm::vec3 p, float timeS, const BillboardWind& wind) {
    glm::vec2 dir = wind.directionXZ;
    dir = glm::dot(dir, dir) > 0.0f ? glm::normalize(dir) : glm::vec2(1.0f, 0.0f);
    const glm::vec2 cross(-dir.y, dir.x);
    const glm::vec2 pXZ(p.x, p.z);
    const float along = glm::dot(dir, pXZ);
    const float across = glm::dot(cross, pXZ);
    const float omega = TWO_PI * wind.frequencyHz;
    const float mainPhase = omega * timeS - WIND_WAVE_NUMBER * along;
    const float crossPhase = WIND_CROSS_RATE * omega * timeS + 2.1f * along + 1.1f * across;
    const float mainSway = WIND_MAIN_SHARE * (0.5f + 0.5f * std::sin(mainPhase));
    const float crossSway = WIND_CROSS_SHARE * std::cos(crossPhase);
    const glm::vec2 offset = wind.amplitudeM * (mainSway * dir + crossSway * cross);
    return {offset.x, 0.0f, offset.y};
}

float billboardFade(float distanceM, const BillboardFade& fade) {
    return ramp(fade.inStartM, fade.inEndM, distanceM) *
           (1.0f - ramp(fade.outStartM, fade.outEndM, distanceM));
}

}  // namespace grass::core
