#version 450 core
// Tessellation path (Jahrmann §6): one patch vertex per blade; the blade index travels on.
out int vBladeIndex;

void main() {
    vBladeIndex = gl_VertexID;
}
