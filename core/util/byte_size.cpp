#include "util/byte_size.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace grass {

std::string byteSizeText(double bytes) {
    constexpr std::array<const char*, 7> UNITS{"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    if (!std::isfinite(bytes))
        return "inf B";
    std::size_t unit = 0;
    while (unit + 1 < UNITS.size() && bytes >= 1024.0) {
        bytes /= 1024.0;
        ++unit;
    }
    char text[48];
    std::snprintf(text, sizeof text, "%.3g %s", bytes, UNITS[unit]);
    return text;
}

}  // namespace grass
