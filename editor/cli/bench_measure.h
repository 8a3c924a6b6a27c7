// The measuring of `grass bench`: every chosen case on one headless GL context. Per case: frames
// of the project's first camera (per-stage GPU timer queries and wall time, medians after a
// warm-up), the cull pass's counts, the compute-shader physics (blade-steps per second) and the
// CPU time of one frame of the editor's real side panel (build + tessellate). Progress goes to
// stderr.
#pragma once

#include <stop_token>
#include <vector>

#include "cli/bench_cases.h"
#include "cli/bench_options.h"
#include "cli/bench_report.h"
#include "util/result.h"

namespace grass::cli {

// Measures every case in `cases`; the error names the case's file or the GL failure.
// A stop requested (Ctrl+C, interrupt_stop.h) ends the run after the case under way: the run
// holds the cases measured.
Result<BenchRun> measureRun(const BenchArgs& args, const std::vector<const BenchCase*>& cases,
                            std::stop_token stop = {});

}  // namespace grass::cli
