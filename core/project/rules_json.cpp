// A layer's "rules" object in project.json: where the layer may grow besides its painted maps
// (PlacementRules, issue 27): names of glTF nodes, meshes or materials to include or exclude,
// slope and altitude windows, and a clearance around colliders and chosen parts.
#include <array>

#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using json::Json;
using settings::field;

// Names a rule may list: a glTF file names thousands of nodes at most, and a longer list is a
// pasted mistake.
constexpr std::size_t MAX_RULE_NAMES = 4096;
constexpr json::NumberRule DEGREES{0.0, 180.0};
// Altitudes beyond a million metres are no terrain; the window's defaults sit at that bound.
constexpr json::NumberRule ALTITUDE{-1.0e6, 1.0e6};
constexpr json::NumberRule SOFT_DEGREES{0.0, 90.0};

using NameList = std::vector<std::string> PlacementRules::*;

template <NameList Names>
void readNames(json::Reader& reader, json::Object& object, std::string_view key,
               PlacementRules& rules) {
    const Json* node = object.find(key);
    if (!node)
        return;
    const std::string at = object.pointerTo(key);
    if (!node->is_array()) {
        reader.fail(at, "must be an array of names (got " + json::describeValue(*node) + ")");
        return;
    }
    if (node->size() > MAX_RULE_NAMES) {
        reader.fail(at, "holds " + std::to_string(node->size()) + " names; at most " +
                            std::to_string(MAX_RULE_NAMES) + " are read");
        return;
    }
    std::vector<std::string> names(node->size());
    for (std::size_t i = 0; i < names.size(); ++i)
        if (!reader.readString((*node)[i], json::childPointer(at, i), false, names[i]))
            return;
    rules.*Names = std::move(names);
}

template <NameList Names>
Json namesJson(const PlacementRules& rules) {
    return Json(rules.*Names);
}

template <NameList Names>
constexpr settings::Setting<PlacementRules> names(std::string_view key, std::string_view help) {
    return settings::custom<PlacementRules>(
        {.key = key, .help = help, .typeText = "array of strings", .allowedText = "names"},
        readNames<Names>, namesJson<Names>);
}

constexpr std::array RULES{
    names<&PlacementRules::include>(
        "include",
        "glTF node (or a node above it), mesh or material names the layer grows on; empty: "
        "the whole surface"),
    names<&PlacementRules::exclude>("exclude",
                                    "names the layer never grows on; wins over `include`"),
    settings::rangeOf<&PlacementRules::slopeMinDeg, &PlacementRules::slopeMaxDeg>(
        {.key = "slope",
         .rule = DEGREES,
         .unit = "°",
         .help = "the surface's angle from level ground, against gravity (0 flat, 90 a wall, "
                 "180 a ceiling) where the layer grows",
         .ui = {.min = 0.0f, .max = 180.0f, .decimals = 1, .speed = 0.5f}}),
    field<&PlacementRules::slopeSoftDeg>(
        {.key = "slope_soft",
         .rule = SOFT_DEGREES,
         .unit = "°",
         .help = "outside the slope window grass thins to none over this many degrees (0: a hard "
                 "edge)",
         .ui = {.min = 0.0f, .max = 45.0f, .decimals = 1, .speed = 0.2f}}),
    settings::rangeOf<&PlacementRules::altitudeMinM, &PlacementRules::altitudeMaxM>(
        {.key = "altitude",
         .rule = ALTITUDE,
         .unit = "m",
         .help = "height along up (with centre gravity: distance from the centre) where the "
                 "layer grows",
         .ui = {.min = -1.0e4f, .max = 1.0e4f, .decimals = 2, .speed = 0.05f}}),
    field<&PlacementRules::altitudeSoftM>(
        {.key = "altitude_soft",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "outside the altitude window grass thins to none over this distance",
         .ui = {.min = 0.0f, .max = 100.0f, .decimals = 2, .speed = 0.02f}}),
    field<&PlacementRules::clearanceM>(
        {.key = "clearance",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "no grass this close to the colliders (with `clear_colliders`) and to the parts "
                 "named in `clear_of`",
         .ui = {.min = 0.0f, .max = 50.0f, .decimals = 2, .speed = 0.02f}}),
    field<&PlacementRules::clearColliders>(
        {.key = "clear_colliders",
         .help = "keep `clearance` from every collider where it stands at time 0, and no "
                 "grass under one (inside it, or under a rock open at the bottom)"}),
    names<&PlacementRules::clearOf>("clear_of",
                                    "node, mesh or material names whose surfaces keep "
                                    "`clearance` of bare ground around them"),
};

}  // namespace

std::span<const settings::Setting<PlacementRules>> settings::rules() { return RULES; }

}  // namespace grass::core
