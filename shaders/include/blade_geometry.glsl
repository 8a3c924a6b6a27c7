// The curve-and-shape evaluation both geometry paths share (SPEC §7): the tessellation
// evaluation shader and the instanced-strip vertex shader call bladeSurface with the same
// (u, v) and get the same point, so the two paths draw the same blade.
#include "blade.glsl"
#include "bezier.glsl"
#include "shapes.glsl"

struct BladeSurfacePoint {
    vec3 position;
    vec3 normal;   // front side; the fragment shader flips it for back faces
    float v;       // 0 at the root, 1 at the tip
};

BladeSurfacePoint bladeSurface(Blade blade, float u, float v, int shape) {
    vec3 v0 = blade.v0Theta.xyz;
    vec3 v1 = blade.v1H.xyz;
    vec3 v2 = blade.v2W.xyz;
    vec3 up = blade.upS.xyz;
    float w = blade.v2W.w;
    vec3 t1 = widthDirection(up, blade.v0Theta.w);
    vec3 c = bezierPoint(v0, v1, v2, v);
    vec3 tangent = bezierTangent(v0, v1, v2, v);
    float t = shapeT(shape, u, v, 0.5);
    BladeSurfacePoint point;
    point.position = mix(c - w * t1, c + w * t1, t);
    vec3 n = cross(tangent, t1);
    point.normal = dot(n, n) > 1e-20 ? normalize(n) : normalize(cross(up, t1));
    point.v = v;
    return point;
}
