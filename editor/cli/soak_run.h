// The loop of `grass soak` (issue 11): a project's physics stepped for a long span of simulated
// time with its wind and colliders kept moving (core/physics/path_loop.h), sampled every so many
// simulated seconds: field health, the process's resident memory and the live GL objects.
#pragma once

#include <cstdint>
#include <cstdio>
#include <stop_token>
#include <vector>

#include "gl/gl_object_count.h"
#include "scene/scene_physics.h"
#include "cli/simulation_runner.h"
#include "util/result.h"

namespace grass::cli {

struct SoakSample {
    std::size_t steps = 0;
    double simulatedS = 0.0;
    double wallS = 0.0;  // since the first step (the GPU waited for at each sample)
    core::FieldHealth health;
    std::uint64_t rssBytes = 0;
    // Bytes malloc has handed out and not had back (all arenas plus mmapped blocks): when RSS
    // grows but this does not, the growth is the allocator's or a mapping's, not a leak.
    std::uint64_t heapInUseBytes = 0;
    gl::GlObjectCounts glObjects;
};

struct SoakOptions {
    double seconds = 3600.0;
    double sampleEveryS = 60.0;
    const char* label = "cpu";  // the progress lines' prefix
    // A stop requested (Ctrl+C, interrupt_stop.h) ends the run at the next step, with a last
    // sample there: what ran is judged as a shorter run.
    std::stop_token stop;
};

struct SoakRun {
    // The first sample is the field at t = 0 after set-up (GPU buffers made, nothing stepped);
    // then one per interval; the last at the end of the run.
    std::vector<SoakSample> samples;
    // The GPU makes its per-step buffers (parameters, wind, spheres) on the first step, so the
    // steady count is the one after that step.
    gl::GlObjectCounts glBeforeSetUp, glAfterFirstStep, glAfterTearDown;
    std::size_t pathSwaps = 0;  // times the path windows were renewed
    double wallS = 0.0;
    bool stopped = false;  // ended early by SoakOptions::stop
};

// Steps `simulation` (whose scene is `scene`) on `backend` for options.seconds, keeping every path
// of its physics looping, with one progress line per sample on `progress`. The GPU backend needs a
// current GL context; its objects are made and destroyed inside.
Result<SoakRun> soakSimulation(core::Scene& scene, core::SceneSimulation& simulation,
                               SimBackend backend, const SoakOptions& options, std::FILE* progress);

}  // namespace grass::cli
