#version 450 core
// The cull's depth pre-pass (render/cull_pass.cpp): the opaque surfaces' depth alone. An empty
// fragment stage lets a software rasterizer skip the shading (the lit mesh.frag, with the snow's
// per-pixel exposure, cost the winter frame's pre-pass 110 ms on llvmpipe) and drops every
// varying but the position.
void main() {}
