// The draw stages' view of the blade buffers: buffer textures read with texelFetch, where the
// cull and physics passes use the SSBOs of blade.glsl and cull.comp. Mesa's llvmpipe loads an
// SSBO element lane by lane, each component behind its own bounds check, while a texel fetch
// gathers a whole vec4 per lane; the blades of projects/nature drawn in full (398k blades, 36
// vertices each) took 2.43 s of vertex work through the SSBO and 0.97 s through texels
// (docs/rendering.md, "What a drawn blade costs"). Units: core/blade/blade_draw_commands.h.
#include "blade.glsl"
#ifndef GRASS_BLADE_TEXELS_GLSL
#define GRASS_BLADE_TEXELS_GLSL

layout(binding = 8) uniform samplerBuffer uBladeTexels;     // 4 RGBA32F texels per blade slot
layout(binding = 9) uniform usamplerBuffer uVisibleTexels;  // R32UI: the cull pass's lists
layout(binding = 10) uniform samplerBuffer uShadingTexels;  // 2 RGBA32F texels per blade slot
layout(binding = 11) uniform samplerBuffer uTipSnowTexels;  // R32F, bound while snow lies

Blade fetchBlade(uint index) {
    int first = 4 * int(index);
    return Blade(texelFetch(uBladeTexels, first), texelFetch(uBladeTexels, first + 1),
                 texelFetch(uBladeTexels, first + 2), texelFetch(uBladeTexels, first + 3));
}

// The visible-index lists the cull pass writes (SPEC §6, shaders/cull.comp): one list per level
// of detail; the draw of LOD k reads from uVisibleOffset = k · blade slots, and entry i is the
// index of the i-th surviving blade of that LOD in the blade buffer.
uniform uint uVisibleOffset;
// The draw of a LOD's blades in its morph band reads its list backwards from uVisibleOffset, the
// list's last entry (shaders/cull.comp lists them from the end).
uniform bool uVisibleBackwards;

uint visibleBlade(int drawIndex) {
    return texelFetch(uVisibleTexels, uVisibleBackwards ? int(uVisibleOffset) - drawIndex
                                                       : int(uVisibleOffset) + drawIndex).r;
}

// The blade draws go in batches of 64 blades an instance (strips: core/blade/strip_batch.h;
// patches: core::PATCH_BATCH_BLADES), so the last batch of a draw runs past its survivors. Those
// are its class's strip command's instance count, read from the command buffer the cull pass
// filled (word uSurvivorWord, core::stripSurvivorWord): a draw index at or beyond it is padding
// and draws nothing.
layout(binding = 14) uniform usamplerBuffer uCommandTexels;  // the command buffer, R32UI
uniform int uSurvivorWord;

bool listedInDraw(int drawIndex) {
    return uint(drawIndex) < texelFetch(uCommandTexels, uSurvivorWord).r;
}

// Per-blade lighting inputs baked when the scene is built (core/scene/blade_shading.h,
// SPEC §10): the Gaussian-blurred terrain normal and the grass AO from neighbour density, and
// the blade's water (young = wet). One entry per blade slot, same order as the blade buffer.
struct BladeShading {
    vec4 blurredNormalAo;  // xyz blurred terrain normal, w AO (1 = open)
    vec4 waterAge;         // x water, y age, z wilt (growth colour)
};

BladeShading fetchShading(uint index) {
    int first = 2 * int(index);
    return BladeShading(texelFetch(uShadingTexels, first), texelFetch(uShadingTexels, first + 1));
}

// Snow on the tips (SPEC §11): the whiteness of each drawn blade's tip, written by the cull pass.
float fetchTipSnow(uint index) {
    return texelFetch(uTipSnowTexels, int(index)).r;
}
#endif
