#include "physics/step_count.h"

#include <cmath>
#include <cstdio>

namespace grass::core {

Result<std::size_t> simulationSteps(double seconds, double dtS, const std::string& option) {
    if (!(seconds > 0.0))
        return std::size_t{0};
    const double steps = std::round(seconds / dtS);
    if (!(dtS > 0.0) || !(steps <= MAX_SIMULATION_STEPS)) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "%g s at a physics step of %g s is %.3g steps; the limit is %.0e: shorten "
                      "the run or lengthen the step (/physics/step_s, --dt)",
                      seconds, dtS, steps, MAX_SIMULATION_STEPS);
        return makeError(option, text);
    }
    return static_cast<std::size_t>(steps);
}

}  // namespace grass::core
