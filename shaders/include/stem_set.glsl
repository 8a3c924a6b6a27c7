// Kim & Cho stem-set geometry (SPEC §9), the GLSL twin of core/growth/growth_stems.cpp: the same
// level-point formulas in the same order, the same clamped uniform B-spline by de Boor, the same
// ribbon; plus the model-to-world frame of editor/render/stem_set_gpu.h. Model frame: x across,
// y up, z the bend direction; one unit is metresPerUnit metres.

const int STEMS_PER_SET = 6;
const int MAX_STEM_LEVELS = 4;
const int STEM_SAMPLES_PER_LEVEL = 5;
// Root + MAX_STEM_LEVELS level points.
const int MAX_STEM_POINTS = MAX_STEM_LEVELS + 1;

// core::StemSetInstance: four vec4, 64 bytes, std430.
struct StemSetInstance {
    vec4 rootMetresPerUnit;  // root (world, m), metres per model unit
    vec4 upYaw;              // surface normal, yaw (radians)
    vec4 alphaBetaThetaB;    // growth parameters α, β, θ and colour blend b
    vec4 halfWidthSpread;    // ribbon half width, spreadX, spreadZ, width at the tip (share)
};

// Stem k's side (−1: stems 0–2, +1: stems 3–5), x spread and z spread (growth_stems.cpp
// stemLayout): the spreads grow with the rank within a side and z alternates, so no two stems
// of a set coincide.
vec3 stemLayout(int stem, float spreadX, float spreadZ) {
    int k = clamp(stem, 0, STEMS_PER_SET - 1);
    float side = k < 3 ? -1.0 : 1.0;
    float rank = float(k % 3);
    float zSign = (k % 2 == 0) ? 1.0 : -1.0;
    return vec3(side, side * spreadX * rank * 0.5, zSign * spreadZ * (rank + 1.0) / 3.0);
}

// The root and one point per level of stem `stem` (levels already clamped to 1..4); returns
// the number of points, levels + 1. β^i is the running product, as on the CPU.
int stemLevelPoints(float alpha, float beta, float theta, int levels, float spreadX,
                    float spreadZ, int stem, out vec3 points[MAX_STEM_POINTS]) {
    vec3 sideSpread = stemLayout(stem, spreadX, spreadZ);
    float c = cos(theta), s = sin(theta);
    points[0] = vec3(0.0);
    float y = 0.0, z = 0.0, betaPower = 1.0;
    for (int i = 1; i <= levels; ++i) {
        betaPower *= beta;
        float grown = y + betaPower;
        float nextY = grown * c - z * s;
        float nextZ = grown * s + z * c + sideSpread.z;
        y = nextY;
        z = nextZ;
        points[i] = vec3(sideSpread.x * alpha * 0.5 + sideSpread.y, y, z);
    }
    for (int i = levels + 1; i < MAX_STEM_POINTS; ++i)
        points[i] = points[levels];
    return levels + 1;
}

// Knot i of the clamped uniform knot vector of growth_stems.cpp: degree + 1 zeros, the interior
// steps 1/spans .. (spans − 1)/spans, degree + 1 ones. A formula instead of the CPU's array.
float clampedKnot(int i, int degree, int spans) {
    return clamp(float(i - degree) / float(spans), 0.0, 1.0);
}

// De Boor evaluation of the clamped uniform B-spline of degree min(3, n − 1) through the first
// n controls at u in [0, 1] (core::clampedBSpline). `tangent` gets the direction of the curve:
// the last de Boor step interpolates between two points, and the derivative is parallel to
// their difference.
vec3 clampedBSpline(vec3 controls[MAX_STEM_POINTS], int n, float u, out vec3 tangent) {
    tangent = vec3(0.0, 1.0, 0.0);
    if (n <= 1)
        return controls[0];
    int degree = min(3, n - 1);
    int spans = n - degree;
    u = clamp(u, 0.0, 1.0);
    int span = degree;
    while (span < n - 1 && u >= clampedKnot(span + 1, degree, spans))
        ++span;
    // Constant loop bounds, so the compiler can unroll to constant array indices: llvmpipe
    // (Mesa 22.3) lost the writes of the same loops bounded by `degree`.
    vec3 d[4];
    for (int j = 0; j <= 3; ++j)
        d[j] = controls[clamp(span - degree + j, 0, MAX_STEM_POINTS - 1)];
    for (int r = 1; r <= 3; ++r) {
        if (r > degree)
            break;
        if (r == degree)
            tangent = d[degree] - d[degree - 1];
        for (int j = 3; j >= 1; --j) {
            if (j < r || j > degree)
                continue;
            int i = span - degree + j;
            float left = clampedKnot(i, degree, spans);
            float right = clampedKnot(i + degree - r + 1, degree, spans);
            float a = right > left ? (u - left) / (right - left) : 0.0;
            d[j] = (1.0 - a) * d[j - 1] + a * d[j];
        }
    }
    return d[degree];
}

// Vertex `side` (0: −x, 1: +x) of sample `sampleIndex` of stem `stem` (core::stemRibbon), in
// the model frame, with the ribbon's normal (cross of the across direction x and the tangent; not
// yet turned to the viewer) and u, 0 at the root and 1 at the tip.
struct StemVertex {
    vec3 position;
    vec3 normal;
    float u;
};

// samplesPerLevel: STEM_SAMPLES_PER_LEVEL at full detail, fewer at a distance
// (core::STEM_SET_LOD_SAMPLES); the samples stay evenly spaced along the whole stem.
StemVertex stemRibbonVertex(StemSetInstance stemSet, int levels, int samplesPerLevel, int stem,
                            int sampleIndex, int side) {
    vec3 controls[MAX_STEM_POINTS];
    vec4 growth = stemSet.alphaBetaThetaB;
    vec4 shape = stemSet.halfWidthSpread;
    int n = stemLevelPoints(growth.x, growth.y, growth.z, levels, shape.y, shape.z, stem,
                            controls);
    int samples = samplesPerLevel * levels;
    StemVertex v;
    v.u = float(sampleIndex) / float(samples - 1);
    vec3 tangent;
    vec3 p = clampedBSpline(controls, n, v.u, tangent);
    // core::stemRibbon: 0 at the tip's share narrows to a point, 1 is the paper's constant width.
    float w = shape.x * (1.0 - (1.0 - shape.w) * v.u);
    v.position = vec3(side == 0 ? p.x - w : p.x + w, p.y, p.z);
    vec3 normal = cross(vec3(1.0, 0.0, 0.0), tangent);
    // With β = 0 and no z spread a stem lies flat along x (or is a point) and the cross
    // product vanishes: face the bend direction instead.
    v.normal = dot(normal, normal) > 1e-12 ? normalize(normal) : vec3(0.0, 0.0, 1.0);
    return v;
}

// stemSetFrame of editor/render/stem_set_gpu.h: columns are where model x, y, z go.
mat3 stemSetFrame(vec3 up, float yawRad) {
    float len = length(up);
    vec3 n = len > 1e-6 ? up / len : vec3(0.0, 1.0, 0.0);
    // Near ±z, cross(up, z) would shrink towards zero; x is then far from up.
    vec3 ref = abs(n.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = normalize(cross(n, ref));
    vec3 b = cross(t, n);
    float c = cos(yawRad), s = sin(yawRad);
    return mat3(c * t - s * b, n, s * t + c * b);
}

vec3 stemSetWorldPosition(StemSetInstance stemSet, mat3 frame, vec3 modelPoint) {
    return stemSet.rootMetresPerUnit.xyz + stemSet.rootMetresPerUnit.w * (frame * modelPoint);
}
