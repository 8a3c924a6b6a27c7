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
    return placeGrassObjects(SurfaceSampler(mesh), params, seed);
}

std::vector<GrassObject> placeGrassObjects(const SurfaceSampler& sampler,
                                           const StarBillboardParams& params, std::uint64_t seed) {
    std::vector<GrassObject> objects;
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

StarInstance starInstance(const GrassObject& object) {
    StarInstance star;
    star.centre = object.centre;
    star.height = object.height;
    star.up = glm::normalize(object.up);
    glm::vec3 tangent, bitangent;
    tangentFrame(star.up, tangent, bitangent);
    const float c = std::cos(object.rotationRad), s = std::sin(object.rotationRad);
    const float half = 0.5f * object.width;
    star.across0 = (c * tangent + s * bitangent) * half;
    star.across90 = (c * bitangent - s * tangent) * half;
    star.tintR = object.tint.r;
    star.tintG = object.tint.g;
    star.tintB = object.tint.b;
    return star;
}

StarVertex starVertex(const StarInstance& star, std::uint32_t vertex) {
    // The three quads of a star, 60° apart (GPU Gems 1 ch. 7, fig. 7-5): cos and sin of 0°, 60°
    // and 120°, quad q's half width cos·across0 + sin·across90, the first quad's turned by q·60°
    // (the same numbers as star_vertex.glsl).
    static constexpr std::array<glm::vec2, STAR_QUADS> TURN = {
        glm::vec2(1.0f, 0.0f), glm::vec2(0.5f, 0.8660254f), glm::vec2(-0.5f, 0.8660254f)};
    const glm::vec2 turn = TURN[vertex / 4 % STAR_QUADS];
    const std::uint32_t corner = vertex % 4;
    const glm::vec3 across = turn.x * star.across0 + turn.y * star.across90;
    const bool right = corner == 1 || corner == 2, top = corner >= 2;
    StarVertex v;
    v.position =
        star.centre + (right ? across : -across) + (top ? star.up * star.height : glm::vec3(0.0f));
    v.uv = glm::vec2(right ? 1.0f : 0.0f, top ? 0.0f : 1.0f);
    v.normal = star.up;
    v.objectCentre = star.centre;
    v.sway = top ? 1.0f : 0.0f;
    v.tint = glm::vec3(star.tintR, star.tintG, star.tintB);
    v.objectHeight = star.height;
    return v;
}

StarInstances buildStarInstances(const std::vector<GrassObject>& objects) {
    StarInstances out;
    std::uint32_t clusterCount = 0;
    for (const GrassObject& object : objects)
        clusterCount = std::max(clusterCount, object.cluster + 1);
    out.clusters.resize(clusterCount);
    // Counting sort by cluster, keeping input order within a cluster.
    std::vector<std::uint32_t> objectsIn(clusterCount, 0);
    for (const GrassObject& object : objects)
        ++objectsIn[object.cluster];
    std::vector<std::uint32_t> nextObject(clusterCount, 0);
    std::uint32_t first = 0;
    for (std::uint32_t c = 0; c < clusterCount; ++c) {
        nextObject[c] = first;
        out.clusters[c].firstVertex = first * STAR_VERTICES_PER_OBJECT;
        out.clusters[c].vertexCount = objectsIn[c] * STAR_VERTICES_PER_OBJECT;
        first += objectsIn[c];
    }
    for (const GrassObject& object : objects)
        out.clusters[object.cluster].centre += object.centre;
    for (std::uint32_t c = 0; c < clusterCount; ++c)
        if (objectsIn[c] > 0)
            out.clusters[c].centre /= static_cast<float>(objectsIn[c]);
    out.stars.resize(objects.size());
    for (const GrassObject& object : objects) {
        const StarInstance star = starInstance(object);
        out.stars[nextObject[object.cluster]++] = star;
        // Every vertex lies within the radius of its cluster's centre.
        StarCluster& cluster = out.clusters[object.cluster];
        for (std::uint32_t v = 0; v < STAR_VERTICES_PER_OBJECT; ++v)
            cluster.radius = std::max(cluster.radius,
                                      glm::length(starVertex(star, v).position - cluster.centre));
    }
    return out;
}

StarMesh buildStarVertices(const std::vector<GrassObject>& objects) {
    StarInstances instances = buildStarInstances(objects);
    StarMesh mesh;
    mesh.clusters = std::move(instances.clusters);
    mesh.vertices.reserve(instances.stars.size() * STAR_VERTICES_PER_OBJECT);
    for (const StarInstance& star : instances.stars)
        for (std::uint32_t v = 0; v < STAR_VERTICES_PER_OBJECT; ++v)
            mesh.vertices.push_back(starVertex(star, v));
    return mesh;
}

std::vector<std::uint32_t> starQuadIndices(std::size_t objectCount) {
    std::vector<std::uint32_t> indices;
    indices.reserve(objectCount * STAR_INDICES_PER_OBJECT);
    const std::size_t quads = objectCount * STAR_QUADS;
    for (std::size_t q = 0; q < quads; ++q) {
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
