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

// Segments (strips) or tessellation level along v at a LOD: full, half, quarter, at least 1.
int lodSegments(int fullSegments, int lod) {
    return max(fullSegments >> lod, 1);
}
