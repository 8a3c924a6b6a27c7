// A "wind" source of project.json (SPEC §4).
#include <array>

#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using json::Json;
using settings::field;

constexpr std::array<std::string_view, 3> WIND_KIND_NAMES{"directional", "point", "vortex"};

constexpr std::array WIND{
    field<&WindDesc::name>({.key = "name", .help = "unique among wind sources"}),
    field<&WindDesc::source, &WindSource::kind>(
        {.key = "kind",
         .names = WIND_KIND_NAMES,
         .allowedText = "`\"directional\"` (a travelling wave), `\"point\"` (blows outwards, a "
                        "helicopter), `\"vortex\"` (around `axis`, a tornado)"}),
    field<&WindDesc::source, &WindSource::position>(
        {.key = "position",
         .help = "centre of the falloff, the point source, the vortex axis (replaced by `path` "
                 "when given)"}),
    field<&WindDesc::source, &WindSource::direction>(
        {.key = "direction", .help = "directional: where the wind blows to; not `[0, 0, 0]`"}),
    field<&WindDesc::source, &WindSource::axis>(
        {.key = "axis",
         .help = "vortex: the axis (counter-clockwise seen from its tip); not `[0, 0, 0]`"}),
    field<&WindDesc::source, &WindSource::strength>(
        {.key = "strength",
         .unit = "m/s",
         .help = "peak displacement rate (negative: a point source sucks in, a vortex turns the "
                 "other way)",
         .ui = {.min = -100.0f, .max = 100.0f}}),
    field<&WindDesc::source, &WindSource::radiusM>(
        {.key = "radius",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "falloff (1 − (r/R)²)² to 0 at R; 0 = reaches everywhere",
         .ui = {.max = 1e4f, .speed = 0.05f}}),
    field<&WindDesc::source, &WindSource::coreRadiusM>(
        {.key = "core_radius",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "point and vortex rise linearly inside it (no singularity at the centre)",
         .ui = {.max = 1e3f, .speed = 0.02f}}),
    field<&WindDesc::source, &WindSource::wavelengthM>(
        {.key = "wavelength",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "directional wave length (0: constant wind)",
         .ui = {.max = 1e3f, .speed = 0.05f}}),
    field<&WindDesc::source, &WindSource::speedMps>(
        {.key = "speed",
         .unit = "m/s",
         .help = "the directional wave travels",
         .ui = {.min = -100.0f, .max = 100.0f, .speed = 0.02f}}),
    field<&WindDesc::source, &WindSource::gust>(
        {.key = "gust",
         .rule = json::UNIT_INTERVAL,
         .help = "share of the directional strength modulated by smooth noise",
         .ui = {.slider = true}}),
    json::pathSetting<&WindDesc::source, &WindSource::path>(
        {.key = "path",
         .allowedText = "keys `{\"time\": s, \"position\": [x, y, z]}` in time order; piecewise "
                        "linear, held at both ends"}),
};

}  // namespace

std::span<const settings::Setting<WindDesc>> settings::wind() { return WIND; }

// A zero vector has no direction: the source would silently blow nowhere.
void json::checkWind(Reader& reader, const Object& object, const WindDesc& wind) {
    const WindSource& source = wind.source;
    if (source.kind == WindKind::Directional && source.direction == glm::vec3(0.0f))
        reader.fail(object.pointerTo("direction"),
                    "must not be [0, 0, 0] (it is where the wind blows to)");
    else if (source.kind == WindKind::Vortex && source.axis == glm::vec3(0.0f))
        reader.fail(object.pointerTo("axis"), "must not be [0, 0, 0] (it is the vortex axis)");
}

}  // namespace grass::core
