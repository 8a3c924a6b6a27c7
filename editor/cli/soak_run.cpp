#include "cli/soak_run.h"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "physics/path_loop.h"
#include "render/scene_physics_gpu.h"
#include "tools/process_memory.h"

namespace grass::cli {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

void printSample(std::FILE* out, const char* label, const SoakSample& sample, double totalS) {
    if (!out)
        return;
    const double done = totalS > 0.0 ? sample.simulatedS / totalS : 1.0;
    const double leftS = done > 0.0 ? sample.wallS * (1.0 - done) / done : 0.0;
    std::fprintf(out,
                 "soak %s: t = %.1f/%.0f s (%.0f %%), %.1f s wall, ~%.0f s left: length error "
                 "%.3g of tolerance, nonfinite %zu, RSS %.1f MiB (heap %.1f), GL objects %lld\n",
                 label, sample.simulatedS, totalS, 100.0 * done, sample.wallS, leftS,
                 sample.health.maxLengthErrorPerTolerance, sample.health.nonfinite,
                 static_cast<double>(sample.rssBytes) / (1024.0 * 1024.0),
                 static_cast<double>(sample.heapInUseBytes) / (1024.0 * 1024.0),
                 static_cast<long long>(sample.glObjects.total()));
    std::fflush(out);
}

}  // namespace


Result<SoakRun> soakSimulation(core::Scene& scene, core::SceneSimulation& simulation,
                               SimBackend backend, const SoakOptions& options,
                               std::FILE* progress) {
    SoakRun run;
    core::ScenePhysics& physics = simulation.physics();
    const float dtS = physics.params.dtS;
    const std::size_t totalSteps = stepsFor(options.seconds, dtS);
    // At least one step between samples; the last sample is at the end whatever the interval.
    const std::size_t stepsPerSample =
        std::max<std::size_t>(1, stepsFor(options.sampleEveryS, dtS));
    core::PathLooper looper(physics.wind, physics.colliders);

    run.glBeforeSetUp = gl::liveGlObjects();
    std::optional<render::ScenePhysicsGpu> gpu;
    if (backend == SimBackend::Gpu) {
        auto created = render::ScenePhysicsGpu::create(scene);
        if (!created)
            return created.error();
        gpu.emplace(std::move(*created));
    }
    const auto start = Clock::now();
    const auto sample = [&]() {
        SoakSample s;
        if (gpu) {
            // Waits for the GPU, so the wall time is the work done, and brings the field down.
            gpu->readBack(scene, simulation);
        }
        s.steps = simulation.stepsDone();
        s.simulatedS = static_cast<double>(s.steps) * static_cast<double>(dtS);
        s.wallS = secondsSince(start);
        s.health = simulation.health();
        s.rssBytes = tools::residentBytes();
        s.heapInUseBytes = tools::heapInUseBytes();
        s.glObjects = gl::liveGlObjects();
        run.samples.push_back(s);
        printSample(progress, options.label, s, static_cast<double>(totalSteps) * dtS);
    };
    sample();
    run.glAfterFirstStep = run.samples.front().glObjects;
    for (std::size_t i = 0; i < totalSteps; ++i) {
        if (options.stop.stop_requested()) {
            run.stopped = true;
            if (run.samples.back().steps != simulation.stepsDone())
                sample();
            break;
        }
        run.pathSwaps += looper.update(physics.wind, physics.colliders, simulation.timeS(), dtS);
        if (gpu) {
            gpu->step(physics, simulation.timeS());
            simulation.advanceClock();
        } else {
            simulation.step();
        }
        if (i == 0)
            run.glAfterFirstStep = gl::liveGlObjects();
        if ((i + 1) % stepsPerSample == 0 || i + 1 == totalSteps)
            sample();
    }
    run.wallS = secondsSince(start);
    gpu.reset();
    run.glAfterTearDown = gl::liveGlObjects();
    return run;
}

}  // namespace grass::cli
