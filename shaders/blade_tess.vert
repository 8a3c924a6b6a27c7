#version 450 core
// Tessellation path (Jahrmann §6): one single-vertex patch per surviving blade, PATCH_BATCH_BLADES
// patches an instance (core::PATCH_BATCH_BLADES says why; the cull pass wrote the instance
// count, the draw's batches); the blade index, read through the visible list, travels on, -1 for
// the last batch's patches past the draw's survivors (blade.tesc discards them). Batches rather
// than one patch list of N vertices: Mesa's llvmpipe drew long patch lists wrongly (regions
// missing, streaks between far blades, beyond ~10k patches at level 8) and 6× slower;
// tests/gl/lod_gl_test.cpp guards it.
#include "blade_texels.glsl"

#define PATCH_BATCH_BLADES 64

out int vBladeIndex;

void main() {
    int drawIndex = gl_InstanceID * PATCH_BATCH_BLADES + gl_VertexID;
    vBladeIndex = listedInDraw(drawIndex) ? int(visibleBlade(drawIndex)) : -1;
}
