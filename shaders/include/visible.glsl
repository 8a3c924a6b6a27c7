// The visible-index lists the cull pass writes (SPEC §6, shaders/cull.comp): one list per level
// of detail, the draw of LOD k reads from uVisibleOffset = k · blade slots; entry i is the index
// of the i-th surviving blade of that LOD in the blade buffer.
layout(std430, binding = 5) readonly buffer VisibleBuffer {
    uint visible[];
};
uniform uint uVisibleOffset;

uint visibleBlade(int drawIndex) {
    return visible[uVisibleOffset + uint(drawIndex)];
}
