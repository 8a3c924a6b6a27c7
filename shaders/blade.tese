#version 450 core
// Tessellation evaluation: bend the unit quad (u, v) onto the blade curve (SPEC §7).
#include "blade_geometry.glsl"

layout(quads, equal_spacing, ccw) in;

in int tcBladeIndex[];

uniform mat4 uViewProj;
uniform int uShape;

out vec3 vPosition;
out vec3 vNormal;
out vec3 vUp;
out float vHeight;

void main() {
    Blade blade = blades[tcBladeIndex[0]];
    BladeSurfacePoint point = bladeSurface(blade, gl_TessCoord.x, gl_TessCoord.y, uShape);
    vPosition = point.position;
    vNormal = point.normal;
    vUp = blade.upS.xyz;
    vHeight = point.v;
    gl_Position = uViewProj * vec4(point.position, 1.0);
}
