// Wind and distance fade of star billboards (SPEC §8, GPU Gems 1 ch. 7). The same functions, with
// the same constants, as core/billboard/star_billboards.cpp (billboardWindOffset,
// billboardFade) and core/billboard/billboard_motion.cpp (the scene wind's bend, the animated
// vertex): the per-cluster mode computes its cluster's sway and wind there on the CPU, the
// per-vertex and per-object modes here.
#include "wind_field.glsl"

const float BILLBOARD_TWO_PI = 6.28318530717958647692;
const float WIND_WAVE_NUMBER = 1.3;
const float WIND_CROSS_RATE = 1.7;
const float WIND_MAIN_SHARE = 0.8;
const float WIND_CROSS_SHARE = 0.2;

// Horizontal offset of an upper vertex whose phase point is p; |offset| <= amplitude.
vec3 billboardWindOffset(vec3 p, float timeS, vec2 directionXZ, float amplitudeM,
                         float frequencyHz) {
    vec2 dir = dot(directionXZ, directionXZ) > 0.0 ? normalize(directionXZ) : vec2(1.0, 0.0);
    vec2 crossDir = vec2(-dir.y, dir.x);
    float along = dot(dir, p.xz);
    float across = dot(crossDir, p.xz);
    float omega = BILLBOARD_TWO_PI * frequencyHz;
    float mainPhase = omega * timeS - WIND_WAVE_NUMBER * along;
    float crossPhase = WIND_CROSS_RATE * omega * timeS + 2.1 * along + 1.1 * across;
    float mainSway = WIND_MAIN_SHARE * (0.5 + 0.5 * sin(mainPhase));
    float crossSway = WIND_CROSS_SHARE * cos(crossPhase);
    vec2 offset = amplitudeM * (mainSway * dir + crossSway * crossDir);
    return vec3(offset.x, 0.0, offset.y);
}

// smoothstep over [start, end]; an empty ramp is a step (GLSL's smoothstep is undefined there).
float billboardRamp(float start, float end, float d) {
    if (!(end > start))
        return d >= start ? 1.0 : 0.0;
    return smoothstep(start, end, d);
}

// fade = (in start, in end, out start, out end) in metres of camera distance.
float billboardFade(float distanceM, vec4 fade) {
    return billboardRamp(fade.x, fade.y, distanceM) *
           (1.0 - billboardRamp(fade.z, fade.w, distanceM));
}

// The scene's wind sources (core::WindSourceGpu) and each one's centre at uTime (xyz), bound by
// render::BillboardField::draw; uWindSourceCount 0 reads neither.
layout(std430, binding = 13) readonly buffer BillboardWindSourceBuffer {
    WindSource billboardWindSources[];
};
layout(std430, binding = 14) readonly buffer BillboardWindCentreBuffer {
    vec4 billboardWindCentres[];
};
uniform int uWindSourceCount;

vec3 billboardSceneWind(vec3 p, float timeS) {
    vec3 wind = vec3(0.0);
    for (int k = 0; k < uWindSourceCount; ++k)
        wind += windAt(billboardWindSources[k], billboardWindCentres[k].xyz, p, timeS);
    return wind;
}

// core::billboardWindBend: the tuft bends as a blade of stiffness s rooted there, Δ = w⊥/s,
// saturating below its height and sinking to keep its length.
vec3 billboardWindBend(vec3 wind, vec3 up, float heightM, float stiffness) {
    if (!(heightM > 0.0) || !(stiffness > 0.0))
        return vec3(0.0);
    vec3 across = wind - up * dot(wind, up);
    float push = length(across) / stiffness;
    if (!(push > 0.0) || !isFiniteFloat(push))
        return vec3(0.0);
    float x = push / heightM;
    float reach = heightM * (x / (1.0 + x));
    float sink = heightM - sqrt(heightM * heightM - reach * reach);
    return across * (reach / (push * stiffness)) - up * sink;
}

struct StarVertexMotion {
    vec3 position;
    vec3 normal;
};

// One star vertex animated in mode `mode` (0 per cluster, 1 per vertex, 2 per object), as
// core::billboardVertexMotion: the sway and the scene wind at the phase point (per cluster: the
// CPU's clusterSway and clusterWind), the bend from the wind, then GPU Gems' listing 7-1: the
// upper vertices move and their normal turns to normalize(N·h + translation).
StarVertexMotion billboardVertexMotion(vec3 position, vec3 normal, vec3 objectCentre, float sway,
                                       float objectHeight, int mode, vec3 clusterSway,
                                       vec3 clusterWind, float timeS, vec2 directionXZ,
                                       float amplitudeM, float frequencyHz, float stiffness) {
    StarVertexMotion motion;
    motion.position = position;
    motion.normal = normal;
    if (sway <= 0.0)
        return motion;
    vec3 translation = clusterSway;
    vec3 wind = clusterWind;
    if (mode != 0) {
        vec3 at = mode == 1 ? position : objectCentre;
        translation = billboardWindOffset(at, timeS, directionXZ, amplitudeM, frequencyHz);
        wind = billboardSceneWind(at, timeS);
    }
    translation += billboardWindBend(wind, normal, objectHeight, stiffness);
    vec3 turned = normal * objectHeight + translation;
    float turnedLength = length(turned);
    motion.position = position + sway * translation;
    motion.normal = turnedLength > 0.0 ? turned / turnedLength : normal;
    return motion;
}
