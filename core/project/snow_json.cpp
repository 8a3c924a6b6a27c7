// The "snow" part of project.json: snow accumulation of SPEC §11 (core/snow/snow_params.h). Keys
// are spelled here only; docs/project-format.md lists them in the order they are written.
#include <array>
#include <cstdint>
#include <string>

#include "project/project_json_parts.h"

namespace grass::core::json {

namespace {

constexpr std::array<std::string_view, 18> SNOW_KEYS{
    "enabled",           "amount",          "max_amount",      "fall_direction", "color",
    "noise_octaves",     "noise_amplitude", "noise_frequency", "noise_scale",    "incline_noise",
    "map_resolution",    "samples",         "sample_radius",   "depth_bias",     "boundary_falloff",
    "accumulation_rate", "melt_rate",       "load_gravity"};
constexpr std::string_view XYZ = "[x, y, z]";
constexpr std::string_view RGB = "[r, g, b]";
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
constexpr std::array<int, 3> MAP_RESOLUTIONS{512, 1024, 2048};

// One message for every wrong value (a non-integer, 700, 4096): the three sizes are the choice.
void readMapResolution(Reader& reader, const Object& object, int& resolution) {
    const Json* node = object.find("map_resolution");
    if (!node || !reader.ok())
        return;
    for (int allowed : MAP_RESOLUTIONS) {
        if (node->is_number_integer() && node->get<std::int64_t>() == allowed) {
            resolution = allowed;
            return;
        }
    }
    reader.fail(object.pointerTo("map_resolution"),
                "must be 512, 1024 or 2048 (got " + describeValue(*node) + ")");
}

}  // namespace

void readSnow(Reader& reader, const Json& node, SnowParams& snow) {
    Object object(reader, node, "/snow", SNOW_KEYS);
    bool enabled = snow.enabled != 0u;
    object.readBool("enabled", enabled);
    snow.enabled = enabled ? 1u : 0u;
    float amount = snow.amountM;
    object.readFloat("amount", DEPTH_RULE, amount);
    object.readFloat("max_amount", DEPTH_RULE, snow.maxAmountM);
    if (reader.ok() && amount > snow.maxAmountM)
        reader.fail(object.pointerTo("amount"),
                    "must not exceed max_amount (" + Json(jsonFloat(snow.maxAmountM)).dump() + ")");
    if (reader.ok())
        snow.amountM = amount;
    glm::vec3 direction = snow.fallDirection;
    object.readVec3("fall_direction", DIRECTION_RULE, XYZ, direction);
    if (reader.ok() && glm::length(direction) < MIN_DIRECTION_LENGTH)
        reader.fail(object.pointerTo("fall_direction"),
                    "must not be zero: the direction snow falls to, e.g. [0, -1, 0]");
    if (reader.ok())
        snow.fallDirection = direction;
    object.readVec3("color", UNIT_INTERVAL, RGB, snow.snowColor);
    object.readInt("noise_octaves", 1, SNOW_MAX_OCTAVES, snow.noiseOctaves);
    object.readFloat("noise_amplitude", AMPLITUDE_RULE, snow.noiseAmplitude);
    object.readFloat("noise_frequency", FREQUENCY_RULE, snow.noiseFrequency);
    object.readFloat("noise_scale", NOISE_SCALE_RULE, snow.noiseScaleM);
    object.readFloat("incline_noise", UNIT_INTERVAL, snow.inclineNoise);
    readMapResolution(reader, object, snow.mapResolution);
    object.readInt("samples", 1, SNOW_MAX_SAMPLES, snow.samples);
    object.readFloat("sample_radius", SAMPLE_RADIUS_RULE, snow.sampleRadiusTexels);
    object.readFloat("depth_bias", DEPTH_RULE, snow.depthBiasM);
    object.readFloat("boundary_falloff", FALLOFF_RULE, snow.boundaryFalloffM);
    object.readFloat("accumulation_rate", RATE_RULE, snow.accumulationRate);
    object.readFloat("melt_rate", RATE_RULE, snow.meltRate);
    object.readFloat("load_gravity", LOAD_RULE, snow.loadGravity);
}

Json snowJson(const SnowParams& snow) {
    Json out = Json::object();
    out["enabled"] = snow.enabled != 0u;
    out["amount"] = jsonFloat(snow.amountM);
    out["max_amount"] = jsonFloat(snow.maxAmountM);
    out["fall_direction"] = jsonVec3(snow.fallDirection);
    out["color"] = jsonVec3(snow.snowColor);
    out["noise_octaves"] = snow.noiseOctaves;
    out["noise_amplitude"] = jsonFloat(snow.noiseAmplitude);
    out["noise_frequency"] = jsonFloat(snow.noiseFrequency);
    out["noise_scale"] = jsonFloat(snow.noiseScaleM);
    out["incline_noise"] = jsonFloat(snow.inclineNoise);
    out["map_resolution"] = snow.mapResolution;
    out["samples"] = snow.samples;
    out["sample_radius"] = jsonFloat(snow.sampleRadiusTexels);
    out["depth_bias"] = jsonFloat(snow.depthBiasM);
    out["boundary_falloff"] = jsonFloat(snow.boundaryFalloffM);
    out["accumulation_rate"] = jsonFloat(snow.accumulationRate);
    out["melt_rate"] = jsonFloat(snow.meltRate);
    out["load_gravity"] = jsonFloat(snow.loadGravity);
    return out;
}

}  // namespace grass::core::json
