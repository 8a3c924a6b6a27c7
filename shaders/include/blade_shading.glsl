// Per-blade lighting inputs baked when the scene is built (core/scene/blade_shading.h,
// SPEC §10): the Gaussian-blurred terrain normal and the grass AO from neighbour density, and
// the blade's water (young = wet). One entry per blade slot, same order as the blade buffer.
struct BladeShading {
    vec4 blurredNormalAo;  // xyz blurred terrain normal, w AO (1 = open)
    vec4 waterAge;         // x water, y age, z wilt (growth colour)
};

layout(std430, binding = 9) readonly buffer BladeShadingBuffer {
    BladeShading bladeShading[];
};
