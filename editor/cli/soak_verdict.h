// What `grass soak` judges a run by (issue 11): the worst length error, NaN/Inf, resident memory
// growth after the warm-up and, for the GPU, leftover GL objects; and how it prints the run and
// its verdict as a table and as the run's object of the JSON report.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/soak_run.h"

namespace grass::cli {

// Resident memory may grow this much after the first sample interval (the warm-up: thread
// stacks, allocator arenas, the driver's shader cache and read-back staging). A stepped field
// allocates nothing per step, so steady growth is a leak: 16 MiB is a 78-byte leak per step
// over an hour at 60 Hz.
inline constexpr double RSS_GROWTH_BOUND_MIB = 16.0;

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

SoakVerdict judgeSoakRun(const SoakRun& run, SimBackend backend);
// The run's samples as a table, then each figure with "ok" or "FAILED".
void printSoakRun(const char* backendName, const std::string& device, std::size_t blades,
                  const SoakRun& run, const SoakVerdict& v, SimBackend backend);
// The run's entry of the --report file's "runs".
nlohmann::ordered_json soakRunJson(const char* backendName, const std::string& device,
                                   std::size_t blades, const SoakRun& run, const SoakVerdict& v,
                                   SimBackend backend);

}  // namespace grass::cli
