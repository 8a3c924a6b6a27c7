#include "scene_physics_gpu.h"

#include <cstring>

namespace grass::render {

Result<ScenePhysicsGpu> ScenePhysicsGpu::create(const core::Scene& scene) {
    ScenePhysicsGpu out;
    for (const core::LayerField& field : scene.layers) {
        auto physics = PhysicsGpu::load();
        if (!physics)
            return physics.error();
        Layer layer{gl::Buffer::fromVector(field.patched.blades, "physics blades: " + field.name),
                    field.patched.blades.size(), std::move(*physics)};
        layer.physics.reset(field.patched.blades);
        out.mLayers.push_back(std::move(layer));
    }
    return out;
}

void ScenePhysicsGpu::step(const core::ScenePhysics& physics, float timeS) {
    for (Layer& layer : mLayers)
        layer.physics.step(layer.blades.id(), layer.bladeCount, physics.params, physics.wind,
                           physics.colliders, timeS);
}

void ScenePhysicsGpu::readBack(core::Scene& scene, core::SceneSimulation& simulation) const {
    for (std::size_t i = 0; i < mLayers.size(); ++i) {
        const Layer& layer = mLayers[i];
        std::vector<core::Blade>& blades = scene.layers[i].patched.blades;
        if (layer.bladeCount == 0)
            continue;
        const std::vector<std::byte> bytes =
            layer.blades.read(0, layer.bladeCount * sizeof(core::Blade));
        std::memcpy(blades.data(), bytes.data(), bytes.size());
        simulation.eta(i) = layer.physics.readEta();
    }
}

}  // namespace grass::render
