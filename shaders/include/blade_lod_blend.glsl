// Continuous level of detail (issue 30 item 12), for the stages that place a blade's vertices
// (blade_strip.vert, blade.tese): a blade of LOD `lod` is drawn `morph` of the way (lod.glsl's
// lodMorph) towards the next LOD's surface, in position, normal and, lit per vertex, colour.
// The next LOD is the polyline of half the segments (params.level >> 1, at least 1: lodSegments
// of the next LOD for either path), folded or flat as lodFolded says, evaluated at its own rows
// and interpolated between them, as its triangles interpolate. A row the coarser blade shares
// moves onto its point; a row between two of its rows moves onto their chord; the midrib of a
// folded blade moves onto the middle of the flat blade's edges (a flat blade is linear across u,
// every shape and the width correction alike). At morph 1 every vertex lies on the coarser
// blade, with its colour, so the switch to it changes nothing.
// The blend is compiled in only with GRASS_LOD_BLEND, the program variant that draws the blades
// in a morph band (the cull lists them apart: core::lodBlending); without it every point is the
// fine one, for software GL runs the blend's extra evaluations whatever the blade.
#include "blade_geometry.glsl"
#include "blade_shade.glsl"
#include "lod.glsl"

struct BladeLodPoints {
    BladeSurfacePoint fine;   // this LOD's point
    BladeSurfacePoint below;  // the next LOD's row at or below v
    BladeSurfacePoint above;  // its row above v; unused where v lies on a row
    float between;            // 0 on the next LOD's row, ½ halfway to the one above
    float morph;
    bool sameAsFine;  // the next LOD's point is this one (a shared row of two flat blades)
};

BladeLodPoints bladeLodPoints(Blade blade, float u, float v, BladeShapeParams params, int lod,
                              float morph) {
    BladeLodPoints points;
    points.fine = bladeSurface(blade, u, v, params);
    points.below = points.fine;
    points.above = points.fine;
    points.between = 0.0;
    points.morph = morph;
    points.sameAsFine = true;
#ifdef GRASS_LOD_BLEND
    if (morph <= 0.0) return points;
    BladeShapeParams coarse = params;
    coarse.level = float(max(int(params.level + 0.5) >> 1, 1));
    coarse.folded = lodFolded(lod + 1);
    float x = v * coarse.level;
    float row = min(floor(x + 1e-3), coarse.level - 1.0);
    points.between = x - row < 1e-3 ? 0.0 : x - row;
    // Two flat blades share the coarser one's rows point for point, except the dandelion, whose
    // notches follow the level.
    points.sameAsFine = points.between == 0.0 && !params.folded && !coarse.folded &&
                        params.shape != SHAPE_DANDELION;
    if (points.sameAsFine) return points;
    points.below = bladeSurface(blade, u, row / coarse.level, coarse);
    if (points.between > 0.0)
        points.above = bladeSurface(blade, u, (row + 1.0) / coarse.level, coarse);
#endif
    return points;
}

// The drawn point: the fine point moved `morph` of the way onto the coarser blade.
BladeSurfacePoint blendedLodPoint(BladeLodPoints points) {
#ifndef GRASS_LOD_BLEND
    return points.fine;
#else
    if (points.sameAsFine) return points.fine;
    BladeSurfacePoint target = points.below;
    if (points.between > 0.0) {
        target.position = mix(points.below.position, points.above.position, points.between);
        target.normal = mix(points.below.normal, points.above.normal, points.between);
    }
    BladeSurfacePoint point = points.fine;
    point.position = mix(point.position, target.position, points.morph);
    point.normal = normalize(mix(point.normal, target.normal, points.morph));
    return point;
#endif
}

// Lit per vertex, the colour blends the same way: the coarser blade interpolates its rows'
// colours, so lighting the moved point alone would leave a step where the lighting is not
// linear (on a field of projects/nature's blades a third of the hard switch's change was left).
vec3 shadeBladeAtLod(BladeLodPoints points, vec3 up, uint bladeIndex) {
    vec3 colour = shadeBlade(points.fine.position, points.fine.normal, up, points.fine.v, bladeIndex);
#ifndef GRASS_LOD_BLEND
    return colour;
#else
    if (points.sameAsFine) return colour;
    vec3 coarse =
        shadeBlade(points.below.position, points.below.normal, up, points.below.v, bladeIndex);
    if (points.between > 0.0)
        coarse = mix(coarse, shadeBlade(points.above.position, points.above.normal, up,
                                        points.above.v, bladeIndex),
                     points.between);
    return mix(colour, coarse, points.morph);
#endif
}
