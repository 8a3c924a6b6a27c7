#include "util/pareto.h"

#include <cmath>

namespace grass::core {

namespace {

bool isFinite(const CostError& p) {
    return std::isfinite(p.cost) && std::isfinite(p.error);
}

}  // namespace

std::vector<bool> paretoFront(std::span<const CostError> points) {
    std::vector<bool> front(points.size(), false);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!isFinite(points[i]))
            continue;
        bool dominated = false;
        for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
            if (j == i || !isFinite(points[j]))
                continue;
            const CostError& a = points[j];
            const CostError& b = points[i];
            dominated =
                a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
        }
        front[i] = !dominated;
    }
    return front;
}

}  // namespace grass::core
