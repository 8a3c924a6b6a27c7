// Frame cost of the scene renderer (Google Benchmark; never gates CI), 1280×720 with 4× MSAA on
// projects/meadow's terrain and overview camera. Four families:
//   BM_Frame_Strips/<n>/cull_{on,off}     strips (8 segments), every cull test on / every one off
//   BM_Technique/<n>/{blades,billboards,hybrid}   the three grass techniques (SPEC §8), cull on
//   BM_Quality/<n>/{strips,tess}/<k>/lod_{off,on}  strips of k segments or tessellation level k,
//                                         image against strips of 32 segments with LOD off
//   BM_Lighting/<n>/{grass,grass_vertex,simple}   the grass lighting model (SPEC §10) per pixel,
//                                         per vertex, and the wrapped Lambert
//   BM_Feature/<n>/{built_without,billboards_unused,snow_off,snow_no_amount}   features present
//                                         but unused against a scene built without them
// Run (RelWithDebInfo: -O3 trips GCC 12 false-positive warnings under -Werror):
//   cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRASS_BUILD_BENCH=ON
//   cmake --build build-bench --target bench_render
//   build-bench/bin/bench_render --benchmark_filter='BM_Quality'
//
// Time source: manual time is the wall clock of one render() up to the end of glFinish (mean of
// the timed frames; counter min_ms: the fastest, less disturbed by other load). The
// GL_TIME_ELAPSED queries of each pass (FrameTimings) are reported as counters cull_ms,
// opaque_ms, grass_ms and billboard_ms: llvmpipe's queries are unreliable (1 ns for every
// bench_physics step; once a 1M-blade opaque pass read 0.02 ms against 3-5 ms elsewhere).
// Culled shares are counters too (c_* and culled, fractions of blades_in), as are the blades
// drawn per LOD (lod0..lod2). Figures and the pipeline they measure: docs/rendering.md.
//
// The field is projects/meadow's (20 m hills, its overview camera and sun) with one uniform
// layer whose density is chosen from the surface area to hit the blade count; no clumps, so the
// count is exact up to the scatter's rounding. Scenes are built on first use, so a filter that
// skips the 1M cases never builds that scene.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "support/image_compare.h"
#include "gl/framebuffer.h"
#include "gl/headless_context.h"
#include "mesh/procedural.h"
#include "mesh/surface_mesh.h"
#include "project/project.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "render/scene_renderer.h"
#include "util/image_file.h"

namespace {

using namespace grass;
using test::compareImages;
using test::ImageDifference;

constexpr int WIDTH = 1280;
constexpr int HEIGHT = 720;
constexpr int MSAA_SAMPLES = 4;
// The quality sweep: blades in its field (tessellation is ~20× slower than strips on
// llvmpipe), the reference's strip segments, and the "visibly different" pixel threshold.
constexpr std::size_t QUALITY_BLADES = 50'000;
constexpr int REFERENCE_SEGMENTS = 32;
constexpr int DIFFER_THRESHOLD = 48;

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

// Scenes by blade count, built on first use and kept; the quality reference image, rendered on
// first use. Owned by main (no mutable globals: STYLE.md §7).
struct BenchState {
    std::map<std::size_t, std::unique_ptr<BenchScene>> scenes;
    std::optional<std::vector<std::uint8_t>> reference;

    const BenchScene* scene(std::size_t blades, benchmark::State& state) {
        auto found = scenes.find(blades);
        if (found != scenes.end())
            return found->second.get();
        auto built = buildBenchScene(blades);
        if (!built) {
            state.SkipWithError(built.error().str().c_str());
            return nullptr;
        }
        std::printf("scene: %zu blades on %.1f m², %zu billboard objects\n",
                    (*built)->scene.totalBlades(), (*built)->scene.area,
                    (*built)->scene.billboards.objects.size());
        return scenes.emplace(blades, std::move(*built)).first->second.get();
    }
};

double share(std::size_t part, std::size_t whole) {
    return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

void disableCulling(render::RenderOptions& options) {
    options.cull.frustum = false;
    options.cull.orientation = false;
    options.cull.distance = false;
    options.cull.occlusion = false;
}

render::RenderOptions baseOptions(const BenchScene& bench) {
    render::RenderOptions options = render::renderOptionsFor(bench.project, true);
    options.geometry = render::GeometryPath::Strips;
    options.technique = core::GrassTechnique::Blades;
    return options;
}

struct FrameResult {
    render::CullStats stats;                // of the warm-up frame
    std::vector<std::uint8_t> pixels;       // of the warm-up frame, when asked
    std::size_t billboardsDrawn = 0;
};

// One frame with statistics first (untimed: it also pays the driver's shader compile); the
// camera does not move, so its counts are those of every timed frame. Timed frames run without
// statistics, as the editor does.
std::optional<FrameResult> runFrames(benchmark::State& state, const BenchScene& bench,
                                     render::RenderOptions options, bool keepPixels) {
    auto renderer = render::SceneRenderer::create(bench.scene);
    if (!renderer) {
        state.SkipWithError(renderer.error().str().c_str());
        return std::nullopt;
    }
    const core::CameraDesc& desc = bench.project.cameras.front();
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt(desc.position, desc.target, glm::radians(desc.fovYDeg));
    gl::Framebuffer framebuffer(WIDTH, HEIGHT, MSAA_SAMPLES);

    FrameResult result;
    options.cull.collectStats = true;
    (*renderer)->render(camera, WIDTH, HEIGHT, framebuffer, options);
    glFinish();
    const render::FrameTimings warm = (*renderer)->lastTimings();
    result.stats = warm.cull;
    result.billboardsDrawn = warm.billboardsDrawn;
    if (keepPixels)
        result.pixels = framebuffer.readPixels().pixels;
    options.cull.collectStats = false;

    double cullMs = 0.0, opaqueMs = 0.0, grassMs = 0.0, billboardMs = 0.0;
    double minMs = 0.0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        (*renderer)->render(camera, WIDTH, HEIGHT, framebuffer, options);
        glFinish();
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        state.SetIterationTime(seconds);
        minMs = minMs == 0.0 ? 1000.0 * seconds : std::min(minMs, 1000.0 * seconds);
        const render::FrameTimings timings = (*renderer)->lastTimings();
        cullMs += timings.cullMs;
        opaqueMs += timings.meshMs;
        grassMs += timings.grassMs;
        billboardMs += timings.billboardMs;
    }
    const auto avg = benchmark::Counter::kAvgIterations;
    // The fastest timed frame: on a shared machine other work only ever adds time.
    state.counters["min_ms"] = minMs;
    state.counters["cull_ms"] = benchmark::Counter(cullMs, avg);
    state.counters["opaque_ms"] = benchmark::Counter(opaqueMs, avg);
    state.counters["grass_ms"] = benchmark::Counter(grassMs, avg);
    state.counters["billboard_ms"] = benchmark::Counter(billboardMs, avg);
    const render::CullStats& stats = result.stats;
    state.counters["blades_in"] = static_cast<double>(stats.bladesIn);
    state.counters["drawn"] = static_cast<double>(stats.drawn);
    state.counters["culled"] = share(stats.culledTotal(), stats.bladesIn);
    state.counters["c_patch"] = share(stats.culledPatch, stats.bladesIn);
    state.counters["c_orient"] = share(stats.culledOrientation, stats.bladesIn);
    state.counters["c_frustum"] = share(stats.culledFrustum, stats.bladesIn);
    state.counters["c_dist"] = share(stats.culledDistance, stats.bladesIn);
    state.counters["c_occl"] = share(stats.culledOcclusion, stats.bladesIn);
    for (std::size_t lod = 0; lod < stats.drawnPerLod.size(); ++lod)
        state.counters["lod" + std::to_string(lod)] = static_cast<double>(stats.drawnPerLod[lod]);
    state.counters["billboards"] = static_cast<double>(result.billboardsDrawn);
    return result;
}

void configure(benchmark::internal::Benchmark* bench, int iterations) {
    // llvmpipe on 2 cores takes 0.1-12 s a frame here.
    bench->Iterations(iterations)->UseManualTime()->Unit(benchmark::kMillisecond);
}

std::string label(std::size_t blades) {
    return blades % 1'000'000 == 0 ? std::to_string(blades / 1'000'000) + "M"
                                   : std::to_string(blades / 1'000) + "k";
}

void registerCulling(BenchState& benchState, std::size_t blades) {
    for (const bool cullOn : {true, false}) {
        const std::string name = std::string("BM_Frame_Strips/") + label(blades) +
                                 (cullOn ? "/cull_on" : "/cull_off");
        configure(benchmark::RegisterBenchmark(
                      name.c_str(),
                      [&benchState, blades, cullOn](benchmark::State& state) {
                          const BenchScene* bench = benchState.scene(blades, state);
                          if (!bench)
                              return;
                          render::RenderOptions options = baseOptions(*bench);
                          if (!cullOn)
                              disableCulling(options);
                          runFrames(state, *bench, options, false);
                      }),
                  3);
    }
}

// Pay only for what you use (issue 10, SPEC §13): the blades technique on a scene built with
// billboards and snow settings but using neither, against the same scene built without them.
// The first four should cost the same within the run-to-run scatter (docs/rendering.md states
// it); shadows_off configures the sun's shadows without turning them on (issue 30 item 11), and
// shadows_on is what they cost when used.
void registerFeatures(BenchState& benchState, std::size_t blades) {
    const char* variants[] = {"built_without", "billboards_unused", "snow_off", "snow_no_amount",
                              "shadows_off",   "shadows_on"};
    for (const char* variant : variants) {
        const std::string name = std::string("BM_Feature/") + label(blades) + "/" + variant;
        configure(benchmark::RegisterBenchmark(
                      name.c_str(),
                      [&benchState, blades, variant = std::string(variant)](
                          benchmark::State& state) {
                          const BenchScene* bench = benchState.scene(blades, state);
                          if (!bench)
                              return;
                          BenchScene without;
                          if (variant == "built_without") {
                              without.project = bench->project;
                              without.scene = bench->scene;
                              without.scene.billboards.objects.clear();
                              without.scene.billboards.placed.clear();
                              bench = &without;
                          }
                          render::RenderOptions options = baseOptions(*bench);
                          core::SnowParams snow;
                          snow.amountM = 0.3f;
                          if (variant == "snow_off")
                              options.snow = snow;  // configured, enabled = 0
                          if (variant == "snow_no_amount") {
                              snow.enabled = 1u;
                              snow.amountM = 0.0f;
                              options.snow = snow;
                          }
                          options.sun.shadowResolution = 4096;
                          options.sun.shadows = variant == "shadows_on";
                          runFrames(state, *bench, options, false);
                      }),
                  5);
    }
}

void registerTechniques(BenchState& benchState, std::size_t blades) {
    const std::pair<const char*, core::GrassTechnique> techniques[] = {
        {"blades", core::GrassTechnique::Blades},
        {"billboards", core::GrassTechnique::Billboards},
        {"hybrid", core::GrassTechnique::Hybrid}};
    for (const auto& [name, technique] : techniques) {
        const std::string full = std::string("BM_Technique/") + label(blades) + "/" + name;
        configure(benchmark::RegisterBenchmark(
                      full.c_str(),
                      [&benchState, blades, technique = technique](benchmark::State& state) {
                          const BenchScene* bench = benchState.scene(blades, state);
                          if (!bench)
                              return;
                          render::RenderOptions options = baseOptions(*bench);
                          options.technique = technique;
                          runFrames(state, *bench, options, false);
                      }),
                  3);
    }
}

// The reference: strips of REFERENCE_SEGMENTS segments, LOD off, rendered once.
const std::vector<std::uint8_t>* referenceImage(BenchState& benchState, const BenchScene& bench,
                                                benchmark::State& state) {
    if (benchState.reference)
        return &*benchState.reference;
    auto renderer = render::SceneRenderer::create(bench.scene);
    if (!renderer) {
        state.SkipWithError(renderer.error().str().c_str());
        return nullptr;
    }
    const core::CameraDesc& desc = bench.project.cameras.front();
    const core::OrbitCamera camera =
        core::OrbitCamera::lookAt(desc.position, desc.target, glm::radians(desc.fovYDeg));
    gl::Framebuffer framebuffer(WIDTH, HEIGHT, MSAA_SAMPLES);
    render::RenderOptions options = baseOptions(bench);
    options.stripSegments = REFERENCE_SEGMENTS;
    options.cull.lodDistanceM = 0.0f;
    (*renderer)->render(camera, WIDTH, HEIGHT, framebuffer, options);
    glFinish();
    benchState.reference = framebuffer.readPixels().pixels;
    if (const char* folder = std::getenv("GRASS_BENCH_IMAGES"))
        (void)writeRgba8Image(std::string(folder) + "/reference.png", WIDTH, HEIGHT,
                              *benchState.reference);
    return &*benchState.reference;
}

void registerQuality(BenchState& benchState, std::size_t blades) {
    for (const bool tess : {false, true}) {
        for (const int level : {2, 4, 8, 16}) {
            for (const bool lod : {false, true}) {
                const std::string name = std::string("BM_Quality/") + label(blades) +
                                         (tess ? "/tess/" : "/strips/") + std::to_string(level) +
                                         (lod ? "/lod_on" : "/lod_off");
                configure(
                    benchmark::RegisterBenchmark(
                        name.c_str(),
                        [&benchState, blades, tess, level, lod, name](benchmark::State& state) {
                            const BenchScene* bench = benchState.scene(blades, state);
                            if (!bench)
                                return;
                            const auto* reference = referenceImage(benchState, *bench, state);
                            if (!reference)
                                return;
                            render::RenderOptions options = baseOptions(*bench);
                            options.geometry = tess ? render::GeometryPath::Tessellation
                                                    : render::GeometryPath::Strips;
                            options.stripSegments = level;
                            options.tessLevel = level;
                            if (!lod)
                                options.cull.lodDistanceM = 0.0f;
                            const auto result = runFrames(state, *bench, options, true);
                            if (!result)
                                return;
                            const ImageDifference diff =
                                compareImages(result->pixels, *reference, DIFFER_THRESHOLD);
                            // GRASS_BENCH_IMAGES=<folder>: keep each image for a look.
                            if (const char* folder = std::getenv("GRASS_BENCH_IMAGES")) {
                                std::string file = std::string(folder) + "/" + name + ".png";
                                std::replace(file.begin() + static_cast<std::ptrdiff_t>(
                                                                std::string(folder).size() + 1),
                                             file.end(), '/', '_');
                                (void)writeRgba8Image(file, WIDTH, HEIGHT, result->pixels);
                            }
                            state.counters["mean_abs"] = diff.meanAbs;
                            state.counters["differ48"] = diff.differingShare;
                        }),
                    2);
            }
        }
    }
}

void registerLighting(BenchState& benchState, std::size_t blades) {
    struct Variant {
        const char* name;
        core::LightingModel model;
        bool perVertex;
    };
    const Variant variants[] = {{"grass", core::LightingModel::Grass, false},
                                {"grass_vertex", core::LightingModel::Grass, true},
                                {"simple", core::LightingModel::Simple, false}};
    for (const Variant& variant : variants) {
        const std::string name =
            std::string("BM_Lighting/") + label(blades) + "/" + variant.name;
        configure(benchmark::RegisterBenchmark(
                      name.c_str(),
                      [&benchState, blades, variant](benchmark::State& state) {
                          const BenchScene* bench = benchState.scene(blades, state);
                          if (!bench)
                              return;
                          render::RenderOptions options = baseOptions(*bench);
                          options.lighting.model = variant.model;
                          options.lightPerVertex = variant.perVertex;
                          runFrames(state, *bench, options, false);
                      }),
                  3);
    }
}

}  // namespace

// Registered here rather than with BENCHMARK(): the runs need the GL context and the scenes,
// owned by main (no static constructors, no mutable globals: STYLE.md §7).
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
    BenchState benchState;
    registerCulling(benchState, 100'000);
    registerCulling(benchState, 1'000'000);
    registerFeatures(benchState, 100'000);
    registerTechniques(benchState, 100'000);
    registerTechniques(benchState, 1'000'000);
    registerQuality(benchState, QUALITY_BLADES);
    registerLighting(benchState, 100'000);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
