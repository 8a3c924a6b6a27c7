// The tradeoff.json files under core/quality/measured/, compiled in by CMake
// (core/quality/measured_tradeoffs.cpp.in) so that presets need no file at run time.
#pragma once

#include <string_view>
#include <vector>

namespace grass::core {

struct MeasuredDocument {
    std::string_view name;  // the file's name, for errors
    std::string_view text;
};

// In file-name order.
const std::vector<MeasuredDocument>& measuredTradeoffDocuments();

}  // namespace grass::core
