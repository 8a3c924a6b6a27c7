#include "scene/layer_growth.h"

#include <algorithm>
#include <cmath>

#include "physics/physics.h"

namespace grass::core {

namespace {

float sampleOrOne(const MapImage& map, glm::vec2 uv) {
    return map.texels.empty() ? 1.0f : map.sample(uv);
}

GrowthParams candidateGrowth(const LayerSource& source, std::size_t candidate) {
    return growthAt(source, source.candidates.uvs[candidate]);
}

// The stem set grown at a slot's candidate: the set stands on the surface (up is the surface
// normal, not a leaned blade's), turned by the blade's theta, and sized so that β = 1 grows it
// to the candidate's height over any number of levels; its width follows α like the blade's.
StemSetInstance stemSetFor(const LayerSource& source, std::size_t candidate) {
    const Blade& c = source.candidates.blades[candidate];
    const GrowthParams growth = candidateGrowth(source, candidate);
    const float metresPerUnit = c.h() / static_cast<float>(std::clamp(source.stemLevels, 1, 4));
    StemSetInstance set;
    set.rootMetresPerUnit = glm::vec4(c.v0(), metresPerUnit);
    set.upYaw = glm::vec4(c.up(), c.theta());
    set.alphaBetaThetaB = glm::vec4(growth.alpha, growth.beta, growth.theta, growth.b);
    const float widthScale = bladeGrowth(growth).widthScale;
    set.halfWidthSpread = glm::vec4(metresPerUnit > 0.0f ? c.w() * widthScale / metresPerUnit : 0.0f,
                                    STEM_SET_SPREAD, STEM_SET_SPREAD,
                                    std::clamp(source.stemTipWidth, 0.0f, 1.0f));
    return set;
}

StemSetInstance nullStemSet(const Blade& candidate) {
    StemSetInstance set;
    set.rootMetresPerUnit = glm::vec4(candidate.v0(), 0.0f);
    return set;
}

// Returns how many slots changed between holding a blade and not.
std::size_t growSlots(const LayerSource& source, std::uint32_t patch, GrownField& field) {
    const std::uint32_t size = field.patched.patchSize;
    const std::size_t first = static_cast<std::size_t>(patch) * size;
    std::size_t flipped = 0;
    for (std::size_t slot = first; slot < first + size; ++slot) {
        const std::uint32_t candidate = field.patched.sourceIndex[slot];
        const bool wasLive = field.patched.blades[slot].h() > 0.0f;
        if (candidate == UINT32_MAX)
            continue;  // padding stays padding, its stem set null
        const GrownBlade grown = growCandidate(source, candidate);
        field.patched.blades[slot] = grown.blade;
        field.wilt[slot] = grown.wilt;
        if (slot % STEMS_PER_SET == 0)
            field.stemSets[slot / STEMS_PER_SET] =
                grown.live ? stemSetFor(source, candidate)
                           : nullStemSet(source.candidates.blades[candidate]);
        field.liveBlades = field.liveBlades - (wasLive ? 1 : 0) + (grown.live ? 1 : 0);
        flipped += wasLive != grown.live ? 1 : 0;
    }
    return flipped;
}

}  // namespace

MapImage& layerMap(LayerMaps& maps, LayerMap which) {
    switch (which) {
    case LayerMap::Soil: return maps.soil;
    case LayerMap::Light: return maps.light;
    case LayerMap::Cut: return maps.cut;
    case LayerMap::Density: break;
    }
    return maps.density;
}

std::string& layerMapFile(GrassLayer& layer, LayerMap which) {
    return which == LayerMap::Density ? layer.densityMap
           : which == LayerMap::Soil  ? layer.soilMap
           : which == LayerMap::Light ? layer.lightMap
                                      : layer.cutMap;
}

const std::string& layerMapFile(const GrassLayer& layer, LayerMap which) {
    return layerMapFile(const_cast<GrassLayer&>(layer), which);
}

const MapImage& layerMap(const LayerMaps& maps, LayerMap which) {
    return layerMap(const_cast<LayerMaps&>(maps), which);
}

GrowthParams growthAt(const LayerSource& source, glm::vec2 uv) {
    if (!source.growthEnabled)
        return growthParams(source.curves, 1.0f, 1.0f);
    return growthParams(source.curves, sampleOrOne(source.maps.soil, uv),
                        sampleOrOne(source.maps.light, uv));
}

float densityAt(const LayerSource& source, glm::vec2 uv) {
    return sampleOrOne(source.maps.density, uv);
}

float cutShareAt(const LayerSource& source, glm::vec2 uv) {
    if (source.maps.cut.texels.empty())
        return 1.0f;
    const float regrown = std::max(source.regrowRate, 0.0f) * std::max(source.regrowthS, 0.0f);
    return std::min(source.maps.cut.sample(uv) + regrown, 1.0f);
}

GrownBlade growCandidate(const LayerSource& source, std::size_t candidate) {
    const Blade& c = source.candidates.blades[candidate];
    const GrownBlade removed{makeRestBlade(c.v0(), c.up(), 0.0f, 0.0f, c.s(), c.theta()), 0.0f,
                             false};
    const MapImage* density = source.maps.density.texels.empty() ? nullptr : &source.maps.density;
    const float rule = source.ruleFactors.empty() ? 1.0f : source.ruleFactors[candidate];
    if (!keepsCandidate(source.candidates, candidate, density, rule))
        return removed;
    const CandidateBend* bend = source.bends.empty() ? nullptr : &source.bends[candidate];
    const float cut = cutShareAt(source, source.candidates.uvs[candidate]);
    if (!(cut > 0.0f))
        return removed;  // mown to the ground
    if (!source.growthEnabled) {
        const float h = c.h() * cut;
        if (bend)
            return {bentRestBlade(c, h, c.w(), 0.0f, *bend, source.sway), 0.0f, true};
        return {cut < 1.0f ? makeRestBlade(c.v0(), c.up(), h, c.w(), c.s(), c.theta()) : c, 0.0f,
                true};
    }
    const BladeGrowth growth = bladeGrowth(candidateGrowth(source, candidate));
    const float h = c.h() * growth.heightScale * cut;
    const float w = c.w() * growth.widthScale;
    if (!(h > 0.0f) || !(w > 0.0f))
        return removed;
    GrownBlade grown{makeRestBlade(c.v0(), c.up(), h, w, c.s(), c.theta()),
                     1.0f - growth.colourBlend, true};
    // Leaned towards the blade's front, the side front gravity pulls it to (SPEC §3), so a lean
    // and a droop agree; validation places v1 and keeps the length h.
    if (bend)
        grown.blade = bentRestBlade(c, h, w, growth.restLeanRad, *bend, source.sway);
    else
        leanTowardsFront(grown.blade, growth.restLeanRad);
    return grown;
}

GrownField growField(const LayerSource& source, std::uint32_t patchSize, std::stop_token stop) {
    GrownField field;
    field.patched = buildPatches(source.candidates.blades, patchSize);
    const std::size_t slots = field.patched.blades.size();
    field.wilt.assign(slots, 0.0f);
    field.stemSets.assign((slots + STEMS_PER_SET - 1) / STEMS_PER_SET, StemSetInstance{});
    for (std::size_t k = 0; k < field.stemSets.size(); ++k)
        field.stemSets[k] = nullStemSet(field.patched.blades[k * STEMS_PER_SET]);
    // Every candidate starts live (buildPatches copied them); growing corrects the count.
    field.liveBlades = source.candidates.blades.size();
    for (std::uint32_t p = 0; p < field.patched.patches.size() && !stop.stop_requested(); ++p)
        growSlots(source, p, field);
    return field;
}

std::size_t regrowPatches(const LayerSource& source, std::span<const std::uint32_t> patches,
                          GrownField& field) {
    std::size_t flipped = 0;
    for (std::uint32_t p : patches)
        if (p < field.patched.patches.size())
            flipped += growSlots(source, p, field);
    return flipped;
}

std::vector<std::uint32_t> patchesWithRootsIn(const LayerSource& source, const GrownField& field,
                                              const Bounds& region) {
    std::vector<std::uint32_t> found;
    const std::uint32_t size = field.patched.patchSize;
    for (std::uint32_t p = 0; p < field.patched.patches.size(); ++p) {
        // The box covers every candidate's reach, so it is a safe first test.
        if (!field.patched.patches[p].bounds.overlaps(region))
            continue;
        const std::size_t first = static_cast<std::size_t>(p) * size;
        for (std::size_t slot = first; slot < first + size; ++slot) {
            const std::uint32_t candidate = field.patched.sourceIndex[slot];
            if (candidate != UINT32_MAX &&
                region.contains(source.candidates.blades[candidate].v0())) {
                found.push_back(p);
                break;
            }
        }
    }
    return found;
}

std::pair<std::size_t, std::size_t> patchStemSets(const GrownField& field, std::uint32_t patch) {
    const std::size_t size = field.patched.patchSize;
    const std::size_t first = patch * size, last = first + size;
    const auto firstSet = (first + STEMS_PER_SET - 1) / STEMS_PER_SET;
    const auto endSet = std::min((last + STEMS_PER_SET - 1) / STEMS_PER_SET, field.stemSets.size());
    return {firstSet, endSet};
}

}  // namespace grass::core
