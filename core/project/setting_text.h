// A setting described in words, from its row of the tables (project/settings.h): the values it
// accepts, its type, its default — shared by docs/project-format.md's tables (setting_docs.cpp)
// and the editor's tooltips (settingTooltip), so both say what the reader accepts.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "project/setting.h"

namespace grass::core::settings {

// "0.15", "100000", "0.00001": fixed notation reads better in a table than "1e-05".
inline std::string numberText(double value) {
    char text[64];
    const auto format = std::abs(value) >= 1e-6 || value == 0.0 ? std::chars_format::fixed
                                                                 : std::chars_format::general;
    const auto printed = std::to_chars(text, text + sizeof text, value, format);
    return std::string(text, printed.ptr);
}

inline std::string ruleText(const json::NumberRule& rule) {
    const bool low = std::isfinite(rule.min), high = std::isfinite(rule.max);
    if (low && high)
        return std::string(rule.minOpen ? "(" : "[") + numberText(rule.min) + ", " +
               numberText(rule.max) + (rule.maxOpen ? ")" : "]");
    if (low)
        return (rule.minOpen ? "> " : ">= ") + numberText(rule.min);
    if (high)
        return (rule.maxOpen ? "< " : "<= ") + numberText(rule.max);
    return "any";
}

// "each in [0, 1]", "each >= 0": a rule for every component.
inline std::string eachText(const json::NumberRule& rule) {
    const bool bounded = std::isfinite(rule.min) && std::isfinite(rule.max);
    return (bounded ? "each in " : "each ") + ruleText(rule);
}

inline std::string withUnit(std::string text, std::string_view unit) {
    if (!unit.empty())
        text += " " + std::string(unit);
    return text;
}

// The value as the doc shows it: compact JSON with a space after each comma.
inline std::string valueText(const json::Json& value) {
    if (value.is_array()) {
        std::string out = "[";
        for (std::size_t i = 0; i < value.size(); ++i)
            out += (i ? ", " : "") + valueText(value[i]);
        return out + "]";
    }
    return value.dump(-1, ' ', false, json::Json::error_handler_t::replace);
}

// The doc's type column of each kind, in Kind's order.
constexpr std::array<std::string_view, 11> TYPE_NAMES{
    "",          "number", "integer", "boolean", "[x, y, z]", "[r, g, b]",
    "[min, max]", "string", "string",  "string",  ""};

template <class S>
std::string typeText(const Setting<S>& row) {
    return std::string(!row.typeText.empty() ? row.typeText
                                             : TYPE_NAMES[static_cast<std::size_t>(row.kind)]);
}
static_assert(static_cast<std::size_t>(Kind::Custom) + 1 == TYPE_NAMES.size(),
              "TYPE_NAMES has one name per Kind");

// What a row accepts, as the doc's "allowed" column says it (before the help text).
template <class S>
std::string allowedText(const Setting<S>& row) {
    if (!row.allowedText.empty())
        return std::string(row.allowedText);
    switch (row.kind) {
        case Kind::Number:
            return withUnit(ruleText(row.rule), row.unit);
        case Kind::Integer:
            if (row.intMin == row.intMax)
                return "0 .. 2⁶⁴−1";
            return withUnit(std::to_string(row.intMin) + " .. " + std::to_string(row.intMax),
                            row.unit);
        case Kind::Flag:
            return "`true` or `false`";
        case Kind::Vector:
        case Kind::Colour:
            return std::isfinite(row.rule.min) || std::isfinite(row.rule.max)
                       ? withUnit(eachText(row.rule), row.unit)
                       : "finite";
        case Kind::Range:
            return withUnit(eachText(row.rule), row.unit) + ", min <= max";
        case Kind::Choice: {
            std::string out;
            for (std::size_t i = 0; i < row.names.size(); ++i)
                out += (i ? ", " : "") + std::string("`\"") + std::string(row.names[i]) + "\"`";
            return out;
        }
        case Kind::Text:
            return row.allowEmpty ? "any" : "not empty";
        case Kind::AssetPath:
            return "`\"\"` or a relative asset path";
        default:
            return "";
    }
}

// The tooltip of a row's widget: what it is, what it accepts (unit and range) and where it is
// saved, on one line.
template <class S>
std::string settingTooltip(const Setting<S>& row) {
    std::string text = row.help.empty() ? std::string(row.key) : std::string(row.help);
    std::string allowed = allowedText(row);
    allowed.erase(std::remove(allowed.begin(), allowed.end(), '`'), allowed.end());
    if (!allowed.empty())
        text += " · allowed: " + allowed;
    text.erase(std::remove(text.begin(), text.end(), '`'), text.end());
    return text + " · project.json \"" + std::string(row.key) + "\"";
}

}  // namespace grass::core::settings
