// A "layers" entry of project.json: scattering, maps, blade ranges, shape and colours of one
// grass layer (its "growth" object is growth_json.cpp's).
#include <array>
#include <cstdio>

#include "project/project_json_parts.h"
#include "util/byte_size.h"

namespace grass::core {

namespace {

using json::Json;
using json::NumberRule;
using settings::field;
using settings::Kind;

// Blades per clump: beyond this a clump is a carpet, and a typo (12000 for 12) would stall.
constexpr int MAX_BLADES_PER_CLUMP = 10000;
// project.h says why blades are bounded.
constexpr NumberRule BLADE_HEIGHT_RULE{0.0, MAX_BLADE_HEIGHT_M, true, false};
constexpr NumberRule BLADE_WIDTH_RULE{0.0, MAX_BLADE_WIDTH_M, true, false};
// τ = 1 would divide by zero in the triangle-tip shape (1 − τ).
constexpr NumberRule TIP_START_RULE{0.0, 1.0, false, true};

constexpr std::array BLADE{
    settings::rangeOf<&BladeRanges::heightMin, &BladeRanges::heightMax>(
        {.key = "height",
         .rule = BLADE_HEIGHT_RULE,
         .unit = "m",
         .ui = {.min = 0.01f, .max = 5.0f, .decimals = 3, .speed = 0.005f}}),
    settings::rangeOf<&BladeRanges::widthMin, &BladeRanges::widthMax>(
        {.key = "width",
         .rule = BLADE_WIDTH_RULE,
         .unit = "m",
         .help = "the root is 2 × width across",
         .ui = {.min = 0.001f, .max = 0.2f, .decimals = 4, .speed = 0.0005f}}),
    settings::rangeOf<&BladeRanges::stiffnessMin, &BladeRanges::stiffnessMax>(
        {.key = "stiffness",
         .rule = json::NON_NEGATIVE,
         .unit = "1/s",
         .help = "recovery rate s: a steady force F bends the tip by about F/s metres, so gravity "
                 "9.81 droops a 0.45 m blade by ~20 % at s = 60",
         .ui = {.min = 1.0f, .max = 1000.0f, .decimals = 1, .speed = 0.5f}}),
};

std::string texelsText(double width, double height) {
    char text[64];
    std::snprintf(text, sizeof text, "%.0f×%.0f", width, height);
    return text;
}

std::string floatMapBytes(double width, double height) {
    return byteSizeText(width * height * static_cast<double>(sizeof(float)));
}

// [width, height] of a layer's maps; a side beyond the limit is refused with the memory the map
// would take (float texels), since each map of the layer is allocated at this size.
void readMapResolution(json::Reader& reader, json::Object& object, std::string_view key,
                       GrassLayer& layer) {
    const Json* size = object.find(key);
    if (!size)
        return;
    const std::string at = object.pointerTo(key);
    if (!size->is_array() || size->size() != 2) {
        reader.fail(at, "must be an array of 2 integers [width, height] (got " +
                            json::describeValue(*size) + ")");
        return;
    }
    const auto side = [&](std::size_t i) {
        const Json& value = (*size)[i];
        return value.is_number_integer() ? value.get<double>() : 0.0;
    };
    for (std::size_t i = 0; i < 2; ++i) {
        if (side(i) <= MAX_MAP_RESOLUTION)
            continue;
        const double width = side(0) > 0.0 ? side(0) : side(1);
        const double height = side(1) > 0.0 ? side(1) : side(0);
        const auto limit = static_cast<double>(MAX_MAP_RESOLUTION);
        reader.fail(json::childPointer(at, i),
                    "must be an integer in 1.." + std::to_string(MAX_MAP_RESOLUTION) + " (got " +
                        json::describeValue((*size)[i]) + ": a " + texelsText(width, height) +
                        " map would take " + floatMapBytes(width, height) +
                        " of float texels; the limit, " + texelsText(limit, limit) + ", takes " +
                        floatMapBytes(limit, limit) + ")");
        return;
    }
    std::int64_t width = 0, height = 0;
    if (reader.readInt((*size)[0], json::childPointer(at, 0), 1, MAX_MAP_RESOLUTION, width) &&
        reader.readInt((*size)[1], json::childPointer(at, 1), 1, MAX_MAP_RESOLUTION, height))
        layer.mapResolution = {static_cast<int>(width), static_cast<int>(height)};
}

Json mapResolutionJson(const GrassLayer& layer) {
    return Json::array({layer.mapResolution.x, layer.mapResolution.y});
}

template <auto Member>
constexpr settings::Setting<GrassLayer> mapPath(std::string_view key, std::string_view help) {
    return field<Member>({.key = key,
                          .kind = Kind::AssetPath,
                          .allowEmpty = true,
                          .help = help});
}

constexpr std::array LAYER{
    field<&GrassLayer::name>({.key = "name", .help = "unique among layers"}),
    field<&GrassLayer::scatter, &ScatterParams::density>(
        {.key = "density",
         .rule = json::NON_NEGATIVE,
         .unit = "/m²",
         .help = "uniform blades per square metre (0: clumps only)",
         .ui = {.min = 1.0f, .max = 5000.0f, .decimals = 0, .logarithmic = true, .slider = true}}),
    mapPath<&GrassLayer::densityMap>(
        "density_map",
        "empty: 1 everywhere; an image (see [maps](#maps)) that thins the layer: a blade "
        "survives with probability map(uv)"),
    mapPath<&GrassLayer::soilMap>("soil_map",
                                  "empty: 1 everywhere (good soil); soil quality g in [0, 1], "
                                  "read by the growth model only when `growth.enabled`"),
    mapPath<&GrassLayer::lightMap>("light_map",
                                   "empty: 1 everywhere (full light); light amount l in [0, 1], "
                                   "read by the growth model only when `growth.enabled`"),
    mapPath<&GrassLayer::cutMap>("cut_map",
                                 "empty: 1 everywhere (uncut); the height blades are cut to, as "
                                 "a share of their own (0: mown to the ground)"),
    field<&GrassLayer::regrowRate>(
        {.key = "regrow_rate",
         .rule = json::NON_NEGATIVE,
         .unit = "1/s",
         .help = "share of their height cut blades grow back each second of scene time (0: they "
                 "stay cut)",
         .ui = {.max = 1.0f, .decimals = 3}}),
    settings::custom<GrassLayer>(
        {.key = "map_resolution",
         .help = "the size every map of the layer is resampled to when loaded and created at "
                 "when painted",
         .typeText = "[width, height]",
         .allowedText = "integers, each 1 .. 8192 texels"},
        readMapResolution, mapResolutionJson),
    field<&GrassLayer::scatter, &ScatterParams::clumpSpacing>(
        {.key = "clump_spacing",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "Poisson-disk minimum distance between clump centres (0: no clumps)"}),
    field<&GrassLayer::scatter, &ScatterParams::bladesPerClump>(
        {.key = "blades_per_clump", .intMin = 0, .intMax = MAX_BLADES_PER_CLUMP}),
    field<&GrassLayer::scatter, &ScatterParams::clumpRadius>(
        {.key = "clump_radius", .rule = json::NON_NEGATIVE, .unit = "m"}),
    settings::object<settings::blade, nullptr, &GrassLayer::scatter, &ScatterParams::blade>(
        {.key = "blade", .allowedText = "see below", .defaultText = "defaults"}),
    field<&GrassLayer::shape>({.key = "shape",
                               .names = BLADE_SHAPE_NAMES,
                               .help = "the outline of every blade of the layer (SPEC §7)"}),
    field<&GrassLayer::tipStart>(
        {.key = "tip_start",
         .rule = TIP_START_RULE,
         .help = "τ, where a `\"triangle-tip\"` blade starts to narrow (0 root, 1 tip); other "
                 "shapes ignore it"}),
    field<&GrassLayer::rootColor>(
        {.key = "root_color", .kind = Kind::Colour, .rule = json::UNIT_INTERVAL,
         .label = "root colour"}),
    field<&GrassLayer::tipColor>(
        {.key = "tip_color", .kind = Kind::Colour, .rule = json::UNIT_INTERVAL,
         .label = "tip colour"}),
    settings::object<settings::growth, nullptr, &GrassLayer::growth>(
        {.key = "growth", .allowedText = "see [growth](#growth)", .defaultText = "defaults (off)"}),
    settings::object<settings::rules, nullptr, &GrassLayer::rules>(
        {.key = "rules",
         .allowedText = "see [rules](#rules)",
         .defaultText = "defaults (everywhere)"}),
    settings::object<settings::bending, nullptr, &GrassLayer::bending>(
        {.key = "bending",
         .allowedText = "see [bending](#bending)",
         .defaultText = "defaults (off)"}),
};

}  // namespace

std::span<const settings::Setting<BladeRanges>> settings::blade() { return BLADE; }
std::span<const settings::Setting<GrassLayer>> settings::layer() { return LAYER; }

}  // namespace grass::core
