// grass soak: a long run of a project's physics, checked for drift and leaks (issue 11).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "physics/path_loop.h"
#include "physics/step_count.h"
#include "project/project_inputs.h"
#include "cli/soak_run.h"
#include "util/arg_parser.h"
#include "util/atomic_file.h"

namespace grass::cli {

namespace {

// Resident memory may grow this much after the first sample interval (the warm-up: thread
// stacks, allocator arenas, the driver's shader cache and read-back staging). A stepped field
// allocates nothing per step, so steady growth is a leak: 16 MiB is a 78-byte leak per step
// over an hour at 60 Hz.
constexpr double RSS_GROWTH_BOUND_MIB = 16.0;
constexpr double MIB = 1024.0 * 1024.0;

struct SoakArgs {
    std::string project, report, backend = "both";
    double seconds = 3600.0;
    double dtS = 1.0 / 60.0;
    double sampleEveryS = 0.0;
    double densityScale = 1.0;
    int threads = 0;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
};

// What a run is judged by (the figures the issue names), with the first failure in words.
struct SoakVerdict {
    double maxLengthErrorPerTolerance = 0.0, maxRelLengthError = 0.0, maxMeanRelLengthError = 0.0;
    double worstLengthAtS = 0.0;
    std::size_t maxNonfinite = 0;
    double nonfiniteAtS = -1.0;
    const SoakSample* warmedUp = nullptr;  // the sample RSS growth is measured from
    double rssGrowthMiB = 0.0;
    std::vector<std::string> failures;
};

SoakVerdict judge(const SoakRun& run, SimBackend backend) {
    SoakVerdict v;
    for (const SoakSample& s : run.samples) {
        if (s.health.maxLengthErrorPerTolerance > v.maxLengthErrorPerTolerance) {
            v.maxLengthErrorPerTolerance = s.health.maxLengthErrorPerTolerance;
            v.worstLengthAtS = s.simulatedS;
        }
        v.maxRelLengthError = std::max(v.maxRelLengthError, s.health.maxRelLengthError);
        v.maxMeanRelLengthError = std::max(v.maxMeanRelLengthError, s.health.meanRelLengthError());
        if (s.health.nonfinite > v.maxNonfinite) {
            v.maxNonfinite = s.health.nonfinite;
            if (v.nonfiniteAtS < 0.0)
                v.nonfiniteAtS = s.simulatedS;
        }
    }
    char text[256];
    if (v.maxLengthErrorPerTolerance > 1.0) {
        std::snprintf(text, sizeof text,
                      "blade length error %.3g times the tolerance at t = %.1f s (max |L - h|/h "
                      "%.3g)",
                      v.maxLengthErrorPerTolerance, v.worstLengthAtS, v.maxRelLengthError);
        v.failures.emplace_back(text);
    }
    if (v.maxNonfinite > 0) {
        std::snprintf(text, sizeof text, "%zu blade(s) with NaN/Inf, first seen at t = %.1f s",
                      v.maxNonfinite, v.nonfiniteAtS);
        v.failures.emplace_back(text);
    }
    // Growth is counted from the end of the first interval; a run of one interval has no warm-up
    // and is measured from its start.
    v.warmedUp = &run.samples[run.samples.size() > 2 ? 1 : 0];
    const SoakSample& last = run.samples.back();
    v.rssGrowthMiB =
        (static_cast<double>(last.rssBytes) - static_cast<double>(v.warmedUp->rssBytes)) / MIB;
    if (v.rssGrowthMiB > RSS_GROWTH_BOUND_MIB) {
        std::snprintf(text, sizeof text,
                      "resident memory grew %.1f MiB from t = %.1f s to the end (bound %.0f MiB)",
                      v.rssGrowthMiB, v.warmedUp->simulatedS, RSS_GROWTH_BOUND_MIB);
        v.failures.emplace_back(text);
    }
    if (backend == SimBackend::Gpu) {
        if (!last.glObjects.noMoreThan(run.glAfterFirstStep))
            v.failures.push_back(
                "live GL objects grew during the run: " + run.glAfterFirstStep.str() +
                " after the first step, " + last.glObjects.str() + " at the end");
        if (!run.glAfterTearDown.noMoreThan(run.glBeforeSetUp))
            v.failures.push_back("GL objects left after tear-down: " + run.glAfterTearDown.str() +
                                 " (before set-up: " + run.glBeforeSetUp.str() + ")");
    }
    return v;
}

void printRun(const char* backendName, const std::string& device, std::size_t blades,
              const SoakRun& run, const SoakVerdict& v, SimBackend backend) {
    const SoakSample& first = run.samples.front();
    const SoakSample& last = run.samples.back();
    std::printf("%s (%s): %zu blades, %zu steps, %.3f s simulated in %.1f s wall (%.3f ms/step)\n",
                backendName, device.c_str(), blades, last.steps, last.simulatedS, run.wallS,
                last.steps > 0 ? 1000.0 * run.wallS / static_cast<double>(last.steps) : 0.0);
    std::printf("  %10s %10s %12s %12s %12s %9s %10s %11s %10s\n", "t (s)", "wall (s)",
                "len err/tol", "max |L-h|/h", "mean |L-h|/h", "nonfinite", "RSS (MiB)",
                "heap (MiB)", "GL objects");
    for (const SoakSample& s : run.samples)
        std::printf("  %10.1f %10.1f %12.3g %12.3g %12.3g %9zu %10.1f %11.1f %10lld\n",
                    s.simulatedS, s.wallS, s.health.maxLengthErrorPerTolerance,
                    s.health.maxRelLengthError, s.health.meanRelLengthError(), s.health.nonfinite,
                    static_cast<double>(s.rssBytes) / MIB,
                    static_cast<double>(s.heapInUseBytes) / MIB,
                    static_cast<long long>(s.glObjects.total()));
    std::printf(
        "  length     max error %.3g of the tolerance (max |L-h|/h %.3g, mean up to %.3g)  %s\n",
        v.maxLengthErrorPerTolerance, v.maxRelLengthError, v.maxMeanRelLengthError,
        v.maxLengthErrorPerTolerance <= 1.0 ? "ok" : "FAILED");
    std::printf("  nonfinite  %zu  %s\n", v.maxNonfinite, v.maxNonfinite == 0 ? "ok" : "FAILED");
    std::printf(
        "  RSS        start %.1f MiB, at t = %.1f s %.1f MiB, end %.1f MiB: %+.1f MiB after "
        "warm-up (bound %.0f MiB; heap in use %+.1f MiB)  %s\n",
        static_cast<double>(first.rssBytes) / MIB, v.warmedUp->simulatedS,
        static_cast<double>(v.warmedUp->rssBytes) / MIB, static_cast<double>(last.rssBytes) / MIB,
        v.rssGrowthMiB, RSS_GROWTH_BOUND_MIB,
        (static_cast<double>(last.heapInUseBytes) -
         static_cast<double>(v.warmedUp->heapInUseBytes)) /
            MIB,
        v.rssGrowthMiB <= RSS_GROWTH_BOUND_MIB ? "ok" : "FAILED");
    if (backend == SimBackend::Gpu) {
        const bool steady = last.glObjects.noMoreThan(run.glAfterFirstStep);
        const bool released = run.glAfterTearDown.noMoreThan(run.glBeforeSetUp);
        std::printf(
            "  GL         before set-up %s; after set-up %s; after the first step %s; end "
            "%s; after tear-down %s  %s\n",
            run.glBeforeSetUp.str().c_str(), first.glObjects.str().c_str(),
            run.glAfterFirstStep.str().c_str(), last.glObjects.str().c_str(),
            run.glAfterTearDown.str().c_str(), steady && released ? "ok" : "FAILED");
    }
}

nlohmann::ordered_json runJson(const char* backendName, const std::string& device,
                               std::size_t blades, const SoakRun& run, const SoakVerdict& v,
                               SimBackend backend) {
    const auto counts = [](const gl::GlObjectCounts& c) {
        nlohmann::ordered_json out;
        for (std::size_t i = 0; i < gl::GL_OBJECT_KIND_COUNT; ++i)
            out[gl::glObjectKindName(static_cast<gl::GlObjectKind>(i))] = c.live[i];
        return out;
    };
    nlohmann::ordered_json out;
    out["backend"] = backendName;
    out["device"] = device;
    out["blades"] = blades;
    out["steps"] = run.samples.back().steps;
    out["seconds"] = run.samples.back().simulatedS;
    out["wall_s"] = run.wallS;
    out["path_window_swaps"] = run.pathSwaps;
    out["max_length_error_per_tolerance"] = v.maxLengthErrorPerTolerance;
    out["max_rel_length_error"] = v.maxRelLengthError;
    out["max_nonfinite"] = v.maxNonfinite;
    out["rss_start_bytes"] = run.samples.front().rssBytes;
    out["rss_warmed_up_bytes"] = v.warmedUp->rssBytes;
    out["rss_end_bytes"] = run.samples.back().rssBytes;
    out["rss_growth_after_warm_up_mib"] = v.rssGrowthMiB;
    out["heap_in_use_start_bytes"] = run.samples.front().heapInUseBytes;
    out["heap_in_use_warmed_up_bytes"] = v.warmedUp->heapInUseBytes;
    out["heap_in_use_end_bytes"] = run.samples.back().heapInUseBytes;
    if (backend == SimBackend::Gpu) {
        out["gl_before_set_up"] = counts(run.glBeforeSetUp);
        out["gl_after_set_up"] = counts(run.samples.front().glObjects);
        out["gl_after_first_step"] = counts(run.glAfterFirstStep);
        out["gl_end"] = counts(run.samples.back().glObjects);
        out["gl_after_tear_down"] = counts(run.glAfterTearDown);
    }
    out["passed"] = v.failures.empty();
    out["failures"] = v.failures;
    auto& samples = out["samples"] = nlohmann::ordered_json::array();
    for (const SoakSample& s : run.samples)
        samples.push_back({{"t", s.simulatedS},
                           {"wall_s", s.wallS},
                           {"length_error_per_tolerance", s.health.maxLengthErrorPerTolerance},
                           {"max_rel_length_error", s.health.maxRelLengthError},
                           {"mean_rel_length_error", s.health.meanRelLengthError()},
                           {"nonfinite", s.health.nonfinite},
                           {"rss_bytes", s.rssBytes},
                           {"heap_in_use_bytes", s.heapInUseBytes},
                           {"gl_objects", s.glObjects.total()}});
    return out;
}

}  // namespace

int runSoak(const std::vector<std::string>& argv) {
    SoakArgs args;
    ArgParser parser(
        "grass soak <project-dir|project.json> [--seconds S] [--dt DT] [--backend cpu|gpu|both] "
        "[--sample-every S] [--density-scale F] [--report FILE]",
        "Runs the project's physics for a long span (default: one hour of game time at 60 Hz) with "
        "its wind and colliders kept moving: paths are held at their last key in a project, so "
        "soak drives every path forth and back (period: twice its span). Every --sample-every "
        "seconds it records the field's length error, NaN/Inf count, the resident memory (RSS) "
        "and, for the GPU, the live GL objects, and prints a table and a verdict. It fails (exit "
        "1) when a blade's length error |L - h| exceeds the tolerance validation states "
        "(docs/physics.md: 1e-4*h + 4*eps*(max|v0| + h)), a NaN/Inf appears, RSS grows more "
        "than 16 MiB after the first interval, or GL objects are left over (more at the end than "
        "after the first step, or after tear-down than before set-up).");
    parser.positional("project", "a project folder (with project.json) or a project .json file",
                      &args.project, true);
    parser.number("--seconds", "S", "simulated time", &args.seconds, 1e-3, 864000.0, "3600");
    parser.number("--dt", "DT", "step length in seconds", &args.dtS, 1e-4, 1.0, "1/60");
    parser.choice("--backend", {"both", "cpu", "gpu"},
                  "cpu: the C++ reference; gpu: the compute shader; both: cpu, then gpu",
                  &args.backend);
    parser.number("--sample-every", "S", "simulated seconds between samples", &args.sampleEveryS,
                  1e-4, 864000.0, "S/60");
    // Thins the field (every layer's density times F) so a long soak of a big project fits a
    // slow machine: every blade runs the same physics, so drift per blade is what it would be at
    // full density; the step cost falls with the blade count.
    parser.number("--density-scale", "F", "grow every layer at F times its density",
                  &args.densityScale, 1e-6, 1.0, "1");
    parser.integer("--threads", "CPU threads for the cpu backend (0: all cores, at most 8)",
                   &args.threads, 0, 256);
    parser.text("--report", "FILE", "write the samples and verdicts as JSON to FILE", &args.report);
    parser.flag("--gl-debug", "print GL debug output (gpu backend)", &args.glDebug);
    if (auto parsed = parser.parse(argv); !parsed) {
        printError("soak", parsed.error().str());
        return EXIT_USAGE;
    }
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    if (!args.report.empty())
        if (auto writable = checkFileWritable(args.report, "soak.json"); !writable) {
            printError("soak", "--report: " + writable.error().str());
            return EXIT_USAGE;
        }
    if (!parser.given("--sample-every"))
        args.sampleEveryS = args.seconds / 60.0;

    auto loaded = core::loadProject(args.project);
    if (!loaded) {
        printError("soak", loaded.error().str());
        return EXIT_FAILED;
    }
    if (!args.report.empty())
        if (auto refused = core::refuseOverwritingInput(*loaded, args.report, "--report");
            !refused) {
            printError("soak", refused.error().str());
            return EXIT_USAGE;
        }
    loaded->project.physics.dtS = static_cast<float>(args.dtS);
    for (const auto& [option, seconds] :
         {std::pair{"--seconds", args.seconds}, {"--sample-every", args.sampleEveryS}})
        if (auto steps = core::simulationSteps(seconds, args.dtS, option); !steps) {
            printError("soak", steps.error().str());
            return EXIT_USAGE;
        }
    for (core::GrassLayer& layer : loaded->project.layers)
        layer.scatter.density *= static_cast<float>(args.densityScale);
    auto physics = core::buildScenePhysics(*loaded);
    if (!physics) {
        printError("soak", physics.error().str());
        return EXIT_FAILED;
    }
    for (const auto& note : physics->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    const core::PathLooper looper(physics->wind, physics->colliders);
    std::string motion;
    if (physics->wind.empty() && physics->colliders.empty())
        motion = "no wind and no colliders: the field stands still";
    else if (looper.loopingPaths() == 0)
        motion = "no paths to loop (wind moves with time only)";
    else {
        char text[160];
        std::snprintf(text, sizeof text,
                      "%zu path(s) driven forth and back (longest period %.4g s)",
                      looper.loopingPaths(), static_cast<double>(looper.longestPeriodS()));
        motion = text;
    }

    std::vector<SimBackend> backends;
    if (args.backend != "gpu")
        backends.push_back(SimBackend::Cpu);
    if (args.backend != "cpu")
        backends.push_back(SimBackend::Gpu);
    const unsigned threads = args.threads > 0
                                 ? static_cast<unsigned>(args.threads)
                                 : std::max(1u, std::min(std::thread::hardware_concurrency(), 8u));
    std::unique_ptr<gl::HeadlessContext> context;
    nlohmann::ordered_json report;
    report["project"] = args.project;
    report["dt"] = args.dtS;
    report["seconds"] = args.seconds;
    report["sample_every_s"] = args.sampleEveryS;
    report["density_scale"] = args.densityScale;
    report["rss_growth_bound_mib"] = RSS_GROWTH_BOUND_MIB;
    report["length_tolerance"] = "1e-4*h + 4*eps*(max|v0| + h)";
    report["motion"] = motion;
    report["runs"] = nlohmann::ordered_json::array();
    bool passed = true;
    std::printf(
        "soak of %s: %.3f s at dt %.4g s (%zu steps), wind %zu source(s), %zu collider "
        "sphere(s), %s\n",
        loaded->project.name.c_str(), args.seconds, args.dtS,
        stepsFor(args.seconds, static_cast<float>(args.dtS)), physics->wind.size(),
        physics->colliders.size(), motion.c_str());
    for (const SimBackend backend : backends) {
        // A fresh field per backend, so each starts from rest.
        auto scene = core::buildScene(*loaded);
        if (!scene) {
            printError("soak", scene.error().str());
            return EXIT_FAILED;
        }
        std::string device =
            "CPU reference, " + std::to_string(threads) + (threads == 1 ? " thread" : " threads");
        if (backend == SimBackend::Gpu) {
            if (!context) {
                auto created = gl::HeadlessContext::create(args.glDebug);
                if (!created) {
                    printError("soak", created.error().str());
                    return EXIT_FAILED;
                }
                context = std::move(*created);
            }
            device = gl::rendererDescription();
        }
        const char* name = backend == SimBackend::Gpu ? "gpu" : "cpu";
        core::SceneSimulation simulation(*scene, *physics, threads);
        auto run = soakSimulation(*scene, simulation, backend,
                                  {args.seconds, args.sampleEveryS, name}, stderr);
        if (!run) {
            printError("soak", run.error().str());
            return EXIT_FAILED;
        }
        const SoakVerdict verdict = judge(*run, backend);
        printRun(name, device, scene->totalBlades(), *run, verdict, backend);
        report["runs"].push_back(
            runJson(name, device, scene->totalBlades(), *run, verdict, backend));
        for (const std::string& failure : verdict.failures)
            printError("soak", std::string(name) + ": " + failure);
        passed = passed && verdict.failures.empty();
    }
    report["passed"] = passed;
    if (!args.report.empty()) {
        if (auto written = writeFileAtomic(args.report, report.dump(2) + "\n"); !written) {
            printError("soak", written.error().str());
            return EXIT_FAILED;
        }
        std::printf("wrote %s\n", args.report.c_str());
    }
    std::printf("soak %s\n", passed ? "passed" : "FAILED");
    return passed ? 0 : EXIT_FAILED;
}

}  // namespace grass::cli
