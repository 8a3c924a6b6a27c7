#version 450 core
// The snow depth map (SPEC §11): the terrain and the props seen along the snowfall, orthographic.
// Depth is linear, metres from the view's near plane over its depth range, so the shaders read
// back metres as core::renderSnowDepthMap stores them.
layout(location = 0) in vec3 aPosition;

#include "snow_view_block.glsl"

uniform mat4 uModel;

void main() {
    vec3 d = (uModel * vec4(aPosition, 1.0)).xyz - uSnowOrigin;
    vec3 c = vec3(dot(d, uSnowRight) / uSnowSizeM, dot(d, uSnowUpAxis) / uSnowSizeM,
                  dot(d, uSnowForward) / uSnowDepthRangeM);
    gl_Position = vec4(c * 2.0 - 1.0, 1.0);
}
