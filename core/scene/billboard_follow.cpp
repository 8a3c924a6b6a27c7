#include "scene/billboard_follow.h"

#include <algorithm>

#include "scene/scene.h"

namespace grass::core {

namespace {

// The mean of mix(root, tip, τ) over the upper half τ ∈ [0.5, 1] of a blade.
constexpr float VISIBLE_TIP_SHARE = 0.75f;

// The blades' own candidates, for placementFactors: a root and a face per object.
ScatterCandidates objectRoots(const std::vector<GrassObject>& placed) {
    ScatterCandidates roots;
    roots.blades.reserve(placed.size());
    roots.faces.reserve(placed.size());
    for (const GrassObject& object : placed) {
        roots.blades.push_back(
            makeRestBlade(object.centre, object.up, object.height, object.width, 1.0f, 0.0f));
        roots.faces.push_back(object.face);
    }
    return roots;
}

}  // namespace

glm::vec3 visibleBladeColour(const LayerField& layer, float wilt) {
    const glm::vec3 healthy = glm::mix(layer.rootColor, layer.tipColor, VISIBLE_TIP_SHARE);
    const glm::vec3 poor = glm::mix(layer.poorRootColor, layer.poorTipColor, VISIBLE_TIP_SHARE);
    return glm::mix(healthy, poor, wilt);
}

BillboardFollow billboardFollow(const std::vector<GrassObject>& placed,
                                const std::vector<LayerField>& layers,
                                const std::vector<PlacementRules>& rules, const SurfaceMesh& mesh,
                                const RuleWorld& world, glm::vec3 textureColour) {
    BillboardFollow follow;
    follow.textureColour = textureColour;
    const ScatterCandidates roots = objectRoots(placed);
    double weightSum = 0.0, stiffnessSum = 0.0;
    for (std::size_t i = 0; i < layers.size(); ++i) {
        follow.ruleFactors.push_back(i < rules.size()
                                         ? placementFactors(mesh, roots, rules[i], world)
                                         : std::vector<float>{});
        const double weight = static_cast<double>(layers[i].source.candidates.blades.size());
        follow.layerWeights.push_back(weight);
        weightSum += weight;
        for (const Blade& blade : layers[i].source.candidates.blades)
            stiffnessSum += blade.s();
    }
    const BladeRanges defaults;
    follow.stiffness = weightSum > 0.0
                           ? static_cast<float>(stiffnessSum / weightSum)
                           : 0.5f * (defaults.stiffnessMin + defaults.stiffnessMax);
    return follow;
}

std::vector<GrassObject> followLayers(const std::vector<GrassObject>& placed,
                                      const BillboardFollow& follow,
                                      const std::vector<LayerField>& layers) {
    double weightSum = 0.0;
    for (double weight : follow.layerWeights)
        weightSum += weight;
    if (layers.empty() || !(weightSum > 0.0))
        return placed;
    const glm::vec3 base = follow.textureColour;
    std::vector<GrassObject> living;
    living.reserve(placed.size());
    for (std::size_t o = 0; o < placed.size(); ++o) {
        const GrassObject& object = placed[o];
        double kept = 0.0, heightSum = 0.0;
        glm::dvec3 colourSum(0.0);
        for (std::size_t i = 0; i < layers.size() && i < follow.layerWeights.size(); ++i) {
            const LayerSource& source = layers[i].source;
            const std::vector<float>& rule = follow.ruleFactors[i];
            const float share = densityAt(source, object.uv) * (rule.empty() ? 1.0f : rule[o]);
            // Growth off leaves heights and colours as scattered (growCandidate does the same).
            const BladeGrowth growth =
                source.growthEnabled ? bladeGrowth(growthAt(source, object.uv)) : BladeGrowth{};
            // Mown blades are short blades (cut and regrow): the tufts standing for them too.
            const float height = growth.heightScale * cutShareAt(source, object.uv);
            if (!(height > 0.0f) || !(share > 0.0f))
                continue;  // this layer grows nothing here
            const double blades = follow.layerWeights[i] * static_cast<double>(share);
            kept += blades;
            heightSum += blades * height;
            const glm::vec3 colour = visibleBladeColour(
                layers[i], source.growthEnabled ? 1.0f - growth.colourBlend : 0.0f);
            colourSum += blades * glm::dvec3(colour);
        }
        if (!(kept > 0.0) || !(static_cast<double>(object.keep) < kept / weightSum))
            continue;
        GrassObject grown = object;
        const auto heightScale = static_cast<float>(heightSum / kept);
        grown.height *= heightScale;
        grown.width *= heightScale;
        const glm::vec3 colour(colourSum / kept);
        for (int c = 0; c < 3; ++c)
            grown.tint[c] = base[c] > 0.0f ? std::clamp(colour[c] / base[c], 0.0f, 4.0f) : 1.0f;
        living.push_back(grown);
    }
    return living;
}

}  // namespace grass::core
