#version 450 core
// Tessellation evaluation: bend the unit quad (u, v) onto the blade curve (SPEC §7).
#include "blade_geometry.glsl"
#include "blade_shade.glsl"

layout(quads, equal_spacing, ccw) in;

in int tcBladeIndex[];

uniform float uWidthScale;  // 1; wider in the editor's thinned picture while the user interacts
uniform mat4 uViewProj;
uniform int uShape;
uniform float uTipStart;
uniform float uPixelScale;  // projection[1][1] · viewport height / 2; 0: no width correction

out vec3 vPosition;
out vec3 vNormal;
out vec3 vUp;
out float vHeight;
out vec3 vLitColor;
flat out uint vBladeIndex;

void main() {
    Blade blade = blades[tcBladeIndex[0]];
    blade.v2W.w *= uWidthScale;
    // The level along v (outer 0) places the vertices at v = i/level, as the strips' segments do.
    BladeShapeParams shape =
        BladeShapeParams(uShape, uTipStart, gl_TessLevelOuter[0], uViewProj, uPixelScale);
    BladeSurfacePoint point = bladeSurface(blade, gl_TessCoord.x, gl_TessCoord.y, shape);
    vPosition = point.position;
    vNormal = point.normal;
    vUp = blade.upS.xyz;
    vHeight = point.v;
    vBladeIndex = uint(tcBladeIndex[0]);
    vLitColor = uLightPerVertex != 0
                    ? shadeBlade(point.position, point.normal, vUp, point.v, vBladeIndex)
                    : vec3(0.0);
    gl_Position = uViewProj * vec4(point.position, 1.0);
}
