// The command line of `grass bench`: which cases, how many frames and steps, the image, and the
// files it reads (--compare, --results) and writes (--out).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gl/debug_output.h"

namespace grass::cli {

inline constexpr std::string_view DEFAULT_BENCH_CASES =
    "nature-100k,nature-100k-all,helicopter-100k,winter-100k,nature-1m,helicopter-1m,"
    "editor-meadow";

struct BenchArgs {
    std::string cases{DEFAULT_BENCH_CASES}, out, compare, results, root = GRASS_SOURCE_DIR;
    std::string geometry = "auto", msaa = "4";
    int frames = 5, framesLarge = 2, warmup = 1, steps = 10, stepsLarge = 3;
    int width = 1280, height = 720;
    bool quick = false;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
    // The first option given that only a measuring run takes ("": none), refused with --results.
    std::string measuringOption;
};

// Reads the command line into `args`. Returns the exit code when the command ends here (--help,
// or a usage error printed); nothing when it goes on.
std::optional<int> parseBenchArgs(const std::vector<std::string>& argv, BenchArgs& args);

}  // namespace grass::cli
