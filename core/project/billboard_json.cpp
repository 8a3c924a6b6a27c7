// The "billboards" part of project.json (SPEC §8) and the technique / animation names. Keys are
// spelled here only; docs/project-format.md lists them in the order they are written.
#include "project/project_json_parts.h"

namespace grass::core {

namespace {

constexpr std::array<std::string_view, 10> BILLBOARD_KEYS{
    "density",        "height",         "width_to_height", "cluster_size", "texture",
    "animation",      "wind_direction", "wind_amplitude",  "wind_frequency", "cross_fade"};
constexpr std::string_view XYZ = "[x, y, z]";
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

namespace json {

void readBillboards(Reader& reader, const Json& node, BillboardDesc& billboards) {
    Object object(reader, node, "/billboards", BILLBOARD_KEYS);
    StarBillboardParams& placement = billboards.placement;
    object.readFloat("density", DENSITY_RULE, placement.density);
    object.readRange("height", SIZE_RULE, placement.heightRangeM.x, placement.heightRangeM.y);
    object.readFloat("width_to_height", NumberRule{0.0, 100.0, true, false},
                     placement.widthToHeight);
    object.readFloat("cluster_size", SIZE_RULE, placement.clusterSizeM);
    object.readString("texture", true, billboards.texture);
    if (!billboards.texture.empty())
        checkAssetPath(reader, "/billboards/texture", billboards.texture);
    if (const Json* animation = object.find("animation")) {
        std::size_t index = 0;
        if (reader.readEnum(*animation, "/billboards/animation", ANIMATION_NAMES, index))
            billboards.animation = static_cast<BillboardWindMode>(index);
    }
    glm::vec3 direction(billboards.wind.directionXZ.x, 0.0f, billboards.wind.directionXZ.y);
    object.readVec3("wind_direction", ANY_NUMBER, XYZ, direction);
    if (reader.ok() && direction.x == 0.0f && direction.z == 0.0f)
        reader.fail("/billboards/wind_direction",
                    "needs a horizontal part (x or z not 0): billboards sway horizontally");
    billboards.wind.directionXZ = {direction.x, direction.z};
    object.readFloat("wind_amplitude", NumberRule{0.0, 100.0}, billboards.wind.amplitudeM);
    object.readFloat("wind_frequency", NumberRule{0.0, 100.0}, billboards.wind.frequencyHz);
    object.readRange("cross_fade", NON_NEGATIVE, billboards.crossFadeM.x,
                     billboards.crossFadeM.y);
}

Json billboardsJson(const BillboardDesc& billboards) {
    const StarBillboardParams& placement = billboards.placement;
    Json out = Json::object();
    out["density"] = jsonFloat(placement.density);
    out["height"] = jsonRange(placement.heightRangeM.x, placement.heightRangeM.y);
    out["width_to_height"] = jsonFloat(placement.widthToHeight);
    out["cluster_size"] = jsonFloat(placement.clusterSizeM);
    out["texture"] = billboards.texture;
    out["animation"] = std::string(billboardAnimationName(billboards.animation));
    out["wind_direction"] = jsonVec3(
        glm::vec3(billboards.wind.directionXZ.x, 0.0f, billboards.wind.directionXZ.y));
    out["wind_amplitude"] = jsonFloat(billboards.wind.amplitudeM);
    out["wind_frequency"] = jsonFloat(billboards.wind.frequencyHz);
    out["cross_fade"] = jsonRange(billboards.crossFadeM.x, billboards.crossFadeM.y);
    return out;
}

}  // namespace json
}  // namespace grass::core
