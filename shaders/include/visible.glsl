// The visible-index list the cull pass writes (SPEC §6, shaders/cull.comp): entry k is the index
// of the k-th surviving blade in the blade buffer. The draws read blades through it.
layout(std430, binding = 5) readonly buffer VisibleBuffer {
    uint visible[];
};
