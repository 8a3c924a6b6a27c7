#version 450 core
// Kim & Cho stem sets (SPEC §9): opaque two-sided ribbons coloured between a poor (b = 0) and a
// healthy (b = 1) grass colour, root to tip, and lit like the blades and billboards.
#include "grass_lighting.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec3 vUp;
in float vHeight;
flat in float vB;

uniform vec3 uHealthyRoot;
uniform vec3 uHealthyTip;
uniform vec3 uPoorRoot;
uniform vec3 uPoorTip;

// SPEC §10 grass lighting (uGrassLighting 1; 0: the wrapped Lambert), as billboard.frag feeds
// it: a set stands for a few blades with no baked per-blade data, so it takes the field's mean
// AO and water (uFieldWater of the lighting block) and the surface normal as terrain and blurred
// normals.
uniform vec3 uCameraPosition;
uniform float uFieldAo;

out vec4 fragColor;

void main() {
    vec3 up = normalize(vUp);
    vec3 toEye = uCameraPosition - vPosition;
    float eyeDistance = length(toEye);
    toEye = eyeDistance > 0.0 ? toEye / eyeDistance : up;
    // Two-sided ribbons: light the side the viewer sees. The triangles' winding follows the
    // stem's bend, so gl_FrontFacing cannot tell the side; the view direction can.
    vec3 normal = normalize(vNormal);
    if (dot(normal, toEye) < 0.0)
        normal = -normal;
    float height = clamp(vHeight, 0.0, 1.0);
    vec3 root = mix(uPoorRoot, uHealthyRoot, vB);
    vec3 tip = mix(uPoorTip, uHealthyTip, vB);
    vec3 albedo = mix(root, tip, height);
    float sun = sunVisibility(vPosition);
    if (uGrassLighting == 0) {
        // A thin ribbon's normal is nearly horizontal, so a high sun would leave it black;
        // leaning it towards the surface normal lights it the way a field scatters.
        fragColor = vec4(simpleLightingShadowed(albedo, normalize(normal + 0.8 * up), 0.5, sun),
                         1.0);
        return;
    }
    GrassSurface surface;
    surface.albedo = albedo;
    surface.bladeNormal = normal;
    surface.terrainNormal = up;
    surface.blurredNormal = up;
    // The canopy above a point occludes it: roots darker than tips.
    surface.ao = mix(uFieldAo, 1.0, height * height);
    surface.water = uFieldWater;
    surface.height = height;
    surface.toEye = toEye;
    surface.eyeDistance = eyeDistance;
    surface.sunVisibility = sun;
    fragColor = vec4(grassLighting(surface), 1.0);
}
