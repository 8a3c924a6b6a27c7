// The Pareto front of (cost, error) points: the settings no other setting beats on both. Used by
// `grass tradeoff` to mark which settings of a quality knob are worth choosing.
#pragma once

#include <span>
#include <vector>

namespace grass::core {

struct CostError {
    double cost = 0.0;
    double error = 0.0;
};

// front[i] is true when no point j is at most as costly and at most as wrong as point i and
// strictly better in one of the two. Equal points are all on the front. Non-finite points are
// never on it and never dominate.
std::vector<bool> paretoFront(std::span<const CostError> points);

}  // namespace grass::core
