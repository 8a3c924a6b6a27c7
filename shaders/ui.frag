#version 450 core
// One shader for every UI mesh: vertex colour times texture. The font atlas is an R8 texture
// swizzled to (c, c, c, c) for coverage c (premultiplied white), so untextured shapes (white
// texel) and glyphs need no branch.
// Textures hold premultiplied alpha, so the product stays premultiplied; blending is
// (ONE, ONE_MINUS_SRC_ALPHA) in sRGB space, without linearisation (see ui_renderer.h).
in vec2 vUv;
in vec4 vColor;

layout(binding = 0) uniform sampler2D uTexture;

out vec4 fragColor;

void main() {
    fragColor = vColor * texture(uTexture, vUv);
}
