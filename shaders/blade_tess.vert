#version 450 core
// Tessellation path (Jahrmann §6): one single-vertex patch per surviving blade, drawn as one
// instance per blade (the cull pass wrote the instance count); the blade index, read through
// the visible list, travels on. Instanced rather than one patch list of N vertices: Mesa's
// llvmpipe drew long patch lists wrongly (regions missing, streaks between far blades, beyond
// ~10k patches at level 8) and 6× slower; tests/gl/lod_gl_test.cpp guards it.
#include "blade_texels.glsl"

out int vBladeIndex;

void main() {
    vBladeIndex = int(visibleBlade(gl_InstanceID));
}
