// The blade layout of SPEC §1, mirrored from core/blade/blade.h (static_asserts there):
// four vec4, 64 bytes, std430: (v0, theta) (v1, h) (v2, w) (up, s).
// Included by both blade_geometry.glsl and blade_texels.glsl: defined once.
#ifndef GRASS_BLADE_GLSL
#define GRASS_BLADE_GLSL
struct Blade {
    vec4 v0Theta;
    vec4 v1H;
    vec4 v2W;
    vec4 upS;
};

layout(std430, binding = 0) readonly buffer BladeBuffer {
    Blade blades[];
};

// Same construction as core::widthDirection: a reference axis not parallel to up, the tangent
// basis (t, b), rotated by theta.
vec3 widthDirection(vec3 up, float theta) {
    vec3 reference = abs(up.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = normalize(cross(reference, up));
    vec3 b = cross(up, t);
    return cos(theta) * t + sin(theta) * b;
}
#endif
