#include "cli/stroke_text.h"

#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <string_view>

namespace grass::cli {

namespace {

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.remove_suffix(1);
    return text;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos)
            return parts;
        start = end + 1;
    }
}

}  // namespace

Result<std::vector<std::string>> takeStrokes(std::vector<std::string>& args) {
    std::vector<std::string> strokes, rest;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--stroke") {
            if (i + 1 >= args.size())
                return makeError("--stroke", "needs a value: --stroke \"x,y,z; x,y,z; ...\"");
            strokes.push_back(args[++i]);
        } else if (args[i].rfind("--stroke=", 0) == 0) {
            strokes.push_back(args[i].substr(9));
        } else {
            rest.push_back(args[i]);
        }
    }
    args = std::move(rest);
    return strokes;
}

Result<std::vector<glm::vec3>> parseStroke(const std::string& text, std::size_t strokeNumber,
                                           int dims) {
    const std::string stroke = "stroke " + std::to_string(strokeNumber);
    const std::string shape = dims == 3 ? "x,y,z" : "u,v";
    const std::vector<std::string_view> points = split(text, ';');
    std::vector<glm::vec3> out;
    for (std::size_t p = 0; p < points.size(); ++p) {
        const std::string where = stroke + ", point " + std::to_string(p + 1);
        const std::string_view point = trimmed(points[p]);
        if (point.empty()) {
            if (p + 1 == points.size() && p > 0)
                break;
            return makeError("--stroke", where + ": empty (expected " + shape + ")");
        }
        const std::vector<std::string_view> numbers = split(point, ',');
        if (numbers.size() != static_cast<std::size_t>(dims))
            return makeError("--stroke", where + ": expected " + shape + " (" +
                                             std::to_string(dims) + " numbers), got '" +
                                             std::string(point) + "'");
        glm::vec3 position(0.0f);
        for (int k = 0; k < dims; ++k) {
            const std::string_view number = trimmed(numbers[static_cast<std::size_t>(k)]);
            double parsed = 0.0;
            const auto [ptr, ec] =
                std::from_chars(number.data(), number.data() + number.size(), parsed);
            if (number.empty() || ec != std::errc() || ptr != number.data() + number.size())
                return makeError("--stroke",
                                 where + ": '" + std::string(number) + "' is not a number");
            // from_chars reads "inf" and "nan"; a float that overflows is just as unpaintable.
            if (!std::isfinite(parsed) || std::abs(parsed) > static_cast<double>(FLT_MAX))
                return makeError("--stroke",
                                 where + ": '" + std::string(number) + "' is not a finite number");
            position[k] = static_cast<float>(parsed);
        }
        out.push_back(position);
    }
    return out;
}

}  // namespace grass::cli
