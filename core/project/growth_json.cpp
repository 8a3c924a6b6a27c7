// A layer's "growth" object in project.json: Kim & Cho's growth model (SPEC §9).
#include <array>

#include "growth/growth_stems.h"
#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using json::Json;
using settings::field;
using settings::Kind;

// The curves keep their control values as named members (growth_curves.h); the file as arrays.
// Control values live in [0, 1] (the curves then stay in [0, 1] too).
template <std::size_t N>
struct CurveKey {
    std::string_view key;
    std::string_view what;
    std::array<float GrowthCurves::*, N> members;
};
constexpr CurveKey<3> SOIL{"soil_curve",
                           "[gy0, gy1, gy2]",
                           {&GrowthCurves::gy0, &GrowthCurves::gy1, &GrowthCurves::gy2}};
constexpr CurveKey<5> WIDTH{"width_light_curve",
                            "[wy0, wy1, wy2, wy3, wy4]",
                            {&GrowthCurves::wy0, &GrowthCurves::wy1, &GrowthCurves::wy2,
                             &GrowthCurves::wy3, &GrowthCurves::wy4}};
constexpr CurveKey<5> HEIGHT{"height_light_curve",
                             "[hy0, hy1, hy2, hy3, hy4]",
                             {&GrowthCurves::hy0, &GrowthCurves::hy1, &GrowthCurves::hy2,
                              &GrowthCurves::hy3, &GrowthCurves::hy4}};

template <const auto& Curve>
void readCurve(json::Reader& /*reader*/, json::Object& object, std::string_view /*key*/,
               GrowthDesc& growth) {
    std::array<float, Curve.members.size()> values{};
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = growth.curves.*Curve.members[i];
    object.readFloats(Curve.key, json::UNIT_INTERVAL, Curve.what, values);
    for (std::size_t i = 0; i < values.size(); ++i)
        growth.curves.*Curve.members[i] = values[i];
}

template <const auto& Curve>
Json curveJson(const GrowthDesc& growth) {
    std::array<float, Curve.members.size()> values{};
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = growth.curves.*Curve.members[i];
    return json::jsonFloats(values);
}

template <const auto& Curve>
constexpr settings::Setting<GrowthDesc> curve(std::string_view help) {
    return settings::custom<GrowthDesc>({.key = Curve.key,
                                         .help = help,
                                         .typeText = Curve.what,
                                         .allowedText = "each in [0, 1]"},
                                        readCurve<Curve>, curveJson<Curve>);
}

constexpr std::array GROWTH{
    field<&GrowthDesc::enabled>(
        {.key = "enabled",
         .help = "`true`: soil and light set each blade's height, width, lean and colour",
         .label = "growth model (soil, light)"}),
    curve<SOIL>("f1(g), growth against soil quality"),
    curve<WIDTH>("f2(l), width against light"),
    curve<HEIGHT>("f3(l), height against light"),
    field<&GrowthDesc::levels>(
        {.key = "levels",
         .intMin = 1,
         .intMax = MAX_STEM_LEVELS,
         .help = "levels of each stem the `\"growth\"` technique draws"}),
    field<&GrowthDesc::stemTipWidth>(
        {.key = "stem_tip_width",
         .rule = json::UNIT_INTERVAL,
         .help = "width of the `\"growth\"` technique's stems at their tips, as a share of their "
                 "root width: 0 narrows each to a point, 1 is Kim & Cho's constant-width strip",
         .label = "stem tip width",
         .ui = {.min = 0.0f, .max = 1.0f, .decimals = 2, .speed = 0.01f, .slider = true}}),
    field<&GrowthDesc::poorRootColor>(
        {.key = "poor_root_color",
         .kind = Kind::Colour,
         .rule = json::UNIT_INTERVAL,
         .help = "the root colour in poor conditions (b = 0); `root_color` is the healthy one "
                 "(b = 1)"}),
    field<&GrowthDesc::poorTipColor>(
        {.key = "poor_tip_color",
         .kind = Kind::Colour,
         .rule = json::UNIT_INTERVAL,
         .help = "the tip colour in poor conditions; `tip_color` is the healthy one"}),
};

}  // namespace

std::span<const settings::Setting<GrowthDesc>> settings::growth() { return GROWTH; }

}  // namespace grass::core
