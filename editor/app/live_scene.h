// The live scene of the editor window: the grown field, the tools that pick and paint it, its
// renderer and the GPU physics stepping the renderer's blades, built and rebuilt together.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "project/project.h"
#include "scene/scene.h"
#include "scene/scene_physics.h"
#include "render/scene_physics_gpu.h"
#include "render/scene_renderer.h"
#include "util/result.h"
#include "app/viewport_tools.h"

namespace grass::editor {

// Physics stepping the renderer's blade buffers on the GPU in fixed steps of the project's
// step_s, following the timeline's time with at most MAX_STEPS_PER_FRAME steps a frame. What a
// slow device cannot step is dropped (the field jumps to the timeline's time) rather than
// piled up, so the field keeps moving with the wind and colliders it sees; droppedS says how
// much, for the status bar.
struct LivePhysics {
    static constexpr int MAX_STEPS_PER_FRAME = 4;
    core::ScenePhysics scene;
    render::ScenePhysicsGpu gpu;
    std::size_t steps = 0;
    double droppedS = 0.0;  // simulated time skipped since the field was built

    double timeS() const { return static_cast<double>(steps) * scene.params.dtS; }
    // Steps towards `targetS`, at most `maxSteps`; returns the time dropped this frame (0 when
    // it kept up).
    double advanceTo(double targetS, int maxSteps = MAX_STEPS_PER_FRAME) {
        const double dtS = scene.params.dtS;
        for (int i = 0; i < maxSteps && timeS() + dtS * (1.0 - 1e-6) <= targetS; ++i) {
            gpu.step(scene, static_cast<float>(timeS()));
            ++steps;
        }
        const double behindS = targetS - timeS();
        if (behindS < dtS)
            return 0.0;
        const auto skipped = static_cast<std::size_t>(std::floor(behindS / dtS));
        steps += skipped;
        const double dropped = static_cast<double>(skipped) * dtS;
        droppedS += dropped;
        return dropped;
    }
};

// What a project becomes on the GPU; rebuilt whole when the project is re-grown or replaced.
// Members are destroyed in reverse order: the physics (which steps the renderer's buffers)
// before the renderer, the renderer (which points at the scene) before the scene.
struct Live {
    std::unique_ptr<core::Scene> scene;
    std::unique_ptr<SceneTools> tools;  // picks and paints `scene`
    std::unique_ptr<render::SceneRenderer> renderer;
    std::optional<LivePhysics> physics;
};

// `prepare` runs on the grown scene before the GPU sees it (painted maps carried over).
Result<Live> buildLive(const core::LoadedProject& loaded, bool withPhysics,
                       const std::function<Result<void>(core::Scene&)>& prepare = {});

// Puts every layer's blades back at rest on the GPU and restarts the simulation from there
// (keeping its step count).
Result<void> resetPhysics(Live& live);

}  // namespace grass::editor
