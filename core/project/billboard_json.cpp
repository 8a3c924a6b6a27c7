// The "billboards" section of project.json (SPEC §8) and the technique / animation names.
#include "project/project_json_parts.h"

namespace grass::core {

namespace {

// Beyond 1000 objects per m² (a few mm apart) a typo would stall the scene build.
constexpr json::NumberRule DENSITY_RULE{0.0, 1000.0};
constexpr json::NumberRule SIZE_RULE{0.0, 1000.0, true, false};

template <class Enum, std::size_t N>
Result<Enum> parseName(std::string_view name, const std::array<std::string_view, N>& names,
                       std::string_view what) {
    for (std::size_t i = 0; i < N; ++i)
        if (names[i] == name)
            return static_cast<Enum>(i);
    return makeError("", "unknown " + std::string(what) + " " + json::quote(name) + " (valid: " +
                             json::quotedList(names) + ")");
}

}  // namespace

std::string_view grassTechniqueName(GrassTechnique technique) {
    return json::TECHNIQUE_NAMES[static_cast<std::size_t>(technique)];
}

Result<GrassTechnique> parseGrassTechnique(std::string_view name) {
    return parseName<GrassTechnique>(name, json::TECHNIQUE_NAMES, "technique");
}

std::string_view billboardAnimationName(BillboardWindMode mode) {
    return json::ANIMATION_NAMES[static_cast<std::size_t>(mode)];
}

Result<BillboardWindMode> parseBillboardAnimation(std::string_view name) {
    return parseName<BillboardWindMode>(name, json::ANIMATION_NAMES, "billboard animation");
}

namespace {

using json::Json;
using json::NumberRule;
using settings::field;

// The file keeps the sway direction as [x, y, z] (y ignored); the scene as an x-z vector.
void readWindDirection(json::Reader& reader, json::Object& object, std::string_view key, BillboardDesc& billboards) {
    glm::vec3 direction(billboards.wind.directionXZ.x, 0.0f, billboards.wind.directionXZ.y);
    object.readVec3(key, json::ANY_NUMBER, "[x, y, z]", direction);
    if (reader.ok() && direction.x == 0.0f && direction.z == 0.0f)
        reader.fail(object.pointerTo(key),
                    "needs a horizontal part (x or z not 0): billboards sway horizontally");
    billboards.wind.directionXZ = {direction.x, direction.z};
}

Json windDirectionJson(const BillboardDesc& billboards) {
    return json::jsonVec3(
        glm::vec3(billboards.wind.directionXZ.x, 0.0f, billboards.wind.directionXZ.y));
}

constexpr std::array BILLBOARDS{
    field<&BillboardDesc::placement, &StarBillboardParams::density>(
        {.key = "density", .rule = DENSITY_RULE, .unit = "/m²", .help = "objects per m²"}),
    field<&BillboardDesc::placement, &StarBillboardParams::heightRangeM>(
        {.key = "height", .rule = SIZE_RULE, .unit = "m"}),
    field<&BillboardDesc::placement, &StarBillboardParams::widthToHeight>(
        {.key = "width_to_height",
         .rule = NumberRule{0.0, 100.0, true, false},
         .help = "quad width / height"}),
    field<&BillboardDesc::placement, &StarBillboardParams::clusterSizeM>(
        {.key = "cluster_size",
         .rule = SIZE_RULE,
         .unit = "m",
         .help = "edge of the grid cells that group objects (the per-cluster animation draws one "
                 "cluster at a time)"}),
    field<&BillboardDesc::texture>(
        {.key = "texture",
         .kind = settings::Kind::AssetPath,
         .allowEmpty = true,
         .help = "an image with an alpha channel (PNG, TIFF, …); empty: generated from the first "
                 "layer's colours"}),
    field<&BillboardDesc::animation>(
        {.key = "animation",
         .names = json::ANIMATION_NAMES,
         .allowedText = "`\"per-cluster\"` (CPU offset per cluster, one draw each), "
                        "`\"per-vertex\"` (by vertex position, one draw) or `\"per-object\"` (by "
                        "object centre, one draw)"}),
    settings::custom<BillboardDesc>(
        {.key = "wind_direction",
         .typeText = "[x, y, z]",
         .allowedText = "the way the billboards sway; needs x or z not 0 (y is ignored)"},
        readWindDirection, windDirectionJson),
    field<&BillboardDesc::wind, &BillboardWind::amplitudeM>(
        {.key = "wind_amplitude",
         .rule = NumberRule{0.0, 100.0},
         .unit = "m",
         .help = "largest sway of the upper vertices"}),
    field<&BillboardDesc::wind, &BillboardWind::frequencyHz>(
        {.key = "wind_frequency", .rule = NumberRule{0.0, 100.0}, .unit = "Hz"}),
    field<&BillboardDesc::crossFadeM>(
        {.key = "cross_fade",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "in the hybrid, blades fade out and billboards fade in between these camera "
                 "distances; blades beyond `far` are culled",
         .typeText = "[near, far]"}),
};

}  // namespace

std::span<const settings::Setting<BillboardDesc>> settings::billboards() { return BILLBOARDS; }

}  // namespace grass::core
