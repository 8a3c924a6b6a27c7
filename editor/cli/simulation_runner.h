// Runs a scene's physics for a span of simulated time on the CPU reference or the compute shader,
// with a progress line on stderr: the shared loop of `grass sim` and `grass render --time`.
#pragma once

#include <stop_token>
#include <string>

#include "scene/scene_physics.h"
#include "util/result.h"

namespace grass::cli {

enum class SimBackend { Cpu, Gpu };

struct SimRun {
    std::size_t steps = 0;
    double wallMs = 0.0;  // all steps, a final glFinish included for the GPU
    double msPerStep = 0.0;
    core::FieldHealth health;
    bool stopped = false;  // ended early (Ctrl+C): `steps` were run
};

// The CPU reference's threads for `--threads N`: N, or for 0 every core of the machine, at most 8
// (more rarely pays on the field sizes of grass projects).
unsigned cpuThreads(int requested);

// The number of steps of dtS that simulate `seconds` (rounded to the nearest step).
std::size_t stepsFor(double seconds, float dtS);

// Steps `simulation` (and its scene, in place) for `seconds`. The GPU backend needs a current GL
// context; it uploads the blades, steps there and reads blades and η back at the end. A stop
// requested (Ctrl+C, interrupt_stop.h) ends it before the next step: SimRun::stopped.
Result<SimRun> runSimulation(core::Scene& scene, core::SceneSimulation& simulation, double seconds,
                             SimBackend backend, const std::string& command,
                             std::stop_token stop = {});

}  // namespace grass::cli
