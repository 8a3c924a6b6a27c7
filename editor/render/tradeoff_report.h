// What `grass tradeoff` writes and prints: the sweep (tradeoff_sweep.h) as JSON (tradeoff.json)
// and as one markdown table per knob.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "tradeoff_sweep.h"

namespace grass::render {

nlohmann::ordered_json tradeoffJson(const TradeoffReport& report);
std::string tradeoffTable(const TradeoffReport& report);

}  // namespace grass::render
