// Grass lighting of SPEC §10 (article 003), per pixel. Terms and their inputs:
//   diffuse ramp on the blade normal leaned towards the SSS terrain normal;
//   GGX D·F specular (no G; Schlick F with N·V, F0 = 0.04) in three lobes whose roughness
//   follows the blade's water, once with the blade normal (weighted towards the tip) and once
//   with the terrain normal, faded out near the eye;
//   transmission through the blade, thinned by the grass AO (dense grass passes less light);
//   SSS: wrapped light on mix(terrainN, blurredTerrainN, sssIntensity);
//   final = mix(diffuse, specular + transmission + sss, water), plus sky ambient × AO.
// uGrassLighting 2 (LightingModel::Article) draws the article's model as written instead of
// ours: lobes without our N·L factor and clamp, α = roughness², SSS as the ramp lit through the
// SSS normal, no ambient and no AO on the lit colour (docs/rendering.md shows the two side by
// side). It is chosen by arithmetic, not by a branch: llvmpipe runs both sides of a uniform
// branch, so ours pays a few multiplications for it and nothing more.
// The article lights per vertex; per pixel costs the same on the strips here (the fragment
// count, not the vertex count, dominates on a software rasterizer) and keeps highlights round.
// core/scene/grass_lighting_formulas.h is this file's C++ twin, function for function; a GL test
// (tests/gl/formula_twins_gl_test.cpp) runs both on the same inputs: change them together.
#include "lighting.glsl"

// core::GRASS_PI and core::GRASS_F0 mirror these.
const float GRASS_PI = 3.14159265358979;
const float GRASS_F0 = 0.04;

struct GrassSurface {
    vec3 albedo;
    vec3 bladeNormal;    // facing the viewer
    vec3 terrainNormal;  // the surface normal under the blade
    vec3 blurredNormal;  // baked, Gaussian-blurred terrain normal
    float ao;            // baked grass AO, 1 = open
    float water;         // baked, 1 = young and wet
    float height;        // 0 root, 1 tip
    vec3 toEye;          // normalized
    float eyeDistance;   // metres
    float sunVisibility; // 0 in the sun's shadow .. 1 lit (sun_shadow.glsl)
};

// GGX normal distribution with α = roughness (not squared: α = r² would make the driest lobe
// a pin-point that aliases on blades a few pixels wide).
float ggxD(float nh, float alpha) {
    float a2 = alpha * alpha;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    return a2 / (GRASS_PI * d * d);
}

float schlickF(float nv) {
    // pow of a negative base is undefined in GLSL: n·v of unit vectors can round above 1.
    return GRASS_F0 + (1.0 - GRASS_F0) * pow(max(1.0 - nv, 0.0), 5.0);
}

// The diffuse ramp: n·l ∈ [−1, 0] maps low → mid, [0, 1] mid → high.
vec3 diffuseRamp(float nl) {
    return nl > 0.0 ? mix(uDiffuseMid, uDiffuseHigh, nl) : mix(uDiffuseLow, uDiffuseMid, nl + 1.0);
}

// 0.5·S(water) + 0.3·S(water/2) + 0.2·S(water/4): the argument is each lobe's roughness r,
// floored at 0.02. Ours (article 0): α = r, times n·l (0 where the light is behind n), at most 4.
// The article's (article 1): α = r², no n·l, no clamp.
float specularLobes(vec3 n, vec3 toLight, vec3 toEye, float water, float article) {
    float cosine = mix(max(dot(n, toLight), 0.0), 1.0, article);
    // The eye looking straight into the light has no half vector: no lobe faces it.
    vec3 halfway = toLight + toEye;
    float nh = dot(halfway, halfway) > 1e-12 ? max(dot(n, normalize(halfway)), 0.0) : 0.0;
    float f = schlickF(max(dot(n, toEye), 0.0));
    float r = max(water, 0.02);
    float lobes = 0.5 * ggxD(nh, mix(r, r * r, article)) +
                  0.3 * ggxD(nh, mix(0.5 * r, 0.25 * r * r, article)) +
                  0.2 * ggxD(nh, mix(0.25 * r, 0.0625 * r * r, article));
    // The lobes are normalized distributions; their peaks reach tens. Ours clamps so a perfect
    // mirror angle on one blade cannot flash a pixel white.
    return min(lobes * f * cosine, mix(4.0, 3.0e38, article));
}

vec3 grassLighting(GrassSurface s) {
    float article = uGrassLighting == 2 ? 1.0 : 0.0;
    vec3 toLight = -uSunDirection;
    vec3 sssNormal = normalize(mix(s.terrainNormal, s.blurredNormal, uSssIntensity));
    vec3 diffuseNormal = normalize(mix(s.bladeNormal, sssNormal, uTerrainNormalWeight));

    // In the sun's shadow the ramp falls to its N·L = −1 colour, the ramp's own shade.
    vec3 diffuse = s.albedo * uSunColor *
                   mix(uDiffuseLow, diffuseRamp(dot(diffuseNormal, toLight)), s.sunVisibility);

    float fade = smoothstep(uSpecularFade.x, uSpecularFade.y, s.eyeDistance);
    float specular = s.height * specularLobes(s.bladeNormal, toLight, s.toEye, s.water, article) +
                     specularLobes(s.terrainNormal, toLight, s.toEye, s.water, article);
    vec3 specularTerm = uSunColor * (uSpecular * fade * specular * s.sunVisibility);

    vec3 fakeN = -normalize(mix(s.bladeNormal, toLight, uTransmissionDistortion));
    float through = pow(clamp(dot(fakeN, s.toEye), 0.0, 1.0), uTransmissionPower);
    vec3 transmissionTerm =
        uTransmission * through * s.ao * s.sunVisibility * uSunColor * s.albedo;

    // Ours: wrapped light on the SSS normal. The article's: its SSS is the blurred shading
    // normal itself, so the ramp lit through it.
    float wrapped = clamp(0.5 + 0.5 * dot(sssNormal, toLight), 0.0, 1.0);
    vec3 sssLight = mix(vec3(wrapped * wrapped), diffuseRamp(dot(sssNormal, toLight)), article);
    vec3 sssTerm = uSss * sssLight * s.sunVisibility * uSunColor * s.albedo;

    vec3 lit = mix(diffuse, specularTerm + transmissionTerm + sssTerm, s.water);
    vec3 ambient = mix(uGroundColor, uSkyColor, 0.5 + 0.5 * sssNormal.y) * 0.35 * s.albedo;
    return lit * mix(1.0, s.ao, 0.5 - 0.5 * article) + (1.0 - article) * ambient * s.ao;
}
