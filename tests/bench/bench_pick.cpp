// Picking cost (issue 8): BVH build time and rays per second through the BVH against testing
// every triangle, on the bunny and a 1M-triangle hills terrain. Google Benchmark; Release;
// never gates CI. Run:
//   cmake -S . -B build-bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DGRASS_BUILD_BENCH=ON
//   cmake --build build-bench --target bench_pick && build-bench/bin/bench_pick
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "mesh/bvh.h"
#include "mesh/gltf_loader.h"
#include "mesh/procedural.h"
#include "scene/camera.h"
#include "util/rng.h"

namespace {

using namespace grass::core;

// Bench meshes are built once, on first use; by index: 0 bunny, 1 hills (2·700² = 980k tris).
const SurfaceMesh& benchMesh(std::int64_t which) {
    static const SurfaceMesh bunny = [] {
        // The source tree from this file's path (CMake passes sources by absolute path).
        const auto source = std::filesystem::path(__FILE__).parent_path() / ".." / "..";
        auto loaded = loadGltf(source / "projects" / "nature" / "bunny.glb");
        if (!loaded.ok()) {
            std::fprintf(stderr, "%s\n", loaded.error().str().c_str());
            std::exit(1);
        }
        return std::move(loaded).value().mesh;
    }();
    static const SurfaceMesh hills = [] {
        ProceduralMeshParams params;
        params.shape = ProceduralShape::Hills;
        params.size = 50.0f;
        params.hillHeight = 3.0f;
        params.resolution = 700;
        return makeProceduralMesh(params);
    }();
    return which == 0 ? bunny : hills;
}

const TriangleBvh& benchBvh(std::int64_t which) {
    static const TriangleBvh bunny(benchMesh(0));
    static const TriangleBvh hills(benchMesh(1));
    return which == 0 ? bunny : hills;
}

// The rays of a cursor over the mesh: from the eye of a camera framing it towards random
// points of random triangles (all hit, unless something nearer is in the way: that is the
// point of picking).
std::vector<Ray> pickRays(const SurfaceMesh& mesh, std::size_t count) {
    const OrbitCamera camera = frameBounds(meshBounds(mesh), 0.785f);
    const glm::vec3 eye = camera.position();
    grass::Rng rng(3);
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < count; ++i) {
        const auto face = mesh.face_handle(int(rng.below(std::uint32_t(mesh.n_faces()))));
        const auto p = facePositions(mesh, face);
        const float u = rng.uniform(), v = rng.uniform() * (1.0f - u);
        const glm::vec3 target = p[0] + u * (p[1] - p[0]) + v * (p[2] - p[0]);
        rays.push_back(Ray{eye, glm::normalize(target - eye)});
    }
    return rays;
}

void BM_BvhBuild(benchmark::State& state) {
    const SurfaceMesh& mesh = benchMesh(state.range(0));
    for (auto _ : state) {
        TriangleBvh bvh(mesh);
        benchmark::DoNotOptimize(bvh.nodeCount());
    }
    state.counters["triangles"] = double(mesh.n_faces());
    state.counters["nodes"] = double(benchBvh(state.range(0)).nodeCount());
}
BENCHMARK(BM_BvhBuild)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_PickBvh(benchmark::State& state) {
    const TriangleBvh& bvh = benchBvh(state.range(0));
    const std::vector<Ray> rays = pickRays(benchMesh(state.range(0)), 4096);
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const auto hit = bvh.intersect(rays[i++ % rays.size()]);
        hits += hit ? 1 : 0;
        benchmark::DoNotOptimize(hit);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["rays/s"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * double(hits) / double(std::max<std::size_t>(i, 1));
    state.counters["triangles"] = double(bvh.triangleCount());
}
BENCHMARK(BM_PickBvh)->Arg(0)->Arg(1);

void BM_PickBruteForce(benchmark::State& state) {
    const TriangleBvh& bvh = benchBvh(state.range(0));
    const std::vector<Ray> rays = pickRays(benchMesh(state.range(0)), 64);
    std::size_t i = 0;
    for (auto _ : state) {
        const auto hit = bruteForceIntersect(bvh, rays[i++ % rays.size()]);
        benchmark::DoNotOptimize(hit);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["rays/s"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["triangles"] = double(bvh.triangleCount());
}
BENCHMARK(BM_PickBruteForce)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
