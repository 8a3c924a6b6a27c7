// The place of this work group in a pass dispatched as a grid of groups (core/util/
// dispatch_grid.h, dispatchGrid): rows of gl_NumWorkGroups.x groups, one after the other.
// Included after the shader's local_size layout (gl_WorkGroupSize is declared by it).
#ifndef GRASS_DISPATCH_GRID_GLSL
#define GRASS_DISPATCH_GRID_GLSL

uint workGroupInPass() {
    return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
}

// The item of this invocation: its group's first item plus its place in the group.
uint invocationInPass() {
    return workGroupInPass() * gl_WorkGroupSize.x + gl_LocalInvocationIndex;
}

#endif
