#include "scene/scene_physics.h"

#include <cstdio>

#include "mesh/gltf_loader.h"

namespace grass::core {

namespace {

Result<void> addMeshCollider(const LoadedProject& loaded, const ColliderDesc&, std::size_t index,
                             ScenePhysics&) {
    return makeError(loaded.file.string(), "/colliders/" + std::to_string(index) +
                                                  ": mesh colliders are not supported by this build yet");
}

}  // namespace

Result<ScenePhysics> buildScenePhysics(const LoadedProject& loaded) {
    const Project& project = loaded.project;
    ScenePhysics out;
    out.params = project.physics;
    for (const WindDesc& wind : project.wind)
        out.wind.push_back(wind.source);
    for (std::size_t i = 0; i < project.colliders.size(); ++i) {
        const ColliderDesc& collider = project.colliders[i];
        if (collider.shape == ColliderShape::Sphere) {
            out.colliders.push_back(
                SphereCollider{collider.position, collider.radiusM, collider.path});
            continue;
        }
        if (auto added = addMeshCollider(loaded, collider, i, out); !added)
            return added.error();
    }
    return out;
}

SceneSimulation::SceneSimulation(Scene& scene, ScenePhysics physics, unsigned threadCount)
    : mScene(scene), mPhysics(std::move(physics)), mThreadCount(threadCount) {
    for (const LayerField& layer : mScene.layers) {
        mEta.emplace_back(layer.patched.blades.size(), 0.0f);
        mRestTips.push_back(core::restTips(layer.patched.blades));
    }
}

void SceneSimulation::step() {
    for (std::size_t i = 0; i < mScene.layers.size(); ++i)
        stepPhysics(mScene.layers[i].patched.blades, mEta[i], mRestTips[i], mPhysics.params,
                    mPhysics.wind, mPhysics.colliders, mTimeS, mThreadCount);
    advanceClock();
}

void SceneSimulation::advanceClock() {
    ++mSteps;
    // From the step count, so the clock does not drift by a rounding per step.
    mTimeS = static_cast<float>(static_cast<double>(mSteps) * mPhysics.params.dtS);
}

FieldHealth SceneSimulation::health() const {
    FieldHealth health;
    for (std::size_t i = 0; i < mScene.layers.size(); ++i)
        health.add(measureHealth(mScene.layers[i].patched.blades, mEta[i], mRestTips[i]));
    return health;
}

}  // namespace grass::core
