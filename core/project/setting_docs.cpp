#include "project/setting_docs.h"

#include <array>
#include <charconv>
#include <cmath>

#include "project/setting_io.h"
#include "project/settings.h"

namespace grass::core::settings {

namespace {

// "0.15", "100000", "0.00001": fixed notation reads better in a table than "1e-05".
std::string numberText(double value) {
    char text[64];
    const auto format = std::abs(value) >= 1e-6 || value == 0.0 ? std::chars_format::fixed
                                                                 : std::chars_format::general;
    const auto printed = std::to_chars(text, text + sizeof text, value, format);
    return std::string(text, printed.ptr);
}

std::string ruleText(const json::NumberRule& rule) {
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
std::string eachText(const json::NumberRule& rule) {
    const bool bounded = std::isfinite(rule.min) && std::isfinite(rule.max);
    return (bounded ? "each in " : "each ") + ruleText(rule);
}

std::string withUnit(std::string text, std::string_view unit) {
    if (!unit.empty())
        text += " " + std::string(unit);
    return text;
}

// The value as the doc shows it: compact JSON with a space after each comma.
std::string valueText(const json::Json& value) {
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

template <class S>
std::string ruleColumn(const Setting<S>& row) {
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

template <class S>
std::string markdownTable(std::span<const Setting<S>> table, const S& defaults) {
    std::string out = "| key | type | default | allowed |\n|---|---|---|---|\n";
    for (const Setting<S>& row : table) {
        std::string allowed = ruleColumn(row);
        if (!row.help.empty())
            allowed += (allowed.empty() ? "" : "; ") + std::string(row.help);
        // The default of a setting only some objects have (a mesh collider's scale) is the
        // value it takes where it applies.
        Setting<S> always = row;
        always.applies = nullptr;
        const json::Json value = settingJson(always, defaults);
        const std::string defaultText = !row.defaultText.empty() ? std::string(row.defaultText)
                                        : value.is_null()        ? "absent"
                                                                 : "`" + valueText(value) + "`";
        out += "| `" + std::string(row.key) + "` | " + typeText(row) + " | " + defaultText +
               " | " + allowed + " |\n";
    }
    return out;
}

}  // namespace

std::vector<DocTable> projectFormatTables() {
    return {
        {"the document", markdownTable(project(), Project{})},
        {"mesh", markdownTable(mesh(), MeshSource{})},
        {"layers", markdownTable(layer(), GrassLayer{})},
        {"layers/blade", markdownTable(blade(), BladeRanges{})},
        {"layers/growth", markdownTable(growth(), GrowthDesc{})},
        {"cameras", markdownTable(camera(), CameraDesc{})},
        {"sun", markdownTable(sun(), SunDesc{})},
        {"lighting", markdownTable(lighting(), GrassLightingDesc{})},
        {"render", markdownTable(render(), RenderSettings{})},
        {"billboards", markdownTable(billboards(), BillboardDesc{})},
        {"physics", markdownTable(physics(), PhysicsParams{})},
        {"wind", markdownTable(wind(), WindDesc{})},
        {"colliders", markdownTable(collider(), ColliderDesc{})},
        {"snow", markdownTable(snow(), SnowParams{})},
    };
}

}  // namespace grass::core::settings
