// Blade shape functions of SPEC §7: t(u, v) places a point of the unit quad between the two
// edges of the blade, c0 = c − w·t1 and c1 = c + w·t1. Shape ids match core's BladeShape
// (core/blade/blade_shape.h).
#define SHAPE_QUAD 0
#define SHAPE_TRIANGLE 1
#define SHAPE_QUADRATIC 2
#define SHAPE_TRIANGLE_TIP 3
#define SHAPE_DANDELION 4

// Width correction of SPEC §7: below W_MIN_PX projected pixels a blade blends towards the quad
// over WIDTH_SPAN_PX pixels, so far blades keep covering pixels instead of aliasing away
// (core::WIDTH_CORRECTION_MIN_PX and _SPAN_PX, core::widthCorrectedT: the tested twin).
#define W_MIN_PX 1.0
#define WIDTH_SPAN_PX 2.0

const float SHAPE_PI = 3.14159265358979;
// How deep the dandelion's notches cut into the leaf, as a share of its local width.
const float DANDELION_NOTCH = 0.6;

// Dandelion leaf: t = 0.5 + (u − 0.5)·e(v)·(1 − k·n(v)), a symmetric outline whose relative
// width is an envelope e(v) with notches n(v) cut into it.
//   e(v) = clamp(0.25(1 − v) + 0.85 sin(πv), 0, 1): a narrow stalk at the root (0.25), widest
//          just past the middle, a pointed tip (e(1) = 0).
//   n(v) = 0.5 − 0.5 cos(π·level·v): 0 at even vertices v = 2j/level and 1 at odd ones, so with
//          vertices only at v = i/level (strip segments or tessellation level, equal spacing)
//          the outline alternates full width and a notch k = 0.6 deep at every vertex. The
//          spike count is therefore about level/2 per side, and spikes survive at low levels
//          (level 2: one notch and a point) instead of being averaged away between vertices.
float dandelionT(float u, float v, float level) {
    float envelope = clamp(0.25 * (1.0 - v) + 0.85 * sin(SHAPE_PI * v), 0.0, 1.0);
    float notch = 0.5 - 0.5 * cos(SHAPE_PI * max(level, 1.0) * v);
    return 0.5 + (u - 0.5) * envelope * (1.0 - DANDELION_NOTCH * notch);
}

// tau: the triangle-tip's τ in [0, 1); level: vertices along v (strip segments, tessellation
// level), which only the dandelion uses.
float shapeT(int shape, float u, float v, float tau, float level) {
    if (shape == SHAPE_QUAD) return u;
    if (shape == SHAPE_QUADRATIC) return u - u * v * v;
    if (shape == SHAPE_TRIANGLE_TIP)
        return 0.5 + (u - 0.5) * (1.0 - max(v - tau, 0.0) / (1.0 - tau));
    if (shape == SHAPE_DANDELION) return dandelionT(u, v, level);
    return u + 0.5 * v - u * v;  // triangle
}

// SPEC §7's blend towards the quad, Φ = 1 − clamp((wpx − w_min)/span, 0, 1), wpx the projected
// blade width in pixels, as t' = t + Φ·(u − t): at Φ = 1 both edges are the quad's (SPEC's
// max(t, Φ·u) moved the u = 1 edge alone and left a triangle a ¾-area trapezoid). A negative
// wpx means "unknown" and leaves the shape alone. core::widthCorrectedT is the twin.
float widthCorrectedT(float t, float u, float widthPx) {
    if (widthPx < 0.0) return t;
    float phi = 1.0 - clamp((widthPx - W_MIN_PX) / WIDTH_SPAN_PX, 0.0, 1.0);
    return t + phi * (u - t);
}
