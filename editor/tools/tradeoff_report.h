// What `grass tradeoff` writes and prints: the sweep (tradeoff_sweep.h) as JSON (tradeoff.json)
// and as one markdown table per knob.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "tools/tradeoff_sweep.h"

namespace grass::render {

nlohmann::ordered_json tradeoffJson(const TradeoffReport& report);
// Per setting of the knob, the presets the rule of core/quality/quality_presets.h would choose
// from this run ("draft, balanced"; empty for none): what these measurements would make them.
std::vector<std::string> presetLabels(const KnobResult& knob);
std::string tradeoffTable(const TradeoffReport& report);
// Reads a tradeoff.json back (`grass tradeoff --replot`: new plots and tables without measuring
// again). Errors name `sourceName` and the missing or malformed field.
Result<TradeoffReport> tradeoffFromJson(const std::string& text, const std::string& sourceName);

}  // namespace grass::render
