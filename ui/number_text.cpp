#include "ui/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grass::ui {

int shownDecimals(double value, int decimals) {
    decimals = std::max(decimals, 0);
    const double magnitude = std::abs(value);
    if (!(magnitude >= 1.0) || !std::isfinite(magnitude))
        return decimals;
    const int whole = int(std::floor(std::log10(magnitude))) + 1;  // digits before the point
    return std::clamp(FLOAT_SIGNIFICANT_DIGITS - whole, 0, decimals);
}

std::string numberText(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", shownDecimals(value, decimals), value);
    return buffer;
}

}  // namespace grass::ui
