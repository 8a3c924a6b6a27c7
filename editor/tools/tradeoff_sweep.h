// The quality knobs of a project swept against a high-quality reference (issue 10, SPEC §13):
// `grass tradeoff` and its GL test. For each setting of a knob: the frame cost (wall clock to the
// end of glFinish and the GL timer queries per stage, median and spread over several frames)
// and the error against the reference of the same scene at the same scene time:
//   - image knobs: mean CIELAB ΔE76 (core/util/color_difference.h) over the pixels the feature
//     touches in either image, i.e. pixels that differ from the same frame drawn without it
//     (without grass for the grass knobs, without snow for the snow knob);
//   - the physics step: the tips' trajectory error |v2 − v2_ref| / h (blade heights), max and
//     mean over every blade and every sample time of the run.
// Costs in milliseconds, distances in metres, times in seconds.
#pragma once

#include <functional>
#include <stop_token>
#include <string>
#include <vector>

#include "project/project.h"
#include "util/result.h"

namespace grass::render {

struct TradeoffOptions {
    // Knob names (tradeoffKnobNames()); empty: every knob.
    std::vector<std::string> knobs;
    int width = 1280;
    int height = 720;
    int msaaSamples = 4;
    int frames = 5;               // timed frames per setting, after one untimed warm-up frame
    std::string camera;           // the project's camera by name ("": the first)
    float sceneTimeS = 1.0f;      // images: the scene simulated (project physics) to this time
    double physicsSeconds = 2.0;  // physics knob: simulated span
    // Physics knob: tips compared every this many seconds (a multiple of every step swept).
    double sampleEveryS = 1.0 / 30.0;
    // Progress lines ("knob 2/6 lod_distance 8 m: frame 3/5"); null: silent.
    std::function<void(const std::string&)> progress;
    // A stop requested (Ctrl+C) ends the sweep after the knob under way: the report holds the
    // knobs measured.
    std::stop_token stop;
};

struct Spread {
    double median = 0.0, min = 0.0, max = 0.0;
};

struct SettingResult {
    std::string label;   // "8 m", "1/60 s", "1024² × 8"
    double value = 0.0;  // the knob's number (the physics step in s, a distance, a count)
    bool reference = false;
    bool check = false;  // the reference's own convergence check (finer than the reference)
    // Cost plotted against the error: the frame's wall ms (images) or the physics wall ms per
    // 1/60 s of simulated time (physics step).
    Spread costMs;
    // GL_TIME_ELAPSED medians per stage: opaque, cull, grass, billboards, snow; physics.
    double meshMs = 0.0, cullMs = 0.0, grassMs = 0.0, billboardMs = 0.0, snowMs = 0.0;
    double physicsGpuMs = 0.0;
    std::size_t bladesDrawn = 0;
    // Error against the reference: mean ΔE76 (images) or mean tip error in blade heights.
    double error = 0.0;
    double errorMax = 0.0;   // max ΔE76 of a pixel, or max tip error
    std::size_t pixels = 0;  // images: pixels in the mask
    bool pareto = false;
};

struct KnobResult {
    std::string name;
    std::string description;
    std::string errorMetric;
    std::string costMetric;
    std::string skipped;  // non-empty: why the knob was not measured (the project lacks it)
    std::vector<SettingResult> settings;  // the swept settings, then the reference (and check)
    // The reference against the finer check setting (0 and empty label when the reference is
    // exact, e.g. LOD off). Converged: under convergedBelow (a tenth of a just-noticeable
    // difference, 0.23 ΔE76; 0.001 h for the tips). Resolves the sweep: under half the smallest
    // swept error, so every swept error is known within a factor of 2.
    std::string checkLabel;
    double referenceCheckError = 0.0;
    double convergedBelow = 0.0;
    bool referenceConverged = true;
    bool referenceResolvesSweep = true;
};

struct TradeoffReport {
    std::string project;
    std::string device;
    std::string geometry;  // strips or tessellation
    int width = 0, height = 0, frames = 0, msaaSamples = 0;
    float sceneTimeS = 0.0f;
    double physicsSeconds = 0.0;
    std::size_t blades = 0;
    std::vector<KnobResult> knobs;
    double wallS = 0.0;
};

// physics_step, geometry_detail, lod_distance, cull_distance, distance_classes, snow_map,
// billboard_fade, ao_kernel.
std::vector<std::string> tradeoffKnobNames();
// The knob names joined by commas: "physics_step,geometry_detail,...".
std::string tradeoffKnobList();

// Runs the sweep on a current GL context. Errors: an unknown knob name, a project that does not
// build, a shader that does not compile.
Result<TradeoffReport> runTradeoffSweep(const core::LoadedProject& loaded,
                                        const TradeoffOptions& options);

}  // namespace grass::render
