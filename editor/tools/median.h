// The median of timed samples, the figure every measurement of grass reports (a mean would let
// one stalled frame move it).
#pragma once

#include <algorithm>
#include <vector>

namespace grass::tools {

inline double median(std::vector<double> values) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace grass::tools
