// Milliseconds of wall-clock time since a steady_clock time point: the one way grass's commands
// and measurements time a stage.
#pragma once

#include <chrono>

namespace grass::tools {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace grass::tools
