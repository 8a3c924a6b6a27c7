#version 450 core
// Tessellation path (Jahrmann §6): one patch vertex per surviving blade (the cull pass wrote the
// vertex count); the blade index, read through the visible list, travels on.
#include "visible.glsl"

out int vBladeIndex;

void main() {
    vBladeIndex = int(visibleBlade(gl_VertexID));
}
