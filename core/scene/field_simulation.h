// FieldSimulation: a scene's blades stepped on the CPU (the SIMD execution, physics_simd.h) in a
// copy of their own, for a viewer that shows them while the scene itself stays at rest (the
// editor's tools pick, paint and re-grow the scene's blades). η and the rest tips live beside
// the copy, as in SceneSimulation; a re-grown patch restarts from the scene's new blades.
// The editor steps it on software renderers, where it is faster than the compute shader
// (docs/physics.md). Snow loads apply as in SceneSimulation (ScenePhysics::snowLoad, filled by
// prepareSnowLoads from the scene at rest).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/physics.h"
#include "scene/scene.h"
#include "scene/scene_physics.h"

namespace grass::core {

class FieldSimulation {
public:
    // Copies every layer's blades as they stand in `scene`, at rest.
    explicit FieldSimulation(const Scene& scene);

    // One step of physics.params.dtS from timeS on every layer (threads 0: the shared pool).
    void step(const ScenePhysics& physics, float timeS, unsigned threads = 0);
    // Every layer back to the scene's blades at rest.
    void reset(const Scene& scene);
    // These patches of `layer` back to the scene's (re-grown) blades: rest tips of the new
    // blades, η 0.
    void resetPatches(std::size_t layer, const Scene& scene, std::span<const std::uint32_t> patches);

    // Lowers every η above `etaMax` to it; returns how many blades it lowered.
    std::size_t capEta(float etaMax);

    std::size_t layerCount() const { return mLayers.size(); }
    std::span<const Blade> blades(std::size_t layer) const { return mLayers.at(layer).blades; }
    std::span<const float> eta(std::size_t layer) const { return mLayers.at(layer).eta; }

private:
    struct Layer {
        std::vector<Blade> blades;
        std::vector<float> eta;
        std::vector<glm::vec3> restTips;
        std::uint32_t patchSize = 0;
    };
    std::vector<Layer> mLayers;
};

}  // namespace grass::core
