// The curve-and-shape evaluation both geometry paths share (SPEC §7): the tessellation
// evaluation shader and the instanced-strip vertex shader call bladeSurface with the same
// (u, v) and get the same point, so the two paths draw the same blade.
#ifndef GRASS_BLADE_GEOMETRY_GLSL
#define GRASS_BLADE_GEOMETRY_GLSL
#include "blade.glsl"
#include "bezier.glsl"
#include "shapes.glsl"

struct BladeSurfacePoint {
    vec3 position;
    vec3 normal;   // front side; the fragment shader flips it for back faces
    float v;       // 0 at the root, 1 at the tip
};

// What the shape needs besides the blade: the layer's shape id and τ, the vertices along v
// (both paths place them at v = i/level), and for the width correction the view-projection
// and the pixels a length of 1 covers at distance 1 (projection[1][1] · viewport height / 2;
// 0 turns the correction off), and whether the blade keeps its V fold (lodFolded: the near LODs).
struct BladeShapeParams {
    int shape;
    float tipStart;
    float level;
    mat4 viewProj;
    float pixelScale;
    bool folded;
};

BladeSurfacePoint bladeSurface(Blade blade, float u, float v, BladeShapeParams params) {
    vec3 v0 = blade.v0Theta.xyz;
    vec3 v1 = blade.v1H.xyz;
    vec3 v2 = blade.v2W.xyz;
    vec3 up = blade.upS.xyz;
    float w = blade.v2W.w;
    vec3 t1 = widthDirection(up, blade.v0Theta.w);
    vec3 c = bezierPoint(v0, v1, v2, v);
    vec3 tangent = bezierTangent(v0, v1, v2, v);
    vec3 n = cross(tangent, t1);
    n = dot(n, n) > 1e-20 ? normalize(n) : normalize(cross(up, t1));
    float t = shapeT(params.shape, u, v, params.tipStart, params.level);
    // Projected full width (2w) at the curve point; clip w is the view depth of a perspective
    // projection.
    float depth = (params.viewProj * vec4(c, 1.0)).w;
    float widthPx = params.pixelScale > 0.0 && depth > 0.0
                        ? 2.0 * w * params.pixelScale / depth
                        : -1.0;
    t = widthCorrectedT(t, u, widthPx);
    // V-shaped fold along the midrib (SPEC §7): at the root the mid line u = ½ stands w/2 off
    // the edges along n; towards the tip the edges rise to it. Both paths place a vertex column
    // at u = ½ so the V shows. A blade drawn without the fold (a far LOD) is flat between its
    // edges, which stay where the folded blade has them.
    float fold = params.folded ? 0.5 - abs(u - 0.5) * (1.0 - v) : 0.5 * v;
    // Each half faces away from the midrib: ∂p/∂u gains ±w(1 − v)·n against 2w·t1, which tilts
    // that half's normal by ∓½(1 − v)·t1; the midrib keeps n, so shading rounds over the V.
    float side = u < 0.5 ? 1.0 : (u > 0.5 ? -1.0 : 0.0);
    BladeSurfacePoint point;
    point.position = mix(c - w * t1, c + w * t1, t) + w * fold * n;
    point.normal = normalize(n - side * 0.5 * (1.0 - v) * t1);
    point.v = v;
    return point;
}
#endif
