#version 450 core
// Per-blade culling (SPEC §6, Jahrmann §6). One invocation per blade slot; patches hold a
// multiple of 32 blades and the buffer is patch-major, so each run of 32 invocations lies in one
// patch; a work group holds GROUP_RUNS runs (core/util/blade_pass_group.h: 1 unless
// GRASS_COMPUTE_GROUP says). Stage 1, once per run before any blade is read: the patch's box
// against the view frustum (the blades of a patch out of view cost no load). Stage 2, per blade:
// uniform thinning (the editor's reduced picture while the user interacts, off otherwise),
// orientation, frustum, distance, occlusion, burial under snow, in that order; a blade is counted
// by the first test that removes it.
// Survivors append their index to the visible list of their level of detail (lod.glsl) and bump
// that LOD's strip and tessellation instance counts (reset to 0 before the dispatch); a blade in
// its LOD's morph band (lodMorph > 0) is listed from the list's end, backwards, and counted in
// the LOD's blending commands, drawn by the program that holds the blend
// (core::lodBlending says why).
// The blades are read through their texel view (blade_texels.glsl): llvmpipe loads an SSBO's
// floats lane by lane, each behind a bounds check, and a texel fetch gathers a vec4 a lane.
#include "blade_texels.glsl"
#include "cull_rules.glsl"
#include "lod.glsl"
#ifdef GRASS_SNOW
#include "snow.glsl"
#endif

#ifndef GROUP_RUNS
#define GROUP_RUNS 1
#endif
#define RUN_BLADES 32u
layout(local_size_x = 32 * GROUP_RUNS) in;
// After the group size, which dispatch_grid.glsl reads.
#include "dispatch_grid.glsl"

// Per patch: min (xyz, w unused) then max.
layout(std430, binding = 1) readonly buffer PatchBoundsBuffer {
    vec4 patchBounds[];
};
// LOD_COUNT lists of uBladeCount entries each: LOD k's survivors start at k·uBladeCount, its
// blending ones end at (k + 1)·uBladeCount − 1 and run backwards.
layout(std430, binding = 5) writeonly buffer VisibleBuffer {
    uint visible[];
};
// DrawArraysIndirectCommand (count, instanceCount, first, baseInstance) per LOD: strips at
// [4k .. 4k+3], tessellation patches at [4·LOD_COUNT + 4k ..], then the same for the blades in
// the morph band from [8·LOD_COUNT] (core::BladeDrawCommands). Then from STRIP_BATCH_WORDS one
// DrawElementsIndirectCommand (count, instanceCount, firstIndex, baseVertex, baseInstance) per
// draw class: the strip batches of STRIP_BATCH_BLADES blades (core/blade/strip_batch.h).
#define STRIP_BATCH_WORDS (16 * LOD_COUNT)
#define STRIP_BATCH_BLADES 64u
layout(std430, binding = 6) buffer CommandBuffer {
    uint commands[STRIP_BATCH_WORDS + 10 * LOD_COUNT];
};
// Statistics: blades in, culled by patch, orientation, frustum, distance, occlusion, snow.
layout(std430, binding = 7) buffer CounterBuffer {
    uint counters[8];
};
#ifdef GRASS_SNOW
// Snow (SPEC §11): the whiteness of each surviving blade's tip (bladeTipSnow), read by the blade
// shaders. This program variant runs only while snow lies.
layout(std430, binding = 10) writeonly buffer TipSnowBuffer {
    float tipSnow[];
};
#endif

uniform sampler2D uSceneDepth;  // window-space depth of the opaque pre-pass
uniform mat4 uViewProj;
uniform vec3 uCameraPosition;
// Projection terms to turn window depth back into view distance: zView = P32 / (zNdc + P22).
uniform float uProj22;
uniform float uProj32;
uniform uint uBladeCount;
uniform uint uPatchSize;
uniform int uTestPatch;
uniform int uTestOrientation;
uniform int uTestFrustum;
uniform int uTestDistance;
uniform int uTestOcclusion;
uniform int uDistanceClasses;
uniform float uMaxDistance;
uniform float uLodDistance;
uniform float uLodBlend;  // lod.glsl's lodMorph band; 0: no blade blends
uniform float uCutoffDistance;  // > 0: blades beyond it are culled as distance (hybrid far field)
uniform int uKeepEvery;  // > 1: only every n-th blade is drawn (the editor's reduced picture)
uniform int uCollectStats;

// Clip-space slack of the frustum test: blades have width and bend between the three tested
// points, so a blade whose points sit just outside the view may still reach into it.
const float FRUSTUM_TOLERANCE = 0.1;
// Occlusion bias: a blade's root lies on the terrain, at the depth of the terrain, and the
// depth texel it samples may hold slightly nearer terrain on slopes seen at a grazing angle.
// A point counts as hidden only when it is behind the opaque depth by this much (metres plus a
// share of the distance, which grows with depth quantisation and texel footprint).
const float OCCLUSION_BIAS_M = 0.1;
const float OCCLUSION_BIAS_RELATIVE = 0.02;

const uint RESULT_VISIBLE = 0u;
const uint RESULT_PATCH = 1u;
const uint RESULT_ORIENTATION = 2u;
const uint RESULT_FRUSTUM = 3u;
const uint RESULT_DISTANCE = 4u;
const uint RESULT_OCCLUSION = 5u;
const uint RESULT_SNOW = 6u;
const uint RESULT_SKIPPED = 7u;
const uint COUNTED_RESULTS = 7u;

shared uint sCounts[COUNTED_RESULTS];
shared bool sPatchOutside[GROUP_RUNS];  // per run of 32 blades
// Per draw class: LOD k's blades at [k], its blending ones at [LOD_COUNT + k].
shared uint sSurvivors[2 * LOD_COUNT];
shared uint sBase[2 * LOD_COUNT];

bool boxOutsideFrustum(vec3 lo, vec3 hi) {
    // Outside when all eight corners lie beyond the same clip plane (conservative).
    uvec3 allLow = uvec3(1u), allHigh = uvec3(1u);
    for (int i = 0; i < 8; ++i) {
        vec3 corner = vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y,
                           (i & 4) != 0 ? hi.z : lo.z);
        vec4 clip = uViewProj * vec4(corner, 1.0);
        allLow &= uvec3(lessThan(clip.xyz, vec3(-clip.w)));
        allHigh &= uvec3(greaterThan(clip.xyz, vec3(clip.w)));
    }
    return any(notEqual(allLow | allHigh, uvec3(0u)));
}

bool insideFrustum(vec4 clip) {
    float limit = clip.w * (1.0 + FRUSTUM_TOLERANCE);
    return clip.w > 0.0 && all(lessThanEqual(abs(clip.xy), vec2(limit))) && clip.z >= -clip.w &&
           clip.z <= clip.w;
}

bool hiddenByOpaque(vec4 clip) {
    // Points behind the camera or off screen have no depth to compare with: not hidden.
    if (clip.w <= 0.0)
        return false;
    vec3 ndc = clip.xyz / clip.w;
    if (any(greaterThan(abs(ndc.xy), vec2(1.0))))
        return false;
    float depth = textureLod(uSceneDepth, ndc.xy * 0.5 + 0.5, 0.0).r;
    if (depth >= 1.0)
        return false;  // sky: nothing opaque there
    float opaqueDistance = uProj32 / ((2.0 * depth - 1.0) + uProj22);
    float bias = OCCLUSION_BIAS_M + OCCLUSION_BIAS_RELATIVE * opaqueDistance;
    return clip.w > opaqueDistance + bias;
}

// The blade tests, in order; `patchOutside` is the group's stage 1, `root` the blade's v0 for the
// LOD. A blade of a patch out of view is drawn in no case: only the statistics tell padding,
// thinned and patch-culled blades apart, so only while they are collected is such a blade read.
uint classify(uint index, bool patchOutside, out vec3 root) {
    root = vec3(0.0);
    if (patchOutside && uCollectStats == 0)
        return RESULT_SKIPPED;
    Blade blade = fetchBlade(index);
    root = blade.v0Theta.xyz;
    if (blade.v1H.w <= 0.0)
        return RESULT_SKIPPED;
    if (uKeepEvery > 1 && index % uint(uKeepEvery) != 0u)
        return RESULT_DISTANCE;
    if (patchOutside)
        return RESULT_PATCH;
    vec3 v0 = blade.v0Theta.xyz;
    vec3 v1 = blade.v1H.xyz;
    vec3 v2 = blade.v2W.xyz;
    vec3 up = blade.upS.xyz;
    // Orientation, distance: the formulas live in cull_rules.glsl, which a GL test runs against
    // their C++ twin (core/scene/cull_rules.h).
    vec3 toBlade = v0 - uCameraPosition;
    if (uTestOrientation != 0 && dot(toBlade, toBlade) > 0.0 &&
        seenEdgeOn(normalize(toBlade), widthDirection(up, blade.v0Theta.w)))
        return RESULT_ORIENTATION;
    vec3 m = 0.25 * v0 + 0.5 * v1 + 0.25 * v2;
    vec4 clipV0 = uViewProj * vec4(v0, 1.0);
    vec4 clipM = uViewProj * vec4(m, 1.0);
    vec4 clipV2 = uViewProj * vec4(v2, 1.0);
    if (uTestFrustum != 0 && !insideFrustum(clipV0) && !insideFrustum(clipM) &&
        !insideFrustum(clipV2))
        return RESULT_FRUSTUM;
    // Distance: thin the field towards uMaxDistance by keeping fewer of n classes (i mod n).
    float dproj = projectedDistance(toBlade, up);
    if (uCutoffDistance > 0.0 && dproj > uCutoffDistance)
        return RESULT_DISTANCE;
    if (uTestDistance != 0 &&
        !keptByDistance(index, uint(uDistanceClasses), dproj, uMaxDistance))
        return RESULT_DISTANCE;
    if (uTestOcclusion != 0 && hiddenByOpaque(clipV0) && hiddenByOpaque(clipM) &&
        hiddenByOpaque(clipV2))
        return RESULT_OCCLUSION;
    // Last, as the dearest test (two exposure lookups of uSnowSamples taps): a blade shorter than
    // the snow at its root is buried (core::bladeBuriedBySnow); a survivor's tip whitens by the
    // exposure of the tip (core::bladeTipSnow).
#ifdef GRASS_SNOW
    if (bladeBuriedBySnow(blade.v1H.w, snowDepthAt(v0, up)))
        return RESULT_SNOW;
    tipSnow[index] =
        bladeTipSnow(exposureCoefficient(v2, uSnowUp, uSnowSamples, uSnowRadiusTexels));
#endif
    return RESULT_VISIBLE;
}

void main() {
    uint index = invocationInPass();
    if (gl_LocalInvocationIndex < COUNTED_RESULTS)
        sCounts[gl_LocalInvocationIndex] = 0u;
    if (gl_LocalInvocationIndex < uint(2 * LOD_COUNT))
        sSurvivors[gl_LocalInvocationIndex] = 0u;
    // The first GROUP_RUNS invocations test one run's patch each, side by side.
    if (gl_LocalInvocationIndex < uint(GROUP_RUNS)) {
        uint runFirst =
            workGroupInPass() * gl_WorkGroupSize.x + RUN_BLADES * gl_LocalInvocationIndex;
        uint patchIndex = runFirst / uPatchSize;
        sPatchOutside[gl_LocalInvocationIndex] =
            uTestPatch != 0 && runFirst < uBladeCount &&
            boxOutsideFrustum(patchBounds[2u * patchIndex].xyz,
                              patchBounds[2u * patchIndex + 1u].xyz);
    }
    barrier();
    vec3 root;
    uint result = index < uBladeCount
                      ? classify(index, sPatchOutside[gl_LocalInvocationIndex / RUN_BLADES], root)
                      : RESULT_SKIPPED;
    int lod = 0;
    bool blending = false;
    if (result == RESULT_VISIBLE) {
        float eyeDistance = distance(root, uCameraPosition);
        lod = bladeLod(eyeDistance, uLodDistance);
        blending = lodMorph(eyeDistance, uLodDistance, lod, uLodBlend) > 0.0;
    }
    int drawClass = blending ? LOD_COUNT + lod : lod;
    // Survivors take a slot in shared memory; one global atomic per group and LOD reserves the
    // range (contended global atomics per blade cost more than the tests on CPU rasterizers).
    uint localSlot = 0u;
    if (result == RESULT_VISIBLE)
        localSlot = atomicAdd(sSurvivors[drawClass], 1u);
    // Statistics are summed in shared memory first: one global atomic per counter and group.
    if (uCollectStats != 0 && result != RESULT_SKIPPED) {
        atomicAdd(sCounts[0], 1u);
        if (result != RESULT_VISIBLE)
            atomicAdd(sCounts[result], 1u);
    }
    barrier();
    // Class c's strip command is command c (blending: 2·LOD_COUNT + k), its patch command
    // LOD_COUNT after it.
    uint groupClass = gl_LocalInvocationIndex;
    if (groupClass < uint(2 * LOD_COUNT) && sSurvivors[groupClass] != 0u) {
        uint strip = groupClass < uint(LOD_COUNT) ? groupClass : groupClass + uint(LOD_COUNT);
        uint base = atomicAdd(commands[4u * strip + 1u], sSurvivors[groupClass]);
        sBase[groupClass] = base;
        // The batches this group's range [base, end) begins (core::stripBatches); over all
        // groups they add up to the batches of the class's survivors. The patches are drawn in
        // batches of the same size (core::PATCH_BATCH_BLADES).
        uint end = base + sSurvivors[groupClass];
        uint batchesBegun = (end + STRIP_BATCH_BLADES - 1u) / STRIP_BATCH_BLADES -
                            (base + STRIP_BATCH_BLADES - 1u) / STRIP_BATCH_BLADES;
        if (batchesBegun != 0u) {
            atomicAdd(commands[STRIP_BATCH_WORDS + 5u * groupClass + 1u], batchesBegun);
            atomicAdd(commands[4u * (strip + uint(LOD_COUNT)) + 1u], batchesBegun);
        }
    }
    if (uCollectStats != 0 && gl_LocalInvocationIndex < COUNTED_RESULTS &&
        sCounts[gl_LocalInvocationIndex] != 0u)
        atomicAdd(counters[gl_LocalInvocationIndex], sCounts[gl_LocalInvocationIndex]);
    barrier();
    if (result == RESULT_VISIBLE) {
        uint rank = sBase[drawClass] + localSlot;
        visible[blending ? uint(lod + 1) * uBladeCount - 1u - rank : uint(lod) * uBladeCount + rank] =
            index;
    }
}
