// The "lighting" part of project.json: the grass lighting of SPEC §10. Keys are spelled here
// only; docs/project-format.md lists them in the order they are written.
#include <array>

#include "project/project_json_parts.h"
#include "scene/blade_shading.h"

namespace grass::core::json {

namespace {

constexpr std::array<std::string_view, 18> LIGHTING_KEYS{"model",
                                                         "diffuse_low",
                                                         "diffuse_mid",
                                                         "diffuse_high",
                                                         "terrain_normal_weight",
                                                         "specular",
                                                         "specular_fade",
                                                         "transmission",
                                                         "transmission_distortion",
                                                         "transmission_power",
                                                         "sss",
                                                         "sss_intensity",
                                                         "ao_radius",
                                                         "ao_strength",
                                                         "ao_floor",
                                                         "normal_blur_radius",
                                                         "ao_cell",
                                                         "water"};
constexpr std::array<std::string_view, 2> MODEL_NAMES{"grass", "simple"};
constexpr std::string_view RGB = "[r, g, b]";
// Colours multiply the sun: above 4 a typo would wash the frame out.
constexpr NumberRule COLOR_RULE{0.0, 4.0};
constexpr NumberRule WEIGHT_RULE{0.0, 10.0};
// Kernel radii (0 turns the term off): beyond 100 m the bake would visit the whole field for
// every blade.
constexpr NumberRule RADIUS_RULE{0.0, 100.0};

}  // namespace

void readLighting(Reader& reader, const Json& node, GrassLightingDesc& lighting) {
    Object object(reader, node, "/lighting", LIGHTING_KEYS);
    if (const Json* model = object.find("model")) {
        std::size_t index = 0;
        if (reader.readEnum(*model, "/lighting/model", MODEL_NAMES, index))
            lighting.model = static_cast<LightingModel>(index);
    }
    object.readVec3("diffuse_low", COLOR_RULE, RGB, lighting.diffuseLow);
    object.readVec3("diffuse_mid", COLOR_RULE, RGB, lighting.diffuseMid);
    object.readVec3("diffuse_high", COLOR_RULE, RGB, lighting.diffuseHigh);
    object.readFloat("terrain_normal_weight", UNIT_INTERVAL, lighting.terrainNormalWeight);
    object.readFloat("specular", WEIGHT_RULE, lighting.specular);
    object.readRange("specular_fade", NON_NEGATIVE, lighting.specularFadeM.x,
                     lighting.specularFadeM.y);
    object.readFloat("transmission", WEIGHT_RULE, lighting.transmission);
    object.readFloat("transmission_distortion", UNIT_INTERVAL, lighting.transmissionDistortion);
    object.readFloat("transmission_power", NumberRule{0.0, 256.0, true, false},
                     lighting.transmissionPower);
    object.readFloat("sss", WEIGHT_RULE, lighting.sss);
    object.readFloat("sss_intensity", UNIT_INTERVAL, lighting.sssIntensity);
    object.readFloat("ao_radius", RADIUS_RULE, lighting.aoRadiusM);
    object.readFloat("ao_strength", WEIGHT_RULE, lighting.aoStrength);
    object.readFloat("ao_floor", UNIT_INTERVAL, lighting.aoFloor);
    object.readFloat("normal_blur_radius", RADIUS_RULE, lighting.normalBlurRadiusM);
    object.readFloat("ao_cell", NumberRule{0.0, 4.0}, lighting.aoCellSigmas);
    // Below a tenth of a millimetre a kernel covers no neighbour: 0 turns the term off instead.
    for (const auto& [key, radius] : {std::pair{"ao_radius", lighting.aoRadiusM},
                                      {"normal_blur_radius", lighting.normalBlurRadiusM}})
        if (radius > 0.0f && radius < MIN_KERNEL_RADIUS_M)
            reader.fail(std::string("/lighting/") + key,
                        "must be 0 (off) or from 0.0001 to 100 metres");
    // Between 0 (exact) and the bake's smallest cells the value would be slow and mean nothing.
    if (lighting.aoCellSigmas > 0.0f && lighting.aoCellSigmas < 0.05f)
        reader.fail("/lighting/ao_cell", "must be 0 (exact sums) or in [0.05, 4] kernel sigmas");
    object.readRange("water", UNIT_INTERVAL, lighting.water.x, lighting.water.y);
}

Json lightingJson(const GrassLightingDesc& lighting) {
    Json out = Json::object();
    out["model"] = std::string(MODEL_NAMES[static_cast<std::size_t>(lighting.model)]);
    out["diffuse_low"] = jsonVec3(lighting.diffuseLow);
    out["diffuse_mid"] = jsonVec3(lighting.diffuseMid);
    out["diffuse_high"] = jsonVec3(lighting.diffuseHigh);
    out["terrain_normal_weight"] = jsonFloat(lighting.terrainNormalWeight);
    out["specular"] = jsonFloat(lighting.specular);
    out["specular_fade"] = jsonRange(lighting.specularFadeM.x, lighting.specularFadeM.y);
    out["transmission"] = jsonFloat(lighting.transmission);
    out["transmission_distortion"] = jsonFloat(lighting.transmissionDistortion);
    out["transmission_power"] = jsonFloat(lighting.transmissionPower);
    out["sss"] = jsonFloat(lighting.sss);
    out["sss_intensity"] = jsonFloat(lighting.sssIntensity);
    out["ao_radius"] = jsonFloat(lighting.aoRadiusM);
    out["ao_strength"] = jsonFloat(lighting.aoStrength);
    out["ao_floor"] = jsonFloat(lighting.aoFloor);
    out["normal_blur_radius"] = jsonFloat(lighting.normalBlurRadiusM);
    out["ao_cell"] = jsonFloat(lighting.aoCellSigmas);
    out["water"] = jsonRange(lighting.water.x, lighting.water.y);
    return out;
}

}  // namespace grass::core::json
