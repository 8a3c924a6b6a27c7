// Plots of `grass tradeoff`: per measured knob, DIR/<knob>.dat (the points), DIR/<knob>.gp (a
// gnuplot script) and, when gnuplot is installed, DIR/<knob>.png (cost against error, the
// Pareto front joined and marked, the reference apart). No GL.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tools/tradeoff_sweep.h"
#include "util/result.h"

namespace grass::render {

struct PlotFiles {
    std::vector<std::filesystem::path> written;  // .dat, .gp and the PNGs made
    // Non-empty when gnuplot was missing or failed: the scripts are there, the PNGs are not.
    std::string warning;
};

Result<PlotFiles> writeTradeoffPlots(const TradeoffReport& report,
                                     const std::filesystem::path& folder);

}  // namespace grass::render
