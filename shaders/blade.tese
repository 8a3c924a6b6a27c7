#version 450 core
// Tessellation evaluation: bend the unit quad (u, v) onto the blade curve (SPEC §7).
#include "blade_lod_blend.glsl"

layout(quads, equal_spacing, ccw) in;

in int tcBladeIndex[];
patch in vec2 tcLodMorph;  // the blade's LOD and its morph towards the next (blade.tesc)

uniform float uWidthScale;  // 1; wider in the editor's thinned picture while the user interacts
uniform mat4 uViewProj;
uniform int uShape;
uniform float uTipStart;
uniform float uPixelScale;  // projection[1][1] · viewport height / 2; 0: no width correction

out vec3 vPosition;
out vec3 vNormal;
flat out vec3 vUp;
out float vHeight;
#ifdef GRASS_LIGHT_PER_VERTEX
out vec3 vLitColor;
#endif
flat out uint vBladeIndex;

void main() {
    Blade blade = fetchBlade(uint(tcBladeIndex[0]));
    blade.v2W.w *= uWidthScale;
    // The level along v (outer 0) places the vertices at v = i/level, as the strips' segments do.
    // Across, the control shader sets 1 for a blade without its fold; GL rounds the inner level
    // up to 2 all the same (an inner level of 1 next to outer levels above 1 counts as 1 + ε),
    // so the midrib column exists and the blade is flattened here instead.
    bool folded = gl_TessLevelOuter[1] > 1.5;
    BladeShapeParams shape = BladeShapeParams(uShape, uTipStart, gl_TessLevelOuter[0], uViewProj,
                                              uPixelScale, folded);
    BladeLodPoints points = bladeLodPoints(blade, gl_TessCoord.x, gl_TessCoord.y, shape,
                                           int(tcLodMorph.x + 0.5), tcLodMorph.y);
    BladeSurfacePoint point = blendedLodPoint(points);
    vPosition = point.position;
    vNormal = point.normal;
    vUp = blade.upS.xyz;
    vHeight = point.v;
    vBladeIndex = uint(tcBladeIndex[0]);
#ifdef GRASS_LIGHT_PER_VERTEX
    vLitColor = shadeBladeAtLod(points, vUp, vBladeIndex);
#endif
    gl_Position = uViewProj * vec4(point.position, 1.0);
}
