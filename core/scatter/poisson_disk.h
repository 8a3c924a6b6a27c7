// Poisson-disk sampling on a triangle mesh (SPEC §2, clump centres) by dart throwing: uniform
// surface points, each kept when no kept point lies within `minDistance` (3D Euclidean, in the
// mesh's units), checked through a spatial hash with cells of that size. The number of darts
// is bounded, so it always terminates; the set is maximal only in the limit of many darts.
#pragma once

#include <cstddef>
#include <vector>

#include "scatter/surface_sampler.h"
#include "util/rng.h"

namespace grass::core {

struct PoissonDiskParams {
    float minDistance = 1.0f;
    std::size_t maxPoints = 0;    // stop once this many are kept
    std::size_t maxAttempts = 0;  // darts thrown at most
};

struct PoissonDiskResult {
    std::vector<SurfaceSample> points;  // in the order they were kept
    std::size_t attempts = 0;
    bool reachedMaxPoints = false;
};

// Deterministic for a given rng state. An empty sampler or minDistance <= 0 gives no points.
PoissonDiskResult poissonDiskSample(const SurfaceSampler& sampler, const PoissonDiskParams& params,
                                    Rng& rng);

// The most points with pairwise distance ≥ minDistance that fit on `area` if it were flat: one
// per hexagon of a hexagonal packing, 2·area / (√3·minDistance²), rounded up. Dart throwing
// typically stops near 60 % of it (random sequential adsorption jams at about 0.547 coverage).
double poissonDiskCapacity(double area, float minDistance);

}  // namespace grass::core
