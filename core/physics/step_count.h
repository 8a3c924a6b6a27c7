// How many physics steps a run of game time takes, bounded: a step of 1e-30 s once gave
// 9.2e18 steps (llround overflowing) and a run that never ends. Every command that simulates
// (sim, render --time, soak, tradeoff) asks here before it builds anything.
#pragma once

#include <cstddef>
#include <string>

#include "util/result.h"

namespace grass::core {

// Ten million steps: 46 hours of game time at 60 Hz, about an hour of CPU physics on a small
// field; more is never one run of ours (docs/project-format.md "Limits").
inline constexpr double MAX_SIMULATION_STEPS = 1e7;

// round(seconds / dtS), or an error naming `option` (the run's length, "--seconds") with the
// steps asked for, the limit and what to change.
Result<std::size_t> simulationSteps(double seconds, double dtS, const std::string& option);

}  // namespace grass::core
