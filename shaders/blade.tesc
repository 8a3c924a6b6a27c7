#version 450 core
// Tessellation control: the level along the blade (v) comes from uTessLevel; across it (u)
// one segment is enough for a flat blade. Padding blades (h = 0) get level 0: discarded.
#include "blade.glsl"

layout(vertices = 1) out;

in int vBladeIndex[];
out int tcBladeIndex[];

uniform float uTessLevel;

void main() {
    tcBladeIndex[gl_InvocationID] = vBladeIndex[gl_InvocationID];
    float level = blades[vBladeIndex[0]].v1H.w > 0.0 ? uTessLevel : 0.0;
    // Quads domain: outer 0 and 2 are the u = 0 and u = 1 edges (along v), 1 and 3 along u.
    gl_TessLevelOuter[0] = level;
    gl_TessLevelOuter[1] = 1.0;
    gl_TessLevelOuter[2] = level;
    gl_TessLevelOuter[3] = 1.0;
    gl_TessLevelInner[0] = 1.0;
    gl_TessLevelInner[1] = level;
}
