// Level of detail by camera distance (SPEC §7), shared by the cull pass (which sorts survivors
// into one visible list and one indirect draw per LOD for the strips) and the tessellation
// control shader (which picks the level), so both paths bend the same polyline at a distance.
// LOD 0 up to lodDistance, LOD 1 up to 3·lodDistance, LOD 2 beyond; each halves the segments
// along the blade. lodDistance ≤ 0 keeps every blade at LOD 0.
// Included by blade_lod_blend.glsl and by the stages that include it: defined once.
#ifndef GRASS_LOD_GLSL
#define GRASS_LOD_GLSL
#define LOD_COUNT 3

int bladeLod(float distance, float lodDistance) {
    if (lodDistance <= 0.0 || distance < lodDistance) return 0;
    return distance < 3.0 * lodDistance ? 1 : 2;
}

// The LODs, from the nearest, that keep the vertex column on the midrib, so the V fold of SPEC §7
// shows (core::FOLDED_LODS). Beyond the LOD distance a blade is a few pixels wide and its fold
// cannot be seen; its two edges alone draw it, with half the triangles (on software GL the grass
// pass is bound by triangle setup and rasterization, not by the fragments: docs/rendering.md).
#define FOLDED_LODS 1

bool lodFolded(int lod) {
    return lod < FOLDED_LODS;
}

// Segments (strips) or tessellation level along v at a LOD: full, half, quarter, at least 1.
int lodSegments(int fullSegments, int lod) {
    return max(fullSegments >> lod, 1);
}

// The share of each LOD's distance range over which its blades morph into the next LOD's
// shape (core::LOD_BLEND; RenderOptions::lodBlend, `grass render --lod-blend`).
#define LOD_BLEND 0.25

// Continuous level of detail (issue 30 item 12): over the last `blend` share of its distance
// range (LOD 0: [0, d), LOD 1: [d, 3d)) a blade of LOD k moves linearly towards LOD k + 1's
// surface (blade_lod_blend.glsl), 0 at the band's start, 1 at the switch,
// where the two LODs therefore draw the same blade and nothing pops. 0 for the last LOD, without
// LODs (lodDistance ≤ 0) and with blend ≤ 0 (the hard switches of before). core::lodMorph is the
// tested twin.
float lodMorph(float distance, float lodDistance, int lod, float blend) {
    if (lodDistance <= 0.0 || blend <= 0.0 || lod >= LOD_COUNT - 1) return 0.0;
    float start = lod == 0 ? 0.0 : lodDistance;
    float end = lod == 0 ? lodDistance : 3.0 * lodDistance;
    float band = min(blend, 1.0) * (end - start);
    return clamp((distance - (end - band)) / band, 0.0, 1.0);
}
#endif
