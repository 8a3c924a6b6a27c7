// Quadratic Bézier of the blade (SPEC §1), the GLSL twin of core/blade/bezier.h.
vec3 bezierPoint(vec3 p0, vec3 p1, vec3 p2, float v) {
    float a = 1.0 - v;
    return a * a * p0 + 2.0 * a * v * p1 + v * v * p2;
}

vec3 bezierTangent(vec3 p0, vec3 p1, vec3 p2, float v) {
    return 2.0 * (1.0 - v) * (p1 - p0) + 2.0 * v * (p2 - p1);
}
