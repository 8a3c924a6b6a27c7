// Per-blade cull rules of SPEC §6 that are plain formulas, shared by cull.comp and the GL test
// that runs them against their C++ twin (core/scene/cull_rules.h, same names).
#ifndef GRASS_CULL_RULES_GLSL
#define GRASS_CULL_RULES_GLSL

// |cos| of the angle between view and width direction beyond which a blade is seen edge-on
// (SPEC §6's 0.9, about 25.8° from edge-on). core::ORIENTATION_CULL_COS mirrors it.
const float ORIENTATION_CULL_COS = 0.9;

// Orientation: a blade seen edge-on is thinner than a pixel and only aliases. Both unit length.
bool seenEdgeOn(vec3 dirView, vec3 dirWidth) {
    return abs(dot(dirView, dirWidth)) > ORIENTATION_CULL_COS;
}

// dproj: the distance from the camera to the blade's root across the blade's unit up, so that
// a blade straight below the camera counts as near.
float projectedDistance(vec3 toBlade, vec3 up) {
    return length(toBlade - up * dot(toBlade, up));
}

// Distance: thin the field towards maxDistance by keeping fewer of n classes (i mod n). Of each
// n blades, ceil(n·max(1 − dproj/maxDistance, 0)) are kept: all n at the camera, at least one
// until maxDistance itself, none beyond.
uint distanceKeptCount(uint classes, float dproj, float maxDistance) {
    float n = float(classes);
    return uint(ceil(n * max(1.0 - dproj / maxDistance, 0.0)));
}

bool keptByDistance(uint index, uint classes, float dproj, float maxDistance) {
    return index % classes < distanceKeptCount(classes, dproj, maxDistance);
}

#endif
