// Scattering blades over any triangle mesh (SPEC §2). Two distributions, combinable:
//  - uniform: expected count = density × ∫ map dA; area-weighted triangle pick, uniform
//    barycentrics;
//  - clumps: centres by Poisson-disk sampling on the surface (minimum distance clumpSpacing,
//    3D Euclidean), blades uniform over the surface within clumpRadius (3D) of each centre.
// A density map in UV space (values in [0, 1]) scales the local density. It only thins: each
// candidate draws the same numbers whatever the map says, so repainting it adds or removes
// blades where it changed and leaves the rest of the field in place. Deterministic per seed;
// blades are uniform first, then clump by clump. Per-blade h, w, s are uniform in BladeRanges,
// theta uniform in [0, 2π), up the interpolated surface normal.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "blade/blade.h"
#include "maps/map_image.h"
#include "mesh/surface_mesh.h"
#include "scatter/surface_sampler.h"

namespace grass::core {

struct BladeRanges {
    float heightMin = 0.25f;  // metres
    float heightMax = 0.55f;
    float widthMin = 0.012f;  // metres, full blade width is 2w at the root (SPEC §7 c ± w·t1)
    float widthMax = 0.022f;
    float stiffnessMin = 40.0f;
    float stiffnessMax = 80.0f;
    bool operator==(const BladeRanges&) const = default;
};

struct ScatterParams {
    float density = 300.0f;     // uniform blades per square metre (0 = none)
    float clumpSpacing = 0.0f;  // Poisson-disk minimum distance between clump centres (0 = none)
    int bladesPerClump = 12;
    float clumpRadius = 0.15f;  // metres
    BladeRanges blade;
    bool operator==(const ScatterParams&) const = default;
};

// A scattered blade, before patching: the GPU layout plus the surface point it came from.
struct ScatterResult {
    std::vector<Blade> blades;
    std::vector<glm::vec2> uvs;    // UV0 of each blade's root, same order as blades
    std::size_t uniformCount = 0;  // blades from the uniform distribution
    std::size_t clumpCount = 0;    // number of clump centres
    std::vector<glm::vec3> clumpCentres;
    std::vector<std::string> warnings;  // e.g. a clamped huge request, for the caller to print
};

// How a density map thins one candidate (scatterCandidates): a uniform candidate (clump < 0)
// survives where keep < map(uv); a clump candidate where its centre survives
// (centreKeep < map(centreUv)) and keep·map(centreUv) < map(uv).
struct CandidateThinning {
    float keep = 0.0f;
    std::int32_t clump = -1;  // into ScatterCandidates::clumps, −1 for a uniform candidate
};

struct ClumpCentre {
    glm::vec3 position{0.0f};
    glm::vec2 uv{0.0f};
    float keep = 0.0f;
};

// Every blade the layer could grow, whatever its density map says, with what thinning needs:
// the map only decides which of them live, so a repaint re-decides only the candidates under
// the brush (scene/layer_growth.h).
struct ScatterCandidates {
    std::vector<Blade> blades;
    std::vector<glm::vec2> uvs;
    std::vector<CandidateThinning> thinning;
    std::vector<std::uint32_t> faces;  // the face of the mesh each candidate stands on
    std::vector<ClumpCentre> clumps;
    std::size_t uniformCount = 0;  // candidates from the uniform distribution (they come first)
    std::vector<std::string> warnings;
};

// Whether candidate i lives under `densityMap` (null: 1 everywhere) scaled by `factor` (the
// layer's placement rules there, placement_rules.h): the map's value at the blade is multiplied
// by it, so a factor of 0 removes the blade whatever the map says.
bool keepsCandidate(const ScatterCandidates& candidates, std::size_t i, const MapImage* densityMap,
                    float factor = 1.0f);

// The most blades one call produces: a guard against a typo'd density (50 M blades are 3.2 GB
// of GPU data), reported through ScatterResult::warnings.
inline constexpr std::size_t MAX_SCATTER_BLADES = 50'000'000;

ScatterCandidates scatterCandidates(const SurfaceMesh& mesh, const ScatterParams& params,
                                    std::uint64_t seed);
// The same on a sampler of the mesh already made (a scene keeps one for all its layers and
// re-grows, Scene::sampler): the same candidates. Clumps need its neighbourhood index
// (scatterNeedsNeighbourhoods): precondition sampler.hasNeighbourhoodIndex() then.
ScatterCandidates scatterCandidates(const SurfaceSampler& sampler, const ScatterParams& params,
                                    std::uint64_t seed);
// Whether these parameters grow clumps, which sample around their centres.
bool scatterNeedsNeighbourhoods(const ScatterParams& params);

// The candidates the map keeps. densityMap may be null (density 1 everywhere).
ScatterResult scatterBlades(const SurfaceMesh& mesh, const ScatterParams& params,
                            const MapImage* densityMap, std::uint64_t seed);

}  // namespace grass::core
