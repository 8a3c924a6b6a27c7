#include "cli/soak_verdict.h"

#include <algorithm>
#include <cstdio>

namespace grass::cli {

namespace {

constexpr double MIB = 1024.0 * 1024.0;

}  // namespace

SoakVerdict judgeSoakRun(const SoakRun& run, SimBackend backend) {
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

void printSoakRun(const char* backendName, const std::string& device, std::size_t blades,
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

nlohmann::ordered_json soakRunJson(const char* backendName, const std::string& device,
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

}  // namespace grass::cli
