// Frame cost of the scene renderer (Google Benchmark; Release; never gates CI): per frame at
// 1280×720 with 4× MSAA and the strips geometry path, the cull pass, the opaque pass and the
// grass draws, for ~100k and ~1M blades, with every cull test on and every one off. Run:
//   cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DGRASS_BUILD_BENCH=ON
//   cmake --build build-bench --target bench_render && build-bench/bin/bench_render
//
// Time source: manual time is the wall clock of one render() up to the end of glFinish. The
// GL_TIME_ELAPSED queries of each pass (FrameTimings) are reported as counters cull_ms,
// opaque_ms and grass_ms: llvmpipe's queries are unreliable (1 ns for every bench_physics
// step; here one 1M-blade opaque pass read 0.02 ms against 3-5 ms elsewhere).
// Culled shares are counters too (c_* and culled, fractions of blades_in). Figures and the
// pipeline they measure: docs/rendering.md.
//
// The field is projects/meadow's (20 m hills, its overview camera and sun) with one uniform
// layer whose density is chosen from the surface area to hit the blade count; no clumps, so the
// count is exact up to the scatter's rounding.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "framebuffer.h"
#include "headless_context.h"
#include "mesh/procedural.h"
#include "mesh/surface_mesh.h"
#include "project/project.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "scene_renderer.h"

namespace {

using namespace grass;

constexpr int WIDTH = 1280;
constexpr int HEIGHT = 720;
constexpr int MSAA_SAMPLES = 4;

// projects/meadow/project.json: mesh, blade ranges, colours, camera and sun.
core::Project meadowProject(std::size_t targetBlades) {
    core::Project project;
    project.name = "bench meadow";
    project.mesh.procedural.shape = core::ProceduralShape::Hills;
    project.mesh.procedural.size = 20.0f;
    project.mesh.procedural.hillHeight = 1.5f;
    project.mesh.procedural.hillScale = 6.0f;
    project.mesh.procedural.resolution = 96;
    project.mesh.procedural.noiseSeed = 7;
    core::GrassLayer layer;
    const double area = core::surfaceArea(core::makeProceduralMesh(project.mesh.procedural));
    layer.scatter.density = static_cast<float>(static_cast<double>(targetBlades) / area);
    layer.scatter.clumpSpacing = 0.0f;
    layer.scatter.blade.heightMin = 0.3f;
    layer.scatter.blade.heightMax = 0.6f;
    layer.rootColor = {0.08f, 0.22f, 0.04f};
    layer.tipColor = {0.5f, 0.72f, 0.22f};
    project.layers = {layer};
    project.cameras = {
        core::CameraDesc{"overview", {14.0f, 7.0f, 14.0f}, {0.0f, 0.5f, 0.0f}, 45.0f}};
    project.sun.direction = {0.85f, -0.42f, -0.32f};
    project.sun.color = {1.0f, 0.84f, 0.62f};
    project.sun.intensity = 1.2f;
    project.render.geometry = core::GeometryPath::Strips;
    project.render.skyColor = {0.62f, 0.74f, 0.88f};
    project.render.groundColor = {0.28f, 0.22f, 0.14f};
    return project;
}

struct BenchScene {
    core::Project project;
    core::Scene scene;
};

Result<std::unique_ptr<BenchScene>> buildBenchScene(std::size_t targetBlades) {
    auto bench = std::make_unique<BenchScene>();
    core::LoadedProject loaded;
    loaded.project = meadowProject(targetBlades);
    loaded.file = "bench_render";
    auto scene = core::buildScene(loaded);
    if (!scene)
        return scene.error();
    bench->project = loaded.project;
    bench->scene = std::move(*scene);
    return bench;
}

double share(std::size_t part, std::size_t whole) {
    return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

// One frame with statistics first (untimed: it also pays the driver's shader compile); the
// camera does not move, so its counts are those of every timed frame. Timed frames run without
// statistics, as the editor does.
void runFrame(benchmark::State& state, const BenchScene& bench, bool cullOn) {
    auto renderer = render::SceneRenderer::create(bench.scene);
    if (!renderer) {
        state.SkipWithError(renderer.error().str().c_str());
        return;
    }
    const core::CameraDesc& desc = bench.project.cameras.front();
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt(desc.position, desc.target, glm::radians(desc.fovYDeg));
    gl::Framebuffer framebuffer(WIDTH, HEIGHT, MSAA_SAMPLES);
    render::RenderOptions options =
        render::renderOptionsFor(bench.project, true);
    options.geometry = render::GeometryPath::Strips;
    if (!cullOn) {
        options.cull.frustum = false;
        options.cull.orientation = false;
        options.cull.distance = false;
        options.cull.occlusion = false;
    }

    options.cull.collectStats = true;
    (*renderer)->render(camera, WIDTH, HEIGHT, framebuffer.id(), options);
    glFinish();
    const render::CullStats stats = (*renderer)->lastTimings().cull;
    options.cull.collectStats = false;

    double cullMs = 0.0, opaqueMs = 0.0, grassMs = 0.0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        (*renderer)->render(camera, WIDTH, HEIGHT, framebuffer.id(), options);
        glFinish();
        state.SetIterationTime(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        const render::FrameTimings timings = (*renderer)->lastTimings();
        cullMs += timings.cullMs;
        opaqueMs += timings.meshMs;
        grassMs += timings.grassMs;
    }
    const auto avg = benchmark::Counter::kAvgIterations;
    state.counters["cull_ms"] = benchmark::Counter(cullMs, avg);
    state.counters["opaque_ms"] = benchmark::Counter(opaqueMs, avg);
    state.counters["grass_ms"] = benchmark::Counter(grassMs, avg);
    state.counters["blades_in"] = static_cast<double>(stats.bladesIn);
    state.counters["drawn"] = static_cast<double>(stats.drawn);
    state.counters["culled"] = share(stats.culledTotal(), stats.bladesIn);
    state.counters["c_patch"] = share(stats.culledPatch, stats.bladesIn);
    state.counters["c_orient"] = share(stats.culledOrientation, stats.bladesIn);
    state.counters["c_frustum"] = share(stats.culledFrustum, stats.bladesIn);
    state.counters["c_dist"] = share(stats.culledDistance, stats.bladesIn);
    state.counters["c_occl"] = share(stats.culledOcclusion, stats.bladesIn);
}

void registerScene(const char* label, const BenchScene& bench) {
    for (const bool cullOn : {true, false}) {
        const std::string name =
            std::string("BM_Frame_Strips/") + label + (cullOn ? "/cull_on" : "/cull_off");
        benchmark::RegisterBenchmark(
            name.c_str(),
            [&bench, cullOn](benchmark::State& state) { runFrame(state, bench, cullOn); })
            // llvmpipe on 2 cores takes 1-12 s a frame at these sizes.
            ->Iterations(3)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace

// Registered here rather than with BENCHMARK(): the runs need the GL context and the scenes,
// created once and owned by main (no static constructors, no mutable globals: STYLE.md §7).
int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    auto context = grass::gl::HeadlessContext::create();
    if (!context) {
        std::fprintf(stderr, "no GL context, render benchmarks not run: %s\n",
                     context.error().str().c_str());
        return 1;
    }
    std::printf("GL: %s\n", grass::gl::rendererDescription().c_str());
    auto small = buildBenchScene(100'000);
    auto large = buildBenchScene(1'000'000);
    if (!small || !large) {
        std::fprintf(stderr, "scene: %s\n", (!small ? small.error() : large.error()).str().c_str());
        return 1;
    }
    std::printf("scenes: %zu and %zu blades on %.1f m²\n", (*small)->scene.totalBlades(),
                (*large)->scene.totalBlades(), (*small)->scene.area);
    registerScene("100k", **small);
    registerScene("1M", **large);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
