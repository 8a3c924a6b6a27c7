// Blade physics throughput (Google Benchmark; Release; never gates CI): blade-steps per second of
// the CPU reference (core::stepPhysics) and of the compute shader (render::PhysicsGpu), plus a
// memory-copy probe for the bandwidth bound. Run:
//   cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DGRASS_BUILD_BENCH=ON
//   cmake --build build-bench --target bench_physics && build-bench/bin/bench_physics
//
// Bytes moved per blade-step: every blade is read once and written once per step (its substeps
// work on it in registers and cache), so the traffic is
//   CPU: Blade 64 B read + 64 B written, η 4 B + 4 B, rest tip (vec3) 12 B read = 148 B;
//   GPU: the same with the rest tip as a std430 vec4 (16 B read)                 = 152 B.
// blade_steps_per_s × that, against BM_MemoryCopy's traffic_bytes_per_s, says how far a run is
// from the bandwidth bound.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>

#include "blade/blade.h"
#include "gl/buffer.h"
#include "gl/headless_context.h"
#include "physics/physics.h"
#include "physics/physics_simd.h"
#include "render/physics_gpu.h"
#include "gl/timer_query.h"
#include "util/rng.h"

namespace {

using namespace grass;

// A square grid of blades 5 cm apart on the y = 0 plane (100k: 15.8 m wide, 1M: 50 m), standing
// at rest: up = +y, h = 0.5 m, s = 20, theta from a seeded RNG. Cheaper to build than a scatter.
constexpr float SPACING_M = 0.05f;

struct Field {
    std::vector<core::Blade> blades;
    float sideM = 0.0f;
};

Field makeField(std::size_t count) {
    const auto perRow = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    const float sideM = static_cast<float>(perRow) * SPACING_M;
    Field field{{}, sideM};
    field.blades.reserve(count);
    Rng rng(7);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec3 v0(static_cast<float>(i % perRow) * SPACING_M - 0.5f * sideM, 0.0f,
                           static_cast<float>(i / perRow) * SPACING_M - 0.5f * sideM);
        field.blades.push_back(
            core::makeRestBlade(v0, {0, 1, 0}, 0.5f, 0.01f, 20.0f, rng.uniform(0.0f, 6.2831853f)));
    }
    return field;
}

enum class Scenario {
    Windy,          // gusty directional wave + gravity
    WindyCollider,  // the same with a sphere rolling across the field
    Still,          // no wind, no colliders, gravity 0, blades at rest
};

struct Forces {
    core::PhysicsParams params;
    std::vector<core::WindSource> wind;
    std::vector<core::SphereCollider> colliders;
};

// Δt = 1/60 and default parameters (2 substeps, gravity 9.81).
Forces makeForces(Scenario scenario, float sideM) {
    Forces forces;
    if (scenario == Scenario::Still) {
        forces.params.gravity.w = 0.0f;
        return forces;
    }
    core::WindSource wave;
    wave.direction = glm::vec3(1.0f, 0.0f, 0.3f);
    wave.strength = 3.0f;
    wave.wavelengthM = 3.0f;
    wave.speedMps = 1.5f;
    wave.gust = 0.4f;
    forces.wind = {wave};
    if (scenario == Scenario::WindyCollider) {
        // A 1 m ball rolling through the blades, across the field in 10 s.
        core::SphereCollider ball;
        ball.radiusM = 1.0f;
        ball.path = {{0.0f, {-0.5f * sideM, 0.5f, 0.0f}}, {10.0f, {0.5f * sideM, 0.5f, 0.0f}}};
        forces.colliders = {ball};
    }
    return forces;
}

void setBladeStepCounters(benchmark::State& state, std::size_t count) {
    state.counters["blade_steps_per_s"] = benchmark::Counter(
        static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate);
}

// state.range(0): blade count, state.range(1): threads. `path`: the scalar reference
// (BM_PhysicsCpu_*) or the SIMD execution (BM_PhysicsSimd_*, physics_simd.h).
void runCpu(benchmark::State& state, Scenario scenario, core::CpuPhysics path) {
    const auto count = static_cast<std::size_t>(state.range(0));
    const auto threads = static_cast<unsigned>(state.range(1));
    Field field = makeField(count);
    const std::vector<glm::vec3> tips = core::restTips(field.blades);
    std::vector<float> eta(count, 0.0f);
    const Forces forces = makeForces(scenario, field.sideM);
    float timeS = 0.0f;
    for (auto _ : state) {
        core::stepPhysicsOn(path, field.blades, eta, tips, forces.params, forces.wind,
                            forces.colliders, timeS, threads);
        timeS += forces.params.dtS;
        benchmark::DoNotOptimize(field.blades.data());
        benchmark::ClobberMemory();
    }
    setBladeStepCounters(state, count);
}

// state.range(0): blade count. Manual time: the wall clock from the step's first call to the end
// of glFinish (uploads of the per-step inputs included). A GL_TIME_ELAPSED query around the
// same calls is reported as timer_query_ms: on llvmpipe (Mesa 22.3) it answered 1 ns for every
// step, 100k or 1M blades, so it cannot be the time source there.
void runGpu(benchmark::State& state, Scenario scenario) {
    const auto count = static_cast<std::size_t>(state.range(0));
    auto physics = render::PhysicsGpu::load();
    if (!physics) {
        state.SkipWithError(physics.error().str().c_str());
        return;
    }
    const Field field = makeField(count);
    physics->reset(field.blades);
    gl::Buffer blades = gl::Buffer::fromVector(field.blades, "bench physics blades");
    const Forces forces = makeForces(scenario, field.sideM);
    gl::GpuTimer timer;
    float timeS = 0.0f;
    // One untimed step: the driver compiles the shader on first use.
    physics->step(blades, count, forces.params, forces.wind, forces.colliders, timeS);
    glFinish();
    double queryMs = 0.0;
    for (auto _ : state) {
        timeS += forces.params.dtS;
        const auto start = std::chrono::steady_clock::now();
        timer.begin();
        physics->step(blades, count, forces.params, forces.wind, forces.colliders, timeS);
        timer.end();
        glFinish();
        state.SetIterationTime(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        queryMs += timer.milliseconds();
    }
    setBladeStepCounters(state, count);
    state.counters["timer_query_ms"] =
        benchmark::Counter(queryMs, benchmark::Counter::kAvgIterations);
}

// Copies 256 MiB (far beyond any cache) on state.range(0) threads, each its own contiguous part.
// bytes_per_second counts the copied bytes; traffic_bytes_per_s counts read + written bytes, the
// figure to compare with bytes per blade-step × blade-steps per second.
void runMemoryCopy(benchmark::State& state) {
    constexpr std::size_t BYTES = std::size_t{256} << 20;
    const auto threads = static_cast<std::size_t>(state.range(0));
    // Filled, so every page is mapped before timing starts.
    std::vector<std::byte> source(BYTES, std::byte{1});
    std::vector<std::byte> target(BYTES, std::byte{0});
    const std::size_t chunk = BYTES / threads;
    for (auto _ : state) {
        std::vector<std::thread> workers;
        for (std::size_t t = 1; t < threads; ++t)
            workers.emplace_back([&, t] {
                std::memcpy(target.data() + t * chunk, source.data() + t * chunk, chunk);
            });
        std::memcpy(target.data(), source.data(), chunk);
        for (std::thread& w : workers)
            w.join();
        benchmark::DoNotOptimize(target.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(BYTES));
    state.counters["traffic_bytes_per_s"] = benchmark::Counter(
        2.0 * static_cast<double>(BYTES), benchmark::Counter::kIsIterationInvariantRate);
}

void registerCpu(const char* name, Scenario scenario, core::CpuPhysics path) {
    benchmark::RegisterBenchmark(name, runCpu, scenario, path)
        ->ArgNames({"blades", "threads"})
        ->ArgsProduct({{100000, 1000000}, {1, 2}})
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
}

void registerGpu(const char* name, Scenario scenario) {
    benchmark::RegisterBenchmark(name, runGpu, scenario)
        ->ArgNames({"blades"})
        ->Arg(100000)
        ->Arg(1000000)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
}

}  // namespace

// Registered here rather than with BENCHMARK(): the GPU runs need the GL context, created once
// and owned by main (no static constructors, no mutable globals: STYLE.md §7).
int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    using grass::core::CpuPhysics;
    registerCpu("BM_PhysicsCpu_Windy", Scenario::Windy, CpuPhysics::Scalar);
    registerCpu("BM_PhysicsCpu_WindyCollider", Scenario::WindyCollider, CpuPhysics::Scalar);
    registerCpu("BM_PhysicsCpu_Still", Scenario::Still, CpuPhysics::Scalar);
    std::printf("SIMD: %s, %zu float lanes\n", grass::core::physicsSimdTarget().c_str(),
                grass::core::physicsSimdLanes());
    registerCpu("BM_PhysicsSimd_Windy", Scenario::Windy, CpuPhysics::Simd);
    registerCpu("BM_PhysicsSimd_WindyCollider", Scenario::WindyCollider, CpuPhysics::Simd);
    registerCpu("BM_PhysicsSimd_Still", Scenario::Still, CpuPhysics::Simd);
    auto context = grass::gl::HeadlessContext::create();
    if (context) {
        std::printf("GL: %s\n", grass::gl::rendererDescription().c_str());
        registerGpu("BM_PhysicsGpu_Windy", Scenario::Windy);
        registerGpu("BM_PhysicsGpu_WindyCollider", Scenario::WindyCollider);
        registerGpu("BM_PhysicsGpu_Still", Scenario::Still);
    } else {
        std::fprintf(stderr, "no GL context, GPU benchmarks not run: %s\n",
                     context.error().str().c_str());
    }
    benchmark::RegisterBenchmark("BM_MemoryCopy256MiB", runMemoryCopy)
        ->ArgNames({"threads"})
        ->Arg(1)
        ->Arg(2)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
