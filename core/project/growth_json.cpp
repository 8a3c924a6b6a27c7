// The "growth" object of a layer in project.json: Kim & Cho's growth model (SPEC §9). Keys are
// spelled here only; docs/project-format.md lists them in the order they are written.
#include <array>

#include "growth/growth_stems.h"
#include "project/project_json_parts.h"

namespace grass::core::json {

namespace {

constexpr std::array<std::string_view, 7> GROWTH_KEYS{
    "enabled",         "soil_curve",      "width_light_curve", "height_light_curve",
    "levels",          "poor_root_color", "poor_tip_color"};
constexpr std::string_view RGB = "[r, g, b]";

}  // namespace

void readGrowth(Reader& reader, const Json& node, const std::string& pointer, GrowthDesc& growth) {
    Object object(reader, node, pointer, GROWTH_KEYS);
    object.readBool("enabled", growth.enabled);
    GrowthCurves& c = growth.curves;
    // Control values live in [0, 1] (growth_curves.h: the curves then stay in [0, 1] too).
    std::array<float, 3> soil{c.gy0, c.gy1, c.gy2};
    std::array<float, 5> width{c.wy0, c.wy1, c.wy2, c.wy3, c.wy4};
    std::array<float, 5> height{c.hy0, c.hy1, c.hy2, c.hy3, c.hy4};
    object.readFloats("soil_curve", UNIT_INTERVAL, "[gy0, gy1, gy2]", soil);
    object.readFloats("width_light_curve", UNIT_INTERVAL, "[wy0, wy1, wy2, wy3, wy4]", width);
    object.readFloats("height_light_curve", UNIT_INTERVAL, "[hy0, hy1, hy2, hy3, hy4]", height);
    c = GrowthCurves{soil[0],  soil[1],  soil[2],   width[0],  width[1],
                     width[2], width[3], width[4],  height[0], height[1],
                     height[2], height[3], height[4]};
    object.readInt("levels", 1, MAX_STEM_LEVELS, growth.levels);
    object.readVec3("poor_root_color", UNIT_INTERVAL, RGB, growth.poorRootColor);
    object.readVec3("poor_tip_color", UNIT_INTERVAL, RGB, growth.poorTipColor);
}

Json growthJson(const GrowthDesc& growth) {
    const GrowthCurves& c = growth.curves;
    Json out = Json::object();
    out["enabled"] = growth.enabled;
    out["soil_curve"] = jsonFloats(std::array<float, 3>{c.gy0, c.gy1, c.gy2});
    out["width_light_curve"] = jsonFloats(std::array<float, 5>{c.wy0, c.wy1, c.wy2, c.wy3, c.wy4});
    out["height_light_curve"] =
        jsonFloats(std::array<float, 5>{c.hy0, c.hy1, c.hy2, c.hy3, c.hy4});
    out["levels"] = growth.levels;
    out["poor_root_color"] = jsonVec3(growth.poorRootColor);
    out["poor_tip_color"] = jsonVec3(growth.poorTipColor);
    return out;
}

}  // namespace grass::core::json
