// The compute-shader execution of a whole scene's physics (one PhysicsGpu per grass layer, each
// on its own blade buffer), for `grass sim --backend gpu` and `grass render --time`. The blades
// go up once, every step runs on the GPU, and readBack brings blades and η down once at the end.
#pragma once

#include <optional>
#include <vector>

#include "gl/buffer.h"
#include "gl/fence.h"
#include "gl/gl_ref.h"
#include "render/physics_gpu.h"
#include "scene/scene_physics.h"

namespace grass::render {

class ScenePhysicsGpu {
public:
    // Uploads the blades of every layer of `scene` and loads the shader (needs a current context).
    static Result<ScenePhysicsGpu> create(const core::Scene& scene);
    // Steps blade buffers that already hold the layers' blades (the renderer's, so the viewport
    // shows the simulation without copies); one buffer per layer, owned by the caller.
    static Result<ScenePhysicsGpu> createOn(const core::Scene& scene,
                                            const std::vector<gl::BufferRef>& bladeBuffers);

    // One step of physics.params.dtS from timeS on every layer (asynchronous: no glFinish).
    void step(const core::ScenePhysics& physics, float timeS);
    // After a brush re-grew patches of layer `layer` (the renderer uploaded their blades): their
    // rest tips follow, so physics pulls the new blades to their own rest pose.
    void uploadRegrown(std::size_t layer, const core::Scene& scene,
                       const std::vector<std::uint32_t>& patches);
    // The snow loads of the ScenePhysics given to step changed (an edit of the snow): they are
    // uploaded again, or freed, at the next step.
    void reloadSnowLoads();
    // Lowers every η above `etaMax` to it on every layer; returns how many blades it lowered.
    std::size_t capEta(float etaMax);
    // Copies blades into `scene` and η into `simulation` (which must be the scene's).
    void readBack(core::Scene& scene, core::SceneSimulation& simulation) const;
    // η of layer `layer`'s blades (a read-back, for tests and tools).
    std::vector<float> readEta(std::size_t layer) const {
        return mLayers.at(layer).physics.readEta();
    }
    // Rest detection (the editor's: app/live_scene.h): with `stillTipMove` > 0 every layer's
    // steps mark whether they moved a tip by more than that share of its blade's height or let a
    // crushed blade recover (PhysicsGpu::setMotionReport); 0 stops it and frees the mark.
    void reportMotion(float stillTipMove);
    // Whether the steps since the last answer moved the field, once the GPU has run them (a
    // fence: the caller never waits); nothing before, and those steps count towards the next
    // answer. An answer clears the mark.
    std::optional<bool> takeMotion();

private:
    struct Layer {
        gl::Buffer ownBlades;  // empty when stepping the caller's buffer
        gl::BufferRef blades;
        std::size_t bladeCount = 0;
        PhysicsGpu physics;
        bool loadUploaded = false;  // the snow load per metre (ScenePhysics) is on the GPU
    };
    std::vector<Layer> mLayers;
    gl::Buffer mMotion;      // one uint: a step since the last answer moved the field
    gl::Fence mMotionFence;  // after the last step that marks it
};

}  // namespace grass::render
