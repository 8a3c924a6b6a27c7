// Scattering and patching cost (Google Benchmark; Release; never gates CI). Run:
//   cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DGRASS_BUILD_BENCH=ON
//   cmake --build build-bench --target bench_scatter && build-bench/bin/bench_scatter
#include <benchmark/benchmark.h>

#include "mesh/procedural.h"
#include "scatter/patches.h"
#include "scatter/scatter.h"

namespace {

using namespace grass::core;

SurfaceMesh hills(int resolution) {
    ProceduralMeshParams params;
    params.shape = ProceduralShape::Hills;
    params.size = 50.0f;
    params.resolution = resolution;
    return makeProceduralMesh(params);
}

// Blades per second of the uniform distribution; state.range(0) = target blade count.
void BM_ScatterUniform(benchmark::State& state) {
    const SurfaceMesh mesh = hills(96);
    ScatterParams params;
    params.density = static_cast<float>(static_cast<double>(state.range(0)) / surfaceArea(mesh));
    for (auto _ : state) {
        ScatterResult result = scatterBlades(mesh, params, nullptr, 1);
        benchmark::DoNotOptimize(result.blades.data());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ScatterUniform)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_ScatterClumps(benchmark::State& state) {
    const SurfaceMesh mesh = hills(96);
    ScatterParams params;
    params.density = 0.0f;
    params.clumpSpacing = 0.35f;
    params.bladesPerClump = 12;
    for (auto _ : state) {
        ScatterResult result = scatterBlades(mesh, params, nullptr, 1);
        benchmark::DoNotOptimize(result.blades.data());
    }
}
BENCHMARK(BM_ScatterClumps)->Unit(benchmark::kMillisecond);

void BM_BuildPatches(benchmark::State& state) {
    const SurfaceMesh mesh = hills(96);
    ScatterParams params;
    params.density = static_cast<float>(static_cast<double>(state.range(0)) / surfaceArea(mesh));
    const ScatterResult scattered = scatterBlades(mesh, params, nullptr, 1);
    for (auto _ : state) {
        PatchedBlades patched = buildPatches(scattered.blades, 256);
        benchmark::DoNotOptimize(patched.blades.data());
    }
    state.SetItemsProcessed(state.iterations() *
                            static_cast<std::int64_t>(scattered.blades.size()));
}
BENCHMARK(BM_BuildPatches)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
