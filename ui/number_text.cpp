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

int significantDecimals(double value, int decimals, int significant) {
    const double magnitude = std::abs(value);
    if (!(magnitude > 0.0 && magnitude < 1.0))
        return shownDecimals(value, decimals);
    // 0.00345: the first significant digit is the third decimal (floor(log10) = -3).
    const int firstDigit = -int(std::floor(std::log10(magnitude)));
    return std::max(std::max(decimals, 0),
                    std::min(firstDigit + significant - 1, MAX_SIGNIFICANT_DECIMALS));
}

std::string numberText(double value, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", shownDecimals(value, decimals), value);
    return buffer;
}

}  // namespace grass::ui
