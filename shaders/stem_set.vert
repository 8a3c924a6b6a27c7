#version 450 core
// Kim & Cho stem sets (SPEC §9), one instance per set: the template mesh has no vertex data,
// gl_VertexID names the stem, the sample along it and the side (editor/render/stem_set_gpu.h),
// and the set's parameters come from the instance SSBO.
#include "stem_set.glsl"

// STEM_SET_BINDING in editor/render/stem_set_gpu.h.
layout(std430, binding = 10) readonly buffer StemSetBuffer {
    StemSetInstance stemSets[];
};

#ifdef STEM_SET_CAPTURE
// Tests compare the geometry with the CPU reference (STEM_SET_CAPTURE_BINDING): per vertex,
// the world position and the world normal.
layout(std430, binding = 11) writeonly buffer StemSetCaptureBuffer {
    vec4 captured[];
};
#endif

// STEM_SET_VISIBLE_BINDING: the culled sets' indices (core::cullStemSets), one list per LOD,
// one draw per list; uVisibleFirst is where this draw's list starts.
layout(std430, binding = 12) readonly buffer StemSetVisibleBuffer {
    uint visibleSets[];
};

uniform mat4 uViewProj;
uniform int uLevels;  // 1..4
uniform int uSamplesPerLevel;  // core::STEM_SET_LOD_SAMPLES: 5 (full detail), 3 or 2
uniform int uUseVisible;       // 0: instance i is set i (no cull)
uniform uint uVisibleFirst;

out vec3 vPosition;
out vec3 vNormal;
out vec3 vUp;
out float vHeight;
flat out float vB;

void main() {
    int levels = clamp(uLevels, 1, MAX_STEM_LEVELS);
    int samplesPerLevel = clamp(uSamplesPerLevel, 2, STEM_SAMPLES_PER_LEVEL);
    int verticesPerStem = 2 * samplesPerLevel * levels;
    int stem = gl_VertexID / verticesPerStem;
    int sampleIndex = (gl_VertexID % verticesPerStem) / 2;
    int side = gl_VertexID % 2;
    int setIndex = uUseVisible != 0 ? int(visibleSets[uVisibleFirst + uint(gl_InstanceID)])
                                    : gl_InstanceID;
    StemSetInstance stemSet = stemSets[setIndex];
#ifndef STEM_SET_CAPTURE
    // A null set (its slot holds no blade: the density map removed it) collapses outside the
    // clip volume at once, so its triangles are dropped without evaluating the spline.
    if (!(stemSet.rootMetresPerUnit.w > 0.0)) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        vPosition = vNormal = vUp = vec3(0.0);
        vHeight = 0.0;
        vB = 0.0;
        return;
    }
#endif

    StemVertex v = stemRibbonVertex(stemSet, levels, samplesPerLevel, stem, sampleIndex, side);
    mat3 frame = stemSetFrame(stemSet.upYaw.xyz, stemSet.upYaw.w);
    vec3 position = stemSetWorldPosition(stemSet, frame, v.position);
    // The frame is a rotation and the scale uniform: it carries normals as it carries points.
    vNormal = frame * v.normal;
#ifdef STEM_SET_CAPTURE
    int slot = gl_InstanceID * STEMS_PER_SET * verticesPerStem + gl_VertexID;
    captured[2 * slot] = vec4(position, 1.0);
    captured[2 * slot + 1] = vec4(vNormal, 0.0);
#endif
    vUp = frame[1];
    vHeight = v.u;
    vB = stemSet.alphaBetaThetaB.w;
    vPosition = position;
    gl_Position = uViewProj * vec4(position, 1.0);
}
