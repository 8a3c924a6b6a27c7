#include "render/scene_physics_gpu.h"

#include "util/assert.h"

namespace grass::render {

Result<ScenePhysicsGpu> ScenePhysicsGpu::createOn(const core::Scene& scene,
                                                  const std::vector<gl::BufferRef>& bladeBuffers) {
    GRASS_ASSERT(bladeBuffers.size() == scene.layers.size());
    ScenePhysicsGpu out;
    for (std::size_t i = 0; i < scene.layers.size(); ++i) {
        const std::vector<core::Blade>& blades = scene.layers[i].patched.blades;
        auto physics = PhysicsGpu::load();
        if (!physics)
            return physics.error();
        physics->reset(blades, core::restTipsAsGrown(blades));
        out.mLayers.push_back(
            Layer{gl::Buffer(), bladeBuffers[i], blades.size(), std::move(*physics)});
    }
    return out;
}

Result<ScenePhysicsGpu> ScenePhysicsGpu::create(const core::Scene& scene) {
    std::vector<gl::Buffer> uploaded;
    std::vector<gl::BufferRef> views;
    for (const core::LayerField& field : scene.layers) {
        uploaded.push_back(
            gl::Buffer::fromVector(field.patched.blades, "physics blades: " + field.name));
        views.push_back(uploaded.back());
    }
    auto out = createOn(scene, views);
    if (!out)
        return out.error();
    for (std::size_t i = 0; i < uploaded.size(); ++i)
        out->mLayers[i].ownBlades = std::move(uploaded[i]);
    return out;
}

void ScenePhysicsGpu::uploadRegrown(std::size_t layer, const core::Scene& scene,
                                    const std::vector<std::uint32_t>& patches) {
    if (layer >= mLayers.size() || layer >= scene.layers.size())
        return;
    const core::PatchedBlades& patched = scene.layers[layer].patched;
    for (const std::uint32_t p : patches) {
        const std::size_t first = std::size_t(p) * patched.patchSize;
        mLayers[layer].physics.resetRange(
            first, std::span(patched.blades).subspan(first, patched.patchSize));
    }
}

void ScenePhysicsGpu::step(const core::ScenePhysics& physics, float timeS) {
    for (std::size_t i = 0; i < mLayers.size(); ++i) {
        Layer& layer = mLayers[i];
        const core::GravityLoad load = physics.snowLoad(i, timeS);
        // Uploaded once: the per-metre load is fixed when the simulation starts (or the snow
        // is edited: reloadSnowLoads). An empty one frees the buffer.
        if (!layer.loadUploaded) {
            layer.physics.setGravityLoad(load.perBlade);
            layer.loadUploaded = true;
        }
        layer.physics.step(layer.blades, layer.bladeCount, physics.params, physics.wind,
                           physics.colliders, timeS, load.scale);
    }
    if (mMotion.id() != 0)
        mMotionFence.place();
}

void ScenePhysicsGpu::reportMotion(float stillTipMove) {
    const bool on = stillTipMove > 0.0f;
    if (!on && mMotion.id() == 0)
        return;  // off already (each frame of a windy field asks this)
    if (on && mMotion.id() == 0) {
        const std::uint32_t clear = 0;
        mMotion = gl::Buffer(std::as_bytes(std::span(&clear, 1)), "physics motion report");
    } else if (!on) {
        mMotion = gl::Buffer();
        mMotionFence.reset();
    }
    for (Layer& layer : mLayers)
        layer.physics.setMotionReport(on ? gl::BufferRef(mMotion) : gl::BufferRef(), stillTipMove);
}

std::optional<bool> ScenePhysicsGpu::takeMotion() {
    if (mMotion.id() == 0 || !mMotionFence.passed())
        return std::nullopt;
    mMotionFence.reset();
    std::uint32_t seen = 0;
    glGetNamedBufferSubData(mMotion.id(), 0, sizeof seen, &seen);
    const std::uint32_t clear = 0;
    mMotion.update(std::as_bytes(std::span(&clear, 1)));
    return seen != 0;
}

std::size_t ScenePhysicsGpu::capEta(float etaMax) {
    std::size_t lowered = 0;
    for (Layer& layer : mLayers)
        lowered += layer.physics.capEta(etaMax);
    return lowered;
}

void ScenePhysicsGpu::reloadSnowLoads() {
    for (Layer& layer : mLayers)
        layer.loadUploaded = false;
}

void ScenePhysicsGpu::readBack(core::Scene& scene, core::SceneSimulation& simulation) const {
    for (std::size_t i = 0; i < mLayers.size(); ++i) {
        const Layer& layer = mLayers[i];
        std::vector<core::Blade>& blades = scene.layers[i].patched.blades;
        if (layer.bladeCount == 0)
            continue;
        const std::size_t bytes = layer.bladeCount * sizeof(core::Blade);
        glGetNamedBufferSubData(layer.blades.id(), 0, static_cast<GLsizeiptr>(bytes),
                                blades.data());
        simulation.eta(i) = layer.physics.readEta();
    }
}

}  // namespace grass::render
