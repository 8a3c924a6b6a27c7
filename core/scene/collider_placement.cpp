#include "scene/collider_placement.h"

#include <algorithm>
#include <cstdint>

#include "scene/bending_cues.h"

namespace grass::core {

namespace {

bool sameBend(const CandidateBend& a, const CandidateBend& b) {
    return a.leanRad == b.leanRad && a.downhill == b.downhill;
}

// The patches holding a candidate whose factor or bend differs between the two (an empty
// vector stands for 1 everywhere, or no bend), sorted.
std::vector<std::uint32_t> changedPatches(const LayerField& field,
                                          const std::vector<float>& oldFactors,
                                          const std::vector<float>& newFactors,
                                          const std::vector<CandidateBend>& oldBends,
                                          const std::vector<CandidateBend>& newBends) {
    const auto factorAt = [](const std::vector<float>& factors, std::size_t i) {
        return factors.empty() ? 1.0f : factors[i];
    };
    const auto bendAt = [](const std::vector<CandidateBend>& bends, std::size_t i) {
        return bends.empty() ? CandidateBend{} : bends[i];
    };
    std::vector<std::uint32_t> patches;
    const std::size_t size = field.patched.patchSize;
    for (std::size_t slot = 0; slot < field.patched.sourceIndex.size(); ++slot) {
        const std::uint32_t candidate = field.patched.sourceIndex[slot];
        const auto patch = static_cast<std::uint32_t>(slot / size);
        if (candidate == UINT32_MAX || (!patches.empty() && patches.back() == patch))
            continue;
        if (factorAt(oldFactors, candidate) != factorAt(newFactors, candidate) ||
            !sameBend(bendAt(oldBends, candidate), bendAt(newBends, candidate)))
            patches.push_back(patch);
    }
    return patches;
}

}  // namespace

Result<std::vector<std::pair<std::size_t, RegrowReport>>> followColliderPlacement(
    Scene& scene, const Project& project) {
    std::vector<std::pair<std::size_t, RegrowReport>> changed;
    const RuleWorld world = ruleWorldOf(project, scene.props);
    const std::size_t layers = std::min(scene.layers.size(), project.layers.size());
    for (std::size_t i = 0; i < layers; ++i) {
        const GrassLayer& layer = project.layers[i];
        if (!layer.rules.clearColliders)
            continue;
        LayerField& field = scene.layers[i];
        LayerSource& source = field.source;
        std::vector<float> factors =
            placementFactors(scene.mesh, source.candidates, layer.rules, world);
        // The bends read the factors only through the neighbours' shade: those within reach of
        // a changed factor are made again (the whole layer's took seconds at a million blades).
        std::vector<std::uint32_t> changedFactors;
        for (std::uint32_t c = 0; c < factors.size(); ++c)
            if (source.ruleFactors.empty() || source.ruleFactors[c] != factors[c])
                changedFactors.push_back(c);
        std::vector<CandidateBend> bends = source.bends;
        updateCandidateBends(layer.bending, source.candidates, factors, world, changedFactors,
                             bends);
        std::vector<std::uint32_t> patches =
            changedPatches(field, source.ruleFactors, factors, source.bends, bends);
        source.ruleFactors = std::move(factors);
        source.bends = std::move(bends);
        if (patches.empty())
            continue;
        auto report = regrowLayerPatches(field, std::move(patches), project.lighting);
        if (!report)
            return report.error();
        changed.emplace_back(i, std::move(*report));
    }
    // The billboards keep the layers' rules at each placed object: those near the colliders
    // change with them.
    BillboardLayer& billboards = scene.billboards;
    if (billboards.unplaced) {
        billboards.unplaced->world = world;
    } else if (!billboards.placed.empty()) {
        std::vector<PlacementRules> rules;
        for (const GrassLayer& layer : project.layers)
            rules.push_back(layer.rules);
        billboards.follow = billboardFollow(billboards.placed, scene.layers, rules, scene.mesh,
                                            world, billboards.follow.textureColour);
        refreshBillboards(scene);
    }
    return changed;
}

}  // namespace grass::core
