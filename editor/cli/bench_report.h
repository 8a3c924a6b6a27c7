// The figures of one `grass bench` run (issue 10, item 4), their table, their JSON file and the
// comparison of two runs as ratios. No GL here: bench_measure.cpp measures, this file reports.
// Times are milliseconds; "drawn" counts blades that survived the cull pass.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::cli {

// The editor case (issue 24): the real editor loop at wall-clock time, by interaction.
struct EditorPhaseFigures {
    int frames = 0;
    double medianMs = 0.0;
    double p95Ms = 0.0;
};
struct EditorFigures {
    EditorPhaseFigures orbit, paint, play;
    double fullQualityS = 0.0;    // input stops → the full picture is on screen
    double realtimeFactor = 0.0;  // simulated / wall time while playing (1: real time)
};

struct BenchCaseResult {
    std::string name;     // "nature-100k"
    std::string project;  // as given, relative to the bench root ("projects/nature")
    std::size_t bladesIn = 0;
    std::size_t drawn = 0;
    double culledShare = 0.0;  // (in − drawn) / in, 0..1
    int frames = 0;            // timed frames, after the warm-up
    // Medians over the timed frames: CPU wall time of a frame (glFinish included) and the GPU
    // timer queries of each stage (grass = blades + billboards + stem sets).
    double frameMs = 0.0;
    double cullMs = 0.0;
    double opaqueMs = 0.0;
    double grassMs = 0.0;
    double snowMs = 0.0;  // 0: the case has no snow, the pass did not run
    int physicsSteps = 0;
    double physicsMsPerStep = 0.0;
    double bladeStepsPerS = 0.0;
    // The same steps on the CPU's SIMD execution (issue 29; physics_simd.h): where the physics is
    // faster on this machine. 0 in runs saved before it was measured.
    double cpuPhysicsMsPerStep = 0.0;
    double cpuBladeStepsPerS = 0.0;
    double uiMs = 0.0;  // median CPU time to build and tessellate the editor's panels
    // Issue 29 (scale); 0 in runs saved before: the scene build (growth, patches, shading bake)
    // in seconds, and the process's peak resident memory in MB after the case (the peak of the
    // run so far: a case run alone gives its own).
    double buildS = 0.0;
    double peakRssMb = 0.0;
    // Triangles of the blades the warm-up's last frame drew (core::drawnBladeTriangles); 0 in
    // runs saved before 2026-12-05.
    std::size_t bladeTriangles = 0;
    std::optional<EditorFigures> editor;  // the editor case only
};

struct BenchRun {
    std::string renderer;  // GL_RENDERER | GL_VERSION
    int width = 1280;
    int height = 720;
    int msaaSamples = 4;
    std::string geometry;  // strips or tess
    // Invocations a work group of the physics and cull dispatches (GRASS_COMPUTE_GROUP,
    // core/util/blade_pass_group.h); 0 in runs saved before 2026-12-06, all of which used 32.
    std::uint32_t computeGroup = 0;
    std::vector<BenchCaseResult> cases;
};

// The run as JSON ("format": "grass-bench", version 1).
std::string benchRunJson(const BenchRun& run);
// Reads a file written by benchRunJson; the error names `file` and what is wrong with it.
Result<BenchRun> readBenchRun(const std::string& file);

// One row per case on stdout, after a header naming the renderer and the settings.
void printBenchTable(const BenchRun& run);
// The same table with each figure as this run / `old` (1.00 = unchanged; "-" where either is 0,
// "new" for a case `old` lacks). Fails when the runs cannot be compared (other image size, no
// case in common); the error names `oldFile`.
Result<void> printBenchComparison(const BenchRun& run, const BenchRun& old,
                                  const std::string& oldFile);

// Fails early, before the measuring starts, when `old` cannot be compared with a run of
// `caseNames` at width × height.
Result<void> checkComparable(const BenchRun& old, const std::string& oldFile,
                             const std::vector<std::string>& caseNames, int width, int height);

}  // namespace grass::cli
