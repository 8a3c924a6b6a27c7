#version 450 core
// The drift factor of every cell of the snow depth map (core::computeSnowDriftMap): D = 1 +
// drift·clamp(Sx / 20°, −1, 1), Sx the maximum upwind slope at the cell's centre
// (snowDriftShelterAngle, shaders/include/snow.glsl). Runs once a frame after the depth pass,
// only while the snow drifts; the snow surface and the cull read the cells bilinearly.
#include "snow.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) writeonly uniform image2D uDriftOut;

void main() {
    ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    int cells = uSnowResolution / SNOW_DRIFT_CELL_TEXELS;
    if (cell.x >= cells || cell.y >= cells)
        return;
    float sx = snowDriftShelterAngle(cell);
    float factor = 1.0 + uSnowDrift * clamp(sx / SNOW_DRIFT_REFERENCE_RAD, -1.0, 1.0);
    imageStore(uDriftOut, cell, vec4(factor, 0.0, 0.0, 0.0));
}
