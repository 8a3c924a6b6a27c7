#version 450 core
// Instanced-strip path (SPEC §7): a blade's strip per level of detail, drawn STRIP_BATCH_BLADES
// blades to an instance (below). Up to
// FOLDED_LODS (lod.glsl) a triangle strip of 4·(uSegments + 1) vertices: the left half (u = 0,
// ½) from root to tip, then the right half (u = 1, ½) from tip to root, so the midrib is a
// vertex column and the V fold shows; the turn at the tip adds two zero-area triangles (all
// three tip points lie on one line). Beyond, 2·(uSegments + 1) vertices of the two edges (u = 0,
// 1) from root to tip: the outline alone. The curve is evaluated here; instances are read
// through the visible list.
// GRASS_LIGHT_PER_VERTEX (a program variant, not a uniform: llvmpipe runs both sides of a
// uniform branch, and the unused per-vertex lighting cost 0.67 s of the 1.7 s that every blade
// of projects/nature drawn in full took) lights each vertex and hands the colour on.
#include "blade_lod_blend.glsl"

uniform mat4 uViewProj;
uniform int uSegments;
uniform int uLod;  // this draw's level of detail
uniform int uShape;
uniform float uTipStart;
uniform float uPixelScale;  // projection[1][1] · viewport height / 2; 0: no width correction
uniform float uWidthScale;  // 1; wider in the editor's thinned picture while the user interacts
// The blend towards the next LOD (lod.glsl's lodMorph): the LOD distance the cull pass sorted
// by (from uCameraPosition, blade_shade.glsl's), and the band's share; 0 switches LODs hard.
uniform float uLodDistance;
uniform float uLodBlend;

out vec3 vPosition;
out vec3 vNormal;
flat out vec3 vUp;
out float vHeight;
#ifdef GRASS_LIGHT_PER_VERTEX
out vec3 vLitColor;
#endif
flat out uint vBladeIndex;

// Strip batches (core/blade/strip_batch.h): an instance draws STRIP_BATCH_BLADES blades of the
// LOD's visible list as indexed triangles, vertex id b · (strip vertices) + j being vertex j of
// the batch's blade b. The blades of the last batch beyond the draw's survivors draw nothing
// (blade_texels.glsl's listedInDraw).
#define STRIP_BATCH_BLADES 64

void main() {
    bool folded = lodFolded(uLod);
    int stripVertices = (folded ? 4 : 2) * (uSegments + 1);  // core::stripVertexCount
    int batchBlade = gl_VertexID / stripVertices;
    int stripVertex = gl_VertexID - batchBlade * stripVertices;
    int drawIndex = gl_InstanceID * STRIP_BATCH_BLADES + batchBlade;
    if (!listedInDraw(drawIndex)) {
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);  // beyond the far plane: clipped
        return;
    }
    uint bladeIndex = visibleBlade(drawIndex);
    Blade blade = fetchBlade(bladeIndex);
    blade.v2W.w *= uWidthScale;
    int halfVertices = 2 * (uSegments + 1);
    int row;
    float u;
    if (!folded) {
        // Same winding as the folded halves: (row, u = 0), (row, u = 1), (row + 1, u = 0), …
        row = stripVertex >> 1;
        u = float(stripVertex & 1);
    } else if (stripVertex < halfVertices) {
        row = stripVertex >> 1;
        u = (stripVertex & 1) != 0 ? 0.5 : 0.0;
    } else {
        // Winding stays counter-clockwise in (u, v): outer edge first on the way down.
        int j = stripVertex - halfVertices;
        row = uSegments - (j >> 1);
        u = (j & 1) != 0 ? 0.5 : 1.0;
    }
    float v = float(row) / float(uSegments);
    BladeShapeParams shape =
        BladeShapeParams(uShape, uTipStart, float(uSegments), uViewProj, uPixelScale, folded);
#ifdef GRASS_LOD_BLEND
    float morph =
        lodMorph(distance(blade.v0Theta.xyz, uCameraPosition), uLodDistance, uLod, uLodBlend);
#else
    float morph = 0.0;  // this draw's blades lie before their LOD's morph band
#endif
    BladeLodPoints points = bladeLodPoints(blade, u, v, shape, uLod, morph);
    BladeSurfacePoint point = blendedLodPoint(points);
    // Padding blades (h = 0) collapse to a point and produce no fragments.
    if (blade.v1H.w <= 0.0) point.position = blade.v0Theta.xyz;
    vPosition = point.position;
    vNormal = point.normal;
    vUp = blade.upS.xyz;
    vHeight = v;
    vBladeIndex = bladeIndex;
#ifdef GRASS_LIGHT_PER_VERTEX
    vLitColor = shadeBladeAtLod(points, vUp, bladeIndex);
#endif
    gl_Position = uViewProj * vec4(point.position, 1.0);
}
