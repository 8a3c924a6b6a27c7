// Layer growth: how a grass layer's candidates (every blade it could grow, scatter.h) become the
// patched blades the GPU draws, under the layer's environment maps (SPEC §9, §12):
//   - density thins the candidates (a thinned candidate's slot holds a null blade, h = w = 0);
//   - with growth on, soil quality g and light amount l set each blade's height (β), width
//     (α/0.25), rest lean (θ, towards the blade's front) and colour (b, between the layer's
//     healthy and poor colours), through the layer's control curves.
// Patches are built once over all candidates, so the slot of every candidate never moves: a
// repaint re-grows the patches whose blades it can reach and nothing else (regrowRegion), and
// the renderer re-uploads only those slots.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "blade/blade.h"
#include "scene/bending_cues.h"
#include "growth/growth_curves.h"
#include "growth/growth_stems.h"
#include "maps/map_image.h"
#include "project/project.h"
#include "scatter/patches.h"
#include "scatter/scatter.h"

namespace grass::core {

// A layer's environment maps in its mesh's UV space; a map without texels reads 1 everywhere.
struct LayerMaps {
    MapImage density;
    MapImage soil;
    MapImage light;
    MapImage cut;  // the height blades are cut to, a share of their own (issue 30 item 10)
};

enum class LayerMap { Density, Soil, Light, Cut };
MapImage& layerMap(LayerMaps& maps, LayerMap which);
const MapImage& layerMap(const LayerMaps& maps, LayerMap which);
// Every map, and its name as the CLI, the panels and default file names spell it.
inline constexpr std::array<LayerMap, 4> ALL_LAYER_MAPS{LayerMap::Density, LayerMap::Soil,
                                                        LayerMap::Light, LayerMap::Cut};
inline constexpr std::array<const char*, 4> LAYER_MAP_NAMES{"density", "soil", "light", "cut"};
constexpr const char* layerMapName(LayerMap which) {
    return LAYER_MAP_NAMES[static_cast<std::size_t>(which)];
}
// The project's file name of a layer's map (empty: none painted yet).
std::string& layerMapFile(GrassLayer& layer, LayerMap which);
const std::string& layerMapFile(const GrassLayer& layer, LayerMap which);

// What a layer's field is grown from, kept next to it so repaints can re-grow parts of it.
struct LayerSource {
    ScatterCandidates candidates;
    LayerMaps maps;
    // Per candidate, the layer's placement rules there (placement_rules.h); empty: 1 everywhere.
    std::vector<float> ruleFactors;
    // Per candidate, what the layer's bending cues do to it (bending_cues.h); empty: nothing.
    std::vector<CandidateBend> bends;
    float sway = 0.0f;
    bool growthEnabled = false;
    GrowthCurves curves;
    int stemLevels = MAX_STEM_LEVELS;
    float stemTipWidth = 0.0f;  // GrowthDesc::stemTipWidth
    // Cut blades grow back by regrowRate of their height a second; regrowthS is the scene time
    // the field has grown since the cut map was painted (regrowCut moves it).
    float regrowRate = 0.0f;
    float regrowthS = 0.0f;
};

// What the layer's maps say at `uv`, for its candidates and for anything standing for them (the
// billboards, scene/billboard_follow.h): the growth model's inputs there (the best conditions
// with growth off: soil and light count only with it on), and the share of its height a blade
// keeps there, its cut map plus what it regrew, at most 1 (1 without a cut map).
// The density map's value there (1 without a map) is the share of candidates a layer keeps
// before its rules.
GrowthParams growthAt(const LayerSource& source, glm::vec2 uv);
float cutShareAt(const LayerSource& source, glm::vec2 uv);
float densityAt(const LayerSource& source, glm::vec2 uv);

// The grown field: per slot of `patched` (patch-major, padding included) the blade, how far its
// colour leans to the poor colours (wilt = 1 − b; 0 without growth), and every STEMS_PER_SET-th
// slot's stem set for the growth technique (a null set, metresPerUnit 0, where that slot holds no
// blade).
struct GrownField {
    PatchedBlades patched;
    std::vector<float> wilt;
    std::vector<StemSetInstance> stemSets;  // stemSets[k] grows at slot STEMS_PER_SET·k
    std::size_t liveBlades = 0;
};

// What one candidate grows into (its slot's blade) and its wilt; a null blade at the
// candidate's root when the density map removes it or the growth model leaves it no height.
struct GrownBlade {
    Blade blade;
    float wilt = 0.0f;
    bool live = false;
};
GrownBlade growCandidate(const LayerSource& source, std::size_t candidate);

// Stem sets per blade of the growth technique, in model units (growth_stems.h): the six stems
// fan out this far around the set's centre.
inline constexpr float STEM_SET_SPREAD = 0.25f;

// Patches all candidates and grows every slot. `stop`: a request ends the growing between
// patches (the field is then partly grown: its builder drops it).
GrownField growField(const LayerSource& source, std::uint32_t patchSize, std::stop_token stop = {});

// Re-grows the slots of `patches` (indices into field.patched.patches) from their candidates,
// updating blades, wilt, stem sets and liveBlades. Returns how many slots gained or lost their
// blade: only those change the neighbourhoods the shading bake sums (it counts blades and
// their surface normals, which growth never changes).
std::size_t regrowPatches(const LayerSource& source, std::span<const std::uint32_t> patches,
                   GrownField& field);

// The patches holding a candidate whose root lies inside `region` (sorted, unique). A texel a
// brush changed moves only candidates whose bilinear footprint covers it, so callers pass the
// painted region grown by a texel's size on the surface.
std::vector<std::uint32_t> patchesWithRootsIn(const LayerSource& source, const GrownField& field,
                                              const Bounds& region);

// The first and one-past-last stem set of a patch (for uploads of regrown patches).
std::pair<std::size_t, std::size_t> patchStemSets(const GrownField& field, std::uint32_t patch);

}  // namespace grass::core
