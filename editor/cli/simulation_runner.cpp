#include "cli/simulation_runner.h"

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "physics/step_count.h"
#include "render/scene_physics_gpu.h"
#include "util/terminal_line.h"

namespace grass::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double, std::milli>(to - from).count();
}

// A progress line at most every half second: rewritten in place on a terminal, one line per
// update in a log.
class Progress {
public:
    Progress(std::string command, std::size_t total)
        : mCommand(std::move(command)), mTotal(total), mTerminal(isatty(STDERR_FILENO) != 0) {}

    bool due(Clock::time_point now) const { return msBetween(mLast, now) >= 500.0; }

    void show(std::size_t done, float simulatedS, Clock::time_point now) {
        mLast = now;
        const double elapsedS = msBetween(mStart, now) / 1000.0;
        const double leftS =
            done > 0 ? elapsedS * static_cast<double>(mTotal - done) / static_cast<double>(done)
                     : 0.0;
        std::fprintf(stderr,
                     "%s%s: step %zu/%zu (%.0f %%), t = %.2f s simulated, %.1f s elapsed, "
                     "~%.0f s left%s",
                     mTerminal ? "\r" : "", mCommand.c_str(), done, mTotal,
                     100.0 * static_cast<double>(done) / static_cast<double>(mTotal),
                     static_cast<double>(simulatedS), elapsedS, leftS, mTerminal ? "" : "\n");
        std::fflush(stderr);
        if (mTerminal)
            core::markProgressLineOpen();
    }

    // Ends the line left open on a terminal, unless a message (the interrupt's note) did.
    void finish() { core::endProgressLine(); }

private:
    std::string mCommand;
    std::size_t mTotal;
    bool mTerminal;
    Clock::time_point mStart = Clock::now();
    Clock::time_point mLast = Clock::now();
};

}  // namespace

unsigned cpuThreads(int requested) {
    if (requested > 0)
        return static_cast<unsigned>(requested);
    return std::max(1u, std::min(std::thread::hardware_concurrency(), 8u));
}

std::size_t stepsFor(double seconds, float dtS) {
    if (!(seconds > 0.0) || !(dtS > 0.0f))
        return 0;
    return static_cast<std::size_t>(std::llround(seconds / static_cast<double>(dtS)));
}

Result<SimRun> runSimulation(core::Scene& scene, core::SceneSimulation& simulation, double seconds,
                             SimBackend backend, const std::string& command, std::stop_token stop) {
    SimRun run;
    auto steps = core::simulationSteps(seconds, simulation.physics().params.dtS, command);
    if (!steps)
        return steps.error();
    run.steps = *steps;
    Progress progress(command, run.steps);
    const auto start = Clock::now();
    // Before step i: a stop leaves the first i steps as the run.
    const auto stopsAt = [&](std::size_t i) {
        if (!stop.stop_requested())
            return false;
        run.steps = i;
        run.stopped = true;
        return true;
    };
    if (backend == SimBackend::Cpu) {
        for (std::size_t i = 0; i < run.steps && !stopsAt(i); ++i) {
            simulation.step();
            if (const auto now = Clock::now(); progress.due(now))
                progress.show(i + 1, simulation.timeS(), now);
        }
    } else {
        auto gpu = render::ScenePhysicsGpu::create(scene);
        if (!gpu)
            return gpu.error();
        for (std::size_t i = 0; i < run.steps && !stopsAt(i); ++i) {
            gpu->step(simulation.physics(), simulation.timeS());
            simulation.advanceClock();
            if (const auto now = Clock::now(); progress.due(now)) {
                // The GPU runs ahead of the CPU; wait for it so the line tells the truth.
                glFinish();
                progress.show(i + 1, simulation.timeS(), Clock::now());
            }
        }
        glFinish();
        run.wallMs = msBetween(start, Clock::now());
        gpu->readBack(scene, simulation);
    }
    if (backend == SimBackend::Cpu)
        run.wallMs = msBetween(start, Clock::now());
    progress.finish();
    run.msPerStep = run.steps > 0 ? run.wallMs / static_cast<double>(run.steps) : 0.0;
    run.health = simulation.health();
    return run;
}

}  // namespace grass::cli
