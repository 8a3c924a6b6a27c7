// The standard benchmark set of `grass bench` (issue 10, item 4): each case a project grown to
// a blade count, and the choice of cases a run measures.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::cli {

// A case: a project (relative to --root) grown to about `targetBlades` (0: as the project says).
struct BenchCase {
    const char* name;
    const char* project;
    double targetBlades;
    // Runs the real editor (grass-editor) on the project instead of the headless renderer.
    bool editor;
    // Equal work (issue 29): every blade drawn at full detail (no culling test, no LOD) without
    // multisampling, whatever --msaa says, so that a run measures what one drawn blade costs.
    bool everyBlade = false;
    // A technique instead of the project's (core::parseGrassTechnique's names), e.g. "hybrid".
    const char* technique = nullptr;
};

// The paper scenes at 100k and 1M blades (SPEC §14: nature 398k, helicopter 900k in the paper),
// winter for the snow pass (the paper scenes have no snow), and tiny (tiny-hybrid: as the
// hybrid technique) for tests.
// editor-meadow: the editor as a user meets it (issue 24), orbiting, painting and playing the
// meadow at wall-clock time in its window.
// nature-100k-all: nature-100k with every blade drawn in full, the measure of a blade's cost.
// nature-1m-all: a million blades drawn in full (issue 29's GPU target: 1 M visible blades drawn
// in 3 ms at 1080p).
// nature-1m-hybrid: nature-1m drawn as the hybrid technique (blades near, star billboards from
// the cross-fade on), the representation that could meet that target where full blades cannot:
// the same million blades, a fraction of the triangles.
// nature-10m (issue 29, scale): nature at 10 million blades; only when named in --cases (a few
// minutes and ~10 GB on llvmpipe).
inline constexpr std::array<BenchCase, 12> BENCH_CASES = {{
    {"nature-100k", "projects/nature", 1e5, false},
    {"nature-100k-all", "projects/nature", 1e5, false, true},
    {"helicopter-100k", "projects/helicopter", 1e5, false},
    {"winter-100k", "projects/winter", 1e5, false},
    {"nature-1m", "projects/nature", 1e6, false},
    {"helicopter-1m", "projects/helicopter", 1e6, false},
    {"nature-10m", "projects/nature", 1e7, false},
    {"nature-1m-all", "projects/nature", 1e6, false, true},
    {"nature-1m-hybrid", "projects/nature", 1e6, false, false, "hybrid"},
    {"tiny", "tests/data/projects/tiny", 0.0, false},
    {"tiny-hybrid", "tests/data/projects/tiny", 0.0, false, false, "hybrid"},
    {"editor-meadow", "projects/meadow", 0.0, true},
}};

// Above this many blades a case is "large": fewer frames and steps (a 1M-blade frame takes
// seconds on llvmpipe), and --quick leaves it out.
inline constexpr double LARGE_CASE_BLADES = 1e5;

inline bool isLargeCase(const BenchCase& c) {
    return c.targetBlades > LARGE_CASE_BLADES;
}

// The cases of the comma-separated `list` in its order, without the large ones when `quick`.
// Errors name --cases (an unknown or repeated case) or --quick (no case left).
Result<std::vector<const BenchCase*>> selectCases(const std::string& list, bool quick);

}  // namespace grass::cli
