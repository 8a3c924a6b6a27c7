#include "scatter/scatter.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scatter/poisson_disk.h"
#include "scatter/surface_sampler.h"
#include "util/assert.h"
#include "util/rng.h"

namespace grass::core {

namespace {

constexpr float TWO_PI = 6.28318530717958647692f;
// Darts per point the surface can hold (poissonDiskCapacity): random sequential adsorption is
// within a few per cent of jamming after ~30 darts per final point.
constexpr double DARTS_PER_CAPACITY = 30.0;
// Proposals per clump blade before a clump gives up: the sampler's acceptance rate is the
// surface area inside the ball over the sum of its proposal domains, about 1/4 at worst for
// ordinary meshes (a flat neighbourhood is ≥ πr²·¾ of a domain sum ≤ 3πr²).
constexpr std::size_t ATTEMPTS_PER_CLUMP_BLADE = 64;

// Separate streams: changing the clump settings leaves the uniform blades where they were,
// which is what an artist tweaking one layer of a field expects.
constexpr std::uint64_t STREAM_UNIFORM = 0;
constexpr std::uint64_t STREAM_CLUMP_CENTRES = 1;
constexpr std::uint64_t STREAM_CLUMP_BLADES = 2;

Blade makeBlade(const SurfaceSample& at, const BladeRanges& ranges, Rng& rng) {
    const float h = rng.uniform(ranges.heightMin, ranges.heightMax);
    const float w = rng.uniform(ranges.widthMin, ranges.widthMax);
    const float s = rng.uniform(ranges.stiffnessMin, ranges.stiffnessMax);
    const float theta = rng.uniform(0.0f, TWO_PI);
    return makeRestBlade(at.position, at.normal, h, w, s, theta);
}

std::string countText(double count) {
    return std::to_string(static_cast<unsigned long long>(std::llround(count)));
}

void scatterUniform(const SurfaceSampler& sampler, const ScatterParams& params,
                    std::uint64_t seed, ScatterCandidates& result) {
    const double density = static_cast<double>(params.density);
    if (!(density > 0.0) || !std::isfinite(density))
        return;
    const double expected = density * sampler.totalArea();
    const double candidates = std::min(expected, static_cast<double>(MAX_SCATTER_BLADES));
    if (expected > static_cast<double>(MAX_SCATTER_BLADES)) {
        result.warnings.push_back("density × area asks for " + countText(expected) +
                                  " blade candidates; clamped to " + countText(candidates) +
                                  " (the limit per layer)");
    }
    const auto count = static_cast<std::size_t>(std::llround(candidates));
    Rng rng(seed, STREAM_UNIFORM);
    result.blades.reserve(count);
    result.uvs.reserve(count);
    result.thinning.reserve(count);
    result.faces.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const SurfaceSample at = sampler.sample(rng);
        // Every candidate draws the same numbers whether a map keeps it or not, so painting the
        // map only adds or removes blades where it paints; the rest of the field stays.
        const float keep = rng.uniform();
        result.blades.push_back(makeBlade(at, params.blade, rng));
        result.uvs.push_back(at.uv);
        result.thinning.push_back({keep, -1});
        result.faces.push_back(at.triangle);
    }
    result.uniformCount = result.blades.size();
}

void scatterClumps(const SurfaceSampler& sampler, const ScatterParams& params, std::uint64_t seed,
                   ScatterCandidates& result) {
    if (!scatterNeedsNeighbourhoods(params))
        return;
    const float spacing = params.clumpSpacing;
    const auto perClump = static_cast<std::size_t>(params.bladesPerClump);
    const std::size_t budget =
        MAX_SCATTER_BLADES - std::min(MAX_SCATTER_BLADES, result.blades.size());
    const std::size_t maxCentres = budget / perClump;
    const double capacity = poissonDiskCapacity(sampler.totalArea(), spacing);
    if (capacity * static_cast<double>(perClump) > static_cast<double>(budget)) {
        result.warnings.push_back("clumps could reach " +
                                  countText(capacity * static_cast<double>(perClump)) +
                                  " blades; stopping at " + countText(static_cast<double>(budget)) +
                                  " (the limit per layer)");
    }
    if (maxCentres == 0)
        return;

    // Centres over the whole surface, thinned later by the map: a subset keeps the minimum
    // distance, and the expected clump count follows ∫ map dA (thinning the darts instead
    // would saturate anyway and only tell 0 from non-0).
    Rng centreRng(seed, STREAM_CLUMP_CENTRES);
    PoissonDiskParams disk;
    disk.minDistance = spacing;
    disk.maxPoints = maxCentres;
    disk.maxAttempts = static_cast<std::size_t>(
        DARTS_PER_CAPACITY * std::min(capacity, static_cast<double>(maxCentres)) + 1.0);
    const PoissonDiskResult centres = poissonDiskSample(sampler, disk, centreRng);

    GRASS_ASSERT(sampler.hasNeighbourhoodIndex());
    result.blades.reserve(result.blades.size() + centres.points.size() * perClump);
    result.uvs.reserve(result.blades.capacity());
    result.thinning.reserve(result.blades.capacity());
    const float radius =
        std::isfinite(params.clumpRadius) ? std::max(params.clumpRadius, 0.0f) : 0.0f;
    std::vector<SurfaceSample> around;
    for (std::size_t k = 0; k < centres.points.size(); ++k) {
        const SurfaceSample& centre = centres.points[k];
        // A stream per clump: like the uniform blades, a clump does not change when the map
        // removes another one.
        Rng bladeRng(Rng::splitMix(seed) + k, STREAM_CLUMP_BLADES);
        const auto clump = static_cast<std::int32_t>(result.clumps.size());
        result.clumps.push_back({centre.position, centre.uv, bladeRng.uniform()});
        around.clear();
        if (radius > 0.0f) {
            sampler.sampleNear(centre.position, radius, perClump,
                               ATTEMPTS_PER_CLUMP_BLADE * perClump, bladeRng, around);
        } else {
            around.assign(perClump, centre);
        }
        for (const SurfaceSample& at : around) {
            const float keep = bladeRng.uniform();
            result.blades.push_back(makeBlade(at, params.blade, bladeRng));
            result.uvs.push_back(at.uv);
            result.thinning.push_back({keep, clump});
            result.faces.push_back(at.triangle);
        }
    }
}

}  // namespace

bool keepsCandidate(const ScatterCandidates& candidates, std::size_t i, const MapImage* densityMap,
                    float factor) {
    const bool mapped = densityMap != nullptr && !densityMap->texels.empty();
    if (!mapped && factor >= 1.0f)
        return true;
    const CandidateThinning& thinning = candidates.thinning[i];
    const float here = (mapped ? densityMap->sample(candidates.uvs[i]) : 1.0f) * factor;
    if (thinning.clump < 0)
        return thinning.keep < here;  // survives with probability map(uv) · factor
    // Inside a clump the map thins relative to its centre: a blade survives with probability
    // min(1, map(blade)/map(centre)), so the expected density is min(map(centre), map(blade))
    // ≈ map, and a clump at the edge of a painted-out area stops at that edge instead of
    // spilling over it.
    const ClumpCentre& centre = candidates.clumps[static_cast<std::size_t>(thinning.clump)];
    const float atCentre = mapped ? densityMap->sample(centre.uv) : 1.0f;
    return centre.keep < atCentre && thinning.keep * atCentre < here;
}

bool scatterNeedsNeighbourhoods(const ScatterParams& params) {
    return params.clumpSpacing > 0.0f && std::isfinite(params.clumpSpacing) &&
           params.bladesPerClump > 0;
}

ScatterCandidates scatterCandidates(const SurfaceMesh& mesh, const ScatterParams& params,
                                    std::uint64_t seed) {
    SurfaceSampler sampler(mesh);
    if (scatterNeedsNeighbourhoods(params))
        sampler.buildNeighbourhoodIndex();
    return scatterCandidates(sampler, params, seed);
}

ScatterCandidates scatterCandidates(const SurfaceSampler& sampler, const ScatterParams& params,
                                    std::uint64_t seed) {
    ScatterCandidates result;
    if (sampler.empty())
        return result;
    scatterUniform(sampler, params, seed, result);
    scatterClumps(sampler, params, seed, result);
    return result;
}

ScatterResult scatterBlades(const SurfaceMesh& mesh, const ScatterParams& params,
                            const MapImage* densityMap, std::uint64_t seed) {
    ScatterCandidates candidates = scatterCandidates(mesh, params, seed);
    ScatterResult result;
    result.warnings = std::move(candidates.warnings);
    std::vector<bool> clumpKept(candidates.clumps.size(), false);
    for (std::size_t i = 0; i < candidates.blades.size(); ++i) {
        if (!keepsCandidate(candidates, i, densityMap))
            continue;
        result.blades.push_back(candidates.blades[i]);
        result.uvs.push_back(candidates.uvs[i]);
        if (i < candidates.uniformCount)
            ++result.uniformCount;
    }
    for (std::size_t k = 0; k < candidates.clumps.size(); ++k) {
        const ClumpCentre& centre = candidates.clumps[k];
        if (densityMap == nullptr || densityMap->texels.empty() ||
            centre.keep < densityMap->sample(centre.uv))
            result.clumpCentres.push_back(centre.position);
    }
    result.clumpCount = result.clumpCentres.size();
    return result;
}

}  // namespace grass::core
