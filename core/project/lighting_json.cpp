// The "sun" and "lighting" sections of project.json: the grass lighting of SPEC §10.
#include <array>

#include "project/project_json_parts.h"
#include "scene/blade_shading.h"

namespace grass::core {

namespace {

using json::NumberRule;
using settings::field;
using settings::Kind;

constexpr std::array<std::string_view, 3> MODEL_NAMES{"grass", "simple", "article"};
// Colours multiply the sun: above 4 a typo would wash the frame out.
constexpr NumberRule COLOR_RULE{0.0, 4.0};
constexpr NumberRule WEIGHT_RULE{0.0, 10.0};
// Kernel radii (0 turns the term off): beyond 100 m the bake would visit the whole field for
// every blade.
constexpr NumberRule RADIUS_RULE{0.0, 100.0};

constexpr std::array SUN{
    field<&SunDesc::direction>(
        {.key = "direction",
         .help = "the way the light travels (so y < 0 shines down); not `[0, 0, 0]`; normalised "
                 "on use"}),
    field<&SunDesc::color>(
        {.key = "color", .kind = Kind::Colour, .rule = json::UNIT_INTERVAL, .label = "colour"}),
    field<&SunDesc::intensity>(
        {.key = "intensity", .rule = json::NON_NEGATIVE, .help = "multiplies `color`"}),
    field<&SunDesc::shadows>(
        {.key = "shadows",
         .kind = Kind::Flag,
         .help = "the surface and the colliders shade the grass, the ground and each other; off "
                 "costs nothing",
         .label = "sun shadows"}),
    field<&SunDesc::shadowResolution>(
        {.key = "shadow_resolution",
         .intMin = 256,
         .intMax = 8192,
         .help = "texels a side of the sun's depth map, which covers the whole scene"}),
};

constexpr std::array LIGHTING{
    field<&GrassLightingDesc::model>(
        {.key = "model",
         .names = MODEL_NAMES,
         .label = "lighting",
         .allowedText = "`\"grass\"` (SPEC §10), `\"simple\"` (wrapped Lambert, for comparison) or "
                        "`\"article\"` (article 003's model exactly as written)"}),
    field<&GrassLightingDesc::diffuseLow>(
        {.key = "diffuse_low", .kind = Kind::Colour, .rule = COLOR_RULE,
         .help = "the ramp at N·L = −1"}),
    field<&GrassLightingDesc::diffuseMid>(
        {.key = "diffuse_mid", .kind = Kind::Colour, .rule = COLOR_RULE, .help = "at N·L = 0"}),
    field<&GrassLightingDesc::diffuseHigh>(
        {.key = "diffuse_high", .kind = Kind::Colour, .rule = COLOR_RULE, .help = "at N·L = 1"}),
    field<&GrassLightingDesc::terrainNormalWeight>(
        {.key = "terrain_normal_weight",
         .rule = json::UNIT_INTERVAL,
         .help = "how far the diffuse normal leans from the blade normal to the terrain (SSS) "
                 "normal"}),
    field<&GrassLightingDesc::specular>(
        {.key = "specular", .rule = WEIGHT_RULE, .help = "weight of the three GGX lobes"}),
    field<&GrassLightingDesc::specularFadeM>(
        {.key = "specular_fade",
         .rule = json::NON_NEGATIVE,
         .unit = "m",
         .help = "specular grows from 0 at near to full at far (weaker near the eye)",
         .typeText = "[near, far]"}),
    field<&GrassLightingDesc::transmission>(
        {.key = "transmission", .rule = WEIGHT_RULE, .help = "light through the blades (I)"}),
    field<&GrassLightingDesc::transmissionDistortion>(
        {.key = "transmission_distortion",
         .rule = json::UNIT_INTERVAL,
         .help = "k in fakeN = −normalize(mix(N, L, k))"}),
    field<&GrassLightingDesc::transmissionPower>(
        {.key = "transmission_power", .rule = NumberRule{0.0, 256.0, true, false}, .help = "e"}),
    field<&GrassLightingDesc::sss>(
        {.key = "sss", .rule = WEIGHT_RULE, .help = "weight of the subsurface term"}),
    field<&GrassLightingDesc::sssIntensity>({.key = "sss_intensity",
                                             .rule = json::UNIT_INTERVAL,
                                             .help = "terrain normal → blurred terrain normal"}),
    field<&GrassLightingDesc::aoRadiusM>(
        {.key = "ao_radius",
         .rule = RADIUS_RULE,
         .unit = "m",
         .help = "0 or from 0.0001; Gaussian σ of the neighbour-density kernel; 0 turns AO off"}),
    field<&GrassLightingDesc::aoStrength>(
        {.key = "ao_strength",
         .rule = WEIGHT_RULE,
         .unit = "m²",
         .help = "one neighbour occludes: AO = floor + (1 − floor)·exp(−density·strength)",
         .ui = {.decimals = 4, .speed = 0.0005f}}),
    field<&GrassLightingDesc::aoFloor>(
        {.key = "ao_floor", .rule = json::UNIT_INTERVAL, .help = "the darkest AO"}),
    field<&GrassLightingDesc::normalBlurRadiusM>(
        {.key = "normal_blur_radius",
         .rule = RADIUS_RULE,
         .unit = "m",
         .help = "0 or from 0.0001; Gaussian σ of the terrain-normal blur; 0 keeps each blade's "
                 "own normal"}),
    field<&GrassLightingDesc::aoCellSigmas>(
        {.key = "ao_cell",
         .rule = NumberRule{0.0, 4.0},
         .help = "0 or from 0.05 kernel σ: the bake sums neighbours in other cells of this side "
                 "per cluster (faster, approximate); 0 sums every neighbour exactly (slow in "
                 "dense fields); the `ao_kernel` knob of [tradeoff](tradeoff.md)"}),
    field<&GrassLightingDesc::water>(
        {.key = "water",
         .rule = json::UNIT_INTERVAL,
         .help = "a blade's water follows its random age; it is the mix weight of specular + "
                 "transmission + SSS against diffuse, and the roughness of the specular lobes",
         .typeText = "[oldest, youngest]"}),
};

}  // namespace

std::span<const settings::Setting<SunDesc>> settings::sun() { return SUN; }
std::span<const settings::Setting<GrassLightingDesc>> settings::lighting() { return LIGHTING; }

void json::checkSun(Reader& reader, const Object& object, const SunDesc& sun) {
    if (sun.direction == glm::vec3(0.0f))
        reader.fail(object.pointerTo("direction"),
                    "must not be [0, 0, 0] (it is the way the light travels)");
}

void json::checkLighting(Reader& reader, const Object& object,
                         const GrassLightingDesc& lighting) {
    // Below a tenth of a millimetre a kernel covers no neighbour: 0 turns the term off instead.
    for (const auto& [key, radius] : {std::pair{"ao_radius", lighting.aoRadiusM},
                                      {"normal_blur_radius", lighting.normalBlurRadiusM}})
        if (radius > 0.0f && radius < MIN_KERNEL_RADIUS_M)
            reader.fail(object.pointerTo(key), "must be 0 (off) or from 0.0001 to 100 metres");
    // Between 0 (exact) and the bake's smallest cells the value would be slow and mean nothing.
    if (lighting.aoCellSigmas > 0.0f && lighting.aoCellSigmas < 0.05f)
        reader.fail(object.pointerTo("ao_cell"),
                    "must be 0 (exact sums) or in [0.05, 4] kernel sigmas");
}

}  // namespace grass::core
