// The "snow" section of project.json: snow accumulation of SPEC §11 (core/snow/snow_params.h).
#include <array>
#include <cstdint>
#include <string>

#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using settings::field;
using settings::Kind;
using json::NumberRule;

// Snow deeper than 10 m is a glacier, not a grass field; a typo (15 for 0.15) would bury it.
constexpr NumberRule DEPTH_RULE{0.0, 10.0};
// Paper eq. 4: 0 < A ≤ 1 and B > 1; beyond 16 an octave is finer than any map texel.
constexpr NumberRule AMPLITUDE_RULE{0.0, 1.0, true, false};
constexpr NumberRule FREQUENCY_RULE{1.0, 16.0, true, false};
constexpr NumberRule NOISE_SCALE_RULE{0.0, 1000.0, true, false};
// Texels: a wider disc is the boundary falloff's job, and costs nothing extra there.
constexpr NumberRule SAMPLE_RADIUS_RULE{0.0, 64.0};
constexpr NumberRule FALLOFF_RULE{0.0, 100.0};
// Metres per second: 1 m/s buries any field within a second of --time.
constexpr NumberRule RATE_RULE{0.0, 1.0};
constexpr NumberRule LOAD_RULE{0.0, 1000.0};
// Components of the fall direction (normalized on use); the length must not vanish.
constexpr NumberRule DIRECTION_RULE{-1000.0, 1000.0};
constexpr float MIN_DIRECTION_LENGTH = 1e-3f;
// Metres upwind that shelter a point: beyond 100 m a hill a field away would still count.
constexpr NumberRule DRIFT_REACH_RULE{0.0, 100.0, true, false};

// One message for every wrong value (a non-integer, 700, 4096): the three sizes are the choice.
void readMapResolution(json::Reader& reader, json::Object& object, std::string_view key, SnowParams& snow) {
    const json::Json* node = object.find(key);
    if (!node)
        return;
    for (int allowed : SNOW_MAP_RESOLUTIONS) {
        if (node->is_number_integer() && node->get<std::int64_t>() == allowed) {
            snow.mapResolution = allowed;
            return;
        }
    }
    reader.fail(object.pointerTo(key),
                "must be 512, 1024 or 2048 (got " + json::describeValue(*node) + ")");
}

json::Json mapResolutionJson(const SnowParams& snow) { return snow.mapResolution; }

constexpr std::array SNOW{
    field<&SnowParams::enabled>({.key = "enabled", .kind = Kind::Flag, .label = "snow"}),
    field<&SnowParams::amountM>(
        {.key = "amount",
         .rule = DEPTH_RULE,
         .unit = "m",
         .help = "and <= `max_amount`; As, the depth on fully exposed flat ground at Zn = 1; 0 is "
                 "exactly snow-free",
         .ui = {.decimals = 3, .slider = true}}),
    field<&SnowParams::maxAmountM>({.key = "max_amount",
                                    .rule = DEPTH_RULE,
                                    .unit = "m",
                                    .help = "the most snow accumulation can reach"}),
    field<&SnowParams::fallDirection>(
        {.key = "fall_direction",
         .rule = DIRECTION_RULE,
         .help = "not zero; where snow falls to (normalized on use)",
         .ui = {.min = -1.0f, .max = 1.0f}}),
    field<&SnowParams::snowColor>(
        {.key = "color", .kind = Kind::Colour, .rule = json::UNIT_INTERVAL, .help = "Cs",
         .label = "snow colour"}),
    field<&SnowParams::noiseOctaves>(
        {.key = "noise_octaves", .intMin = 1, .intMax = SNOW_MAX_OCTAVES, .label = "octaves"}),
    field<&SnowParams::noiseAmplitude>(
        {.key = "noise_amplitude",
         .rule = AMPLITUDE_RULE,
         .help = "A of Σ Aⁱ noise(Bⁱ x), the sum divided by Σ Aⁱ so it stays in [−1, 1]",
         .label = "noise A",
         .ui = {.min = 0.01f, .max = 1.0f, .slider = true}}),
    field<&SnowParams::noiseFrequency>({.key = "noise_frequency",
                                        .rule = FREQUENCY_RULE,
                                        .help = "B",
                                        .label = "noise B",
                                        .ui = {.min = 1.01f, .max = 16.0f, .slider = true}}),
    field<&SnowParams::noiseScaleM>(
        {.key = "noise_scale",
         .rule = NOISE_SCALE_RULE,
         .unit = "m",
         .help = "the world size of the lowest octave (x = position / scale)",
         .label = "scale",
         .ui = {.min = 0.01f, .max = 1000.0f, .logarithmic = true, .slider = true}}),
    field<&SnowParams::inclineNoise>({.key = "incline_noise",
                                      .rule = json::UNIT_INTERVAL,
                                      .help = "strength of the noise n added to cos φ",
                                      .label = "incline",
                                      .ui = {.slider = true}}),
    settings::custom<SnowParams>({.key = "map_resolution",
                                  .kind = Kind::Integer,
                                  .help = "side of the depth map",
                                  .label = "depth map texels",
                                  .typeText = "integer",
                                  .allowedText = "`512`, `1024` or `2048`"},
                                 readMapResolution, mapResolutionJson),
    field<&SnowParams::samples>(
        {.key = "samples",
         .intMin = 1,
         .intMax = SNOW_MAX_SAMPLES,
         .help = "stochastic samples per point (the paper: 18; 8 is on the measured front, "
                 "[snow.md](snow.md#speed-against-accuracy))"}),
    field<&SnowParams::sampleRadiusTexels>(
        {.key = "sample_radius",
         .rule = SAMPLE_RADIUS_RULE,
         .unit = "texels",
         .help = "radius of the jittered sample disc (0: the single-texel test, a hard edge)",
         .ui = {.speed = 0.05f}}),
    field<&SnowParams::depthBiasM>(
        {.key = "depth_bias",
         .rule = DEPTH_RULE,
         .unit = "m",
         .help = "a sample shelters the point only when nearer the sky by more (a slope term is "
                 "added)",
         .ui = {.decimals = 3, .speed = 0.001f}}),
    field<&SnowParams::boundaryFalloffM>(
        {.key = "boundary_falloff",
         .rule = FALLOFF_RULE,
         .unit = "m",
         .help = "width of the smooth rise of the snow surface at a shelter edge"}),
    field<&SnowParams::accumulationRate>(
        {.key = "accumulation_rate",
         .rule = RATE_RULE,
         .unit = "m/s",
         .help = "with `--time`, As(t) = clamp(As + (accumulation − melt)·t, 0, max_amount)",
         .label = "accumulation",
         .ui = {.decimals = 4, .speed = 0.0005f}}),
    field<&SnowParams::meltRate>({.key = "melt_rate",
                                  .rule = RATE_RULE,
                                  .unit = "m/s",
                                  .label = "melt",
                                  .ui = {.decimals = 4, .speed = 0.0005f}}),
    field<&SnowParams::loadGravity>(
        {.key = "load_gravity",
         .rule = LOAD_RULE,
         .unit = "(m/s²)/m",
         .help = "extra gravity on exposed blades: load_gravity × depth × Fe",
         .ui = {.decimals = 1, .speed = 0.5f}}),
    field<&SnowParams::drift>(
        {.key = "drift",
         .rule = json::UNIT_INTERVAL,
         .help = "how much the wind moves the snow: the depth is scaled by 1 ± drift, more in "
                 "the lee of what stands upwind, less on ground facing the wind ([snow.md]"
                 "(snow.md#drift-with-the-wind)); 0: none",
         .ui = {.slider = true}}),
    field<&SnowParams::driftReachM>(
        {.key = "drift_reach",
         .rule = DRIFT_REACH_RULE,
         .unit = "m",
         .help = "how far upwind a rock or a ridge shelters the ground",
         .label = "drift reach",
         .ui = {.min = 0.1f, .max = 100.0f, .logarithmic = true, .slider = true}}),
    field<&SnowParams::driftFollowsWind>(
        {.key = "drift_follows_wind",
         .kind = Kind::Flag,
         .help = "`true`: the snow drifts the way the project's directional winds blow "
                 "(strength-weighted; none: no drift); `false`: along `drift_direction`",
         .label = "drift follows the wind"}),
    field<&SnowParams::driftDirection>(
        {.key = "drift_direction",
         .rule = DIRECTION_RULE,
         .help = "not zero; where the snow drifts to when `drift_follows_wind` is `false`",
         .ui = {.min = -1.0f, .max = 1.0f}}),
};

}  // namespace

std::span<const settings::Setting<SnowParams>> settings::snow() { return SNOW; }

void json::checkSnow(Reader& reader, const Object& object, const SnowParams& snow) {
    if (snow.amountM > snow.maxAmountM)
        reader.fail(object.pointerTo("amount"),
                    "must not exceed max_amount (" + Json(jsonFloat(snow.maxAmountM)).dump() + ")");
    else if (glm::length(snow.fallDirection) < MIN_DIRECTION_LENGTH)
        reader.fail(object.pointerTo("fall_direction"),
                    "must not be zero: the direction snow falls to, e.g. [0, -1, 0]");
    else if (glm::length(snow.driftDirection) < MIN_DIRECTION_LENGTH)
        reader.fail(object.pointerTo("drift_direction"),
                    "must not be zero: the direction snow drifts to, e.g. [1, 0, 0]");
}

}  // namespace grass::core
