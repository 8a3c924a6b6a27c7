// Level of detail by camera distance (SPEC §7), shared by the cull pass (which sorts survivors
// into one visible list and one indirect draw per LOD for the strips) and the tessellation
// control shader (which picks the level), so both paths bend the same polyline at a distance.
// LOD 0 up to lodDistance, LOD 1 up to 3·lodDistance, LOD 2 beyond; each halves the segments
// along the blade. lodDistance ≤ 0 keeps every blade at LOD 0.
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
