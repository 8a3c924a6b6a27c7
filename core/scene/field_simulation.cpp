#include "scene/field_simulation.h"

#include <algorithm>

#include "physics/physics_simd.h"

namespace grass::core {

FieldSimulation::FieldSimulation(const Scene& scene) {
    reset(scene);
}

std::size_t FieldSimulation::capEta(float etaMax) {
    std::size_t lowered = 0;
    for (Layer& layer : mLayers)
        lowered += core::capEta(layer.eta, etaMax);
    return lowered;
}

void FieldSimulation::reset(const Scene& scene) {
    mLayers.clear();
    for (const LayerField& field : scene.layers) {
        Layer layer;
        layer.blades = field.patched.blades;
        layer.eta.assign(layer.blades.size(), 0.0f);
        layer.restTips = restTipsAsGrown(layer.blades);
        layer.patchSize = field.patched.patchSize;
        mLayers.push_back(std::move(layer));
    }
}

void FieldSimulation::resetPatches(std::size_t layerIndex, const Scene& scene,
                                   std::span<const std::uint32_t> patches) {
    if (layerIndex >= mLayers.size() || layerIndex >= scene.layers.size())
        return;
    Layer& layer = mLayers[layerIndex];
    const std::vector<Blade>& rest = scene.layers[layerIndex].patched.blades;
    if (rest.size() != layer.blades.size()) {  // a re-grow that changed the layout: all of it
        reset(scene);
        return;
    }
    for (const std::uint32_t patch : patches) {
        const std::size_t first = std::size_t(patch) * layer.patchSize;
        const std::size_t end = std::min(first + layer.patchSize, rest.size());
        for (std::size_t i = first; i < end; ++i) {
            layer.blades[i] = rest[i];
            layer.eta[i] = 0.0f;
        }
        const std::vector<glm::vec3> tips =
            restTipsAsGrown(std::span(rest).subspan(first, end - first));
        std::copy(tips.begin(), tips.end(), layer.restTips.begin() + std::ptrdiff_t(first));
    }
}

void FieldSimulation::step(const ScenePhysics& physics, float timeS, unsigned threads) {
    for (std::size_t i = 0; i < mLayers.size(); ++i) {
        Layer& layer = mLayers[i];
        stepPhysicsSimd(layer.blades, layer.eta, layer.restTips, physics.params, physics.wind,
                        physics.colliders, timeS, threads, physics.snowLoad(i, timeS));
    }
}

}  // namespace grass::core
