#version 450 core
// Instanced-strip path (SPEC §7): one instance per blade, a triangle strip of
// 2·(uSegments + 1) vertices; the curve is evaluated here. Cheap on software rasterizers.
// Instances are the blades that survived the cull pass, read through the visible list.
#include "blade_geometry.glsl"
#include "visible.glsl"

uniform mat4 uViewProj;
uniform int uSegments;
uniform int uShape;
uniform float uTipStart;
uniform float uPixelScale;  // projection[1][1] · viewport height / 2; 0: no width correction

out vec3 vPosition;
out vec3 vNormal;
out vec3 vUp;
out float vHeight;

void main() {
    Blade blade = blades[visible[gl_InstanceID]];
    int segment = gl_VertexID >> 1;
    float u = float(gl_VertexID & 1);
    float v = float(segment) / float(uSegments);
    BladeShapeParams shape =
        BladeShapeParams(uShape, uTipStart, float(uSegments), uViewProj, uPixelScale);
    BladeSurfacePoint point = bladeSurface(blade, u, v, shape);
    // Padding blades (h = 0) collapse to a point and produce no fragments.
    if (blade.v1H.w <= 0.0) point.position = blade.v0Theta.xyz;
    vPosition = point.position;
    vNormal = point.normal;
    vUp = blade.upS.xyz;
    vHeight = v;
    gl_Position = uViewProj * vec4(point.position, 1.0);
}
