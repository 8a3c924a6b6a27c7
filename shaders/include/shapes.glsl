// Blade shape functions of SPEC §7: t(u, v) places a point of the unit quad between the two
// edges of the blade, c0 = c − w·t1 and c1 = c + w·t1. Shape ids match core's BladeShape.
#define SHAPE_QUAD 0
#define SHAPE_TRIANGLE 1
#define SHAPE_QUADRATIC 2
#define SHAPE_TRIANGLE_TIP 3

float shapeT(int shape, float u, float v, float tau) {
    if (shape == SHAPE_QUAD) return u;
    if (shape == SHAPE_QUADRATIC) return u - u * v * v;
    if (shape == SHAPE_TRIANGLE_TIP)
        return 0.5 + (u - 0.5) * (1.0 - max(v - tau, 0.0) / (1.0 - tau));
    return u + 0.5 * v - u * v;  // triangle
}
