#version 450 core
// Tessellation control (Jahrmann §6): the level along the blade (v) follows the camera distance
// with the same LOD steps the strips use (lod.glsl); across it (u) two segments put a vertex
// column on the midrib for the V fold of SPEC §7; beyond FOLDED_LODS one segment, which tells the
// evaluation shader to draw the blade flat, as the strips draw it by its edges alone. Padding
// blades (h = 0) and the patches of a batch past the draw's survivors (index -1,
// blade_tess.vert) get level 0: discarded.
#include "blade_texels.glsl"
#include "lod.glsl"

layout(vertices = 1) out;

in int vBladeIndex[];
out int tcBladeIndex[];
// The blade's LOD and how far it has morphed towards the next (lod.glsl's lodMorph).
patch out vec2 tcLodMorph;

uniform float uTessLevel;
uniform vec3 uCameraPosition;
uniform float uLodDistance;
uniform float uLodBlend;  // 0: LODs switch hard

void main() {
    int index = vBladeIndex[0];
    tcBladeIndex[gl_InvocationID] = index;
    if (index < 0) {
        tcLodMorph = vec2(0.0);
        gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = 0.0;
        gl_TessLevelOuter[3] = gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
        return;
    }
    Blade blade = fetchBlade(uint(index));
    float toCamera = distance(blade.v0Theta.xyz, uCameraPosition);
    int lod = bladeLod(toCamera, uLodDistance);
#ifdef GRASS_LOD_BLEND
    tcLodMorph = vec2(float(lod), lodMorph(toCamera, uLodDistance, lod, uLodBlend));
#else
    tcLodMorph = vec2(float(lod), 0.0);  // this draw's blades lie before their LOD's morph band
#endif
    float level = blade.v1H.w > 0.0 ? float(lodSegments(int(uTessLevel), lod)) : 0.0;
    // Quads domain: outer 0 and 2 are the u = 0 and u = 1 edges (along v), 1 and 3 along u.
    float across = lodFolded(lod) ? 2.0 : 1.0;
    gl_TessLevelOuter[0] = level;
    gl_TessLevelOuter[1] = across;
    gl_TessLevelOuter[2] = level;
    gl_TessLevelOuter[3] = across;
    gl_TessLevelInner[0] = across;
    gl_TessLevelInner[1] = level;
}
