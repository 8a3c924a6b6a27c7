#include "blade/blade_shape.h"

#include <algorithm>
#include <string>

namespace grass::core {

float widthCorrectionPhi(float widthPx) {
    return 1.0f - std::clamp((widthPx - WIDTH_CORRECTION_MIN_PX) / WIDTH_CORRECTION_SPAN_PX, 0.0f,
                             1.0f);
}

float widthCorrectedT(float t, float u, float widthPx) {
    if (widthPx < 0.0f)
        return t;
    return t + widthCorrectionPhi(widthPx) * (u - t);
}

const std::array<std::string_view, BLADE_SHAPE_COUNT>& bladeShapeNames() {
    return BLADE_SHAPE_NAMES;
}

std::string_view bladeShapeName(BladeShape shape) {
    const auto index = static_cast<std::size_t>(shape);
    return index < BLADE_SHAPE_COUNT ? bladeShapeNames()[index] : "triangle";
}

Result<BladeShape> parseBladeShape(std::string_view name) {
    const auto& names = bladeShapeNames();
    std::string valid;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name)
            return static_cast<BladeShape>(i);
        valid += (i ? ", \"" : "\"") + std::string(names[i]) + "\"";
    }
    return makeError("",
                     "unknown blade shape \"" + std::string(name) + "\" (valid: " + valid + ")");
}

}  // namespace grass::core
