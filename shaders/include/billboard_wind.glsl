// Wind and distance fade of star billboards (SPEC §8, GPU Gems 1 ch. 7). The same functions, with
// the same constants, as core/billboard/star_billboards.cpp (billboardWindOffset,
// billboardFade): the per-cluster mode computes the offset there on the CPU, the per-vertex and
// per-object modes here.
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
