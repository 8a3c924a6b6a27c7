#version 450 core
// Test program of tests/gl/formula_twins_gl_test.cpp: runs the grass lighting functions of
// shaders/include/grass_lighting.glsl and the cull rules of shaders/include/cull_rules.glsl (the
// very files the passes include) on one case per invocation, so the test can compare them with
// their C++ twins (core/scene/grass_lighting_formulas.h, core/scene/cull_rules.h). The lighting
// block is bound as the passes bind it.
#include "grass_lighting.glsl"
#include "cull_rules.glsl"

layout(local_size_x = 64) in;

// FormulaCase in the test, std430: inputs packed into the w of the vectors beside them.
struct FormulaCase {
    vec4 albedoAo;               // GrassSurface albedo, ao
    vec4 bladeNormalWater;       // bladeNormal, water
    vec4 terrainNormalHeight;    // terrainNormal, height
    vec4 blurredNormalDistance;  // blurredNormal, eyeDistance
    vec4 toEyeNv;                // toEye; schlickF's n·v
    vec4 toLightNh;              // specularLobes' toLight; ggxD's n·h
    vec4 dirViewAlpha;           // seenEdgeOn's dirView; ggxD's α
    vec4 dirWidthDproj;          // seenEdgeOn's dirWidth; the keep count's dproj
    vec4 toBladeMaxDistance;     // projectedDistance's toBlade; the keep count's maxDistance
    vec4 up;                     // projectedDistance's up, w GrassSurface sunVisibility
    uvec4 classesIndex;          // x distance classes, y blade index, zw unused
};

// FormulaResult in the test.
struct FormulaResult {
    vec4 lightingLobes;       // grassLighting(surface), specularLobes(bladeNormal, toLight, ...)
    vec4 ggxSchlickDproj;     // ggxD, schlickF, projectedDistance, unused
    uvec4 keptKeptByEdgeOn;   // distanceKeptCount, keptByDistance, seenEdgeOn, unused
};

layout(std430, binding = 0) readonly buffer CaseBuffer {
    FormulaCase cases[];
};
layout(std430, binding = 1) writeonly buffer ResultBuffer {
    FormulaResult results[];
};

uniform uint uCaseCount;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCaseCount)
        return;
    FormulaCase c = cases[i];
    GrassSurface s;
    s.albedo = c.albedoAo.xyz;
    s.bladeNormal = c.bladeNormalWater.xyz;
    s.terrainNormal = c.terrainNormalHeight.xyz;
    s.blurredNormal = c.blurredNormalDistance.xyz;
    s.ao = c.albedoAo.w;
    s.water = c.bladeNormalWater.w;
    s.height = c.terrainNormalHeight.w;
    s.toEye = c.toEyeNv.xyz;
    s.eyeDistance = c.blurredNormalDistance.w;
    s.sunVisibility = c.up.w;

    FormulaResult r;
    float article = uGrassLighting == 2 ? 1.0 : 0.0;
    r.lightingLobes = vec4(grassLighting(s), specularLobes(s.bladeNormal, c.toLightNh.xyz,
                                                           s.toEye, s.water, article));
    r.ggxSchlickDproj = vec4(ggxD(c.toLightNh.w, c.dirViewAlpha.w), schlickF(c.toEyeNv.w),
                             projectedDistance(c.toBladeMaxDistance.xyz, c.up.xyz), 0.0);
    uint classes = c.classesIndex.x;
    float dproj = c.dirWidthDproj.w;
    float maxDistance = c.toBladeMaxDistance.w;
    bool kept = keptByDistance(c.classesIndex.y, classes, dproj, maxDistance);
    bool edgeOn = seenEdgeOn(c.dirViewAlpha.xyz, c.dirWidthDproj.xyz);
    r.keptKeptByEdgeOn =
        uvec4(distanceKeptCount(classes, dproj, maxDistance), kept ? 1u : 0u, edgeOn ? 1u : 0u, 0u);
    results[i] = r;
}
