// Snow accumulation, CPU reference (SPEC §11, paper 004 "A Study on Real-time Representation of
// Accumulated Snow", issue 9). The snow passes mirror these functions one for one, with the same
// names and the same float maths; the equations cite the paper ("eq. n" = its 식 n).
//
// Per surface point (world space, metres, unit-free coefficients in [0, 1]):
//   Fe  exposure (snow_map.h, eq. 1): how much of the sky along the fall direction it sees;
//   Fi  incline (eq. 2): less snow on steep faces, none on vertical ones and overhangs;
//   Fp = Fe·Fi (eq. 3), colour C = Fp·Cs + (1 − Fp)·Cn (eq. 3);
//   displacement Vn = V + As·Fe·Zn·up (eq. 5 raised against the fall, not along N: see
//   snowDisplacement), Fe taken over the boundary falloff (below).
// Beyond the paper: blades under snow deeper than they are tall are culled, exposed tips turn
// white, snow load adds gravity, and the amount grows and melts over time.
// Disabled snow or As = 0 gives exactly the snow-free colour and zero displacement.
#pragma once

#include <glm/glm.hpp>

#include "snow/snow_map.h"
#include "snow/snow_noise.h"
#include "snow/snow_params.h"

namespace grass::core {

// Upper part of a blade (fraction of its height, τ ∈ [1 − this, 1]) that snow on the tip whitens.
inline constexpr float SNOW_TIP_FRACTION = 0.3f;

// "Up" as the snow sees it: −normalize(fallDirection).
glm::vec3 snowUp(const SnowParams& params);

// The fractal noise of the snow at a point: fractalNoise(posWorld / noiseScaleM, noiseOctaves,
// noiseAmplitude, noiseFrequency) ∈ [−1, 1]. One value feeds both n of Fi and Zn of eq. 5, so
// thicker snow and whiter snow go together.
float snowNoiseAt(const SnowParams& params, glm::vec3 posWorld);

// Paper eq. 2: Fi = clamp(cos φ + n, 0, 1) with n = inclineNoise·noise, φ the angle between
// `normal` (any length > 0) and `up` (unit). φ ≥ 90° (cos φ ≤ 0) gives exactly 0 whatever the
// noise: the paper's two cases meet at 90°, and a vertical wall or an overhang holds no snow.
// The paper perturbs the normal with a noise vector; a scalar n added to cos φ is the same
// perturbation projected on `up`, and cheaper.
float inclineCoefficient(glm::vec3 normal, glm::vec3 up, float noise, float inclineNoise);

// Paper eq. 3: Fp = Fe·Fi ∈ [0, 1].
float snowCoverage(float Fe, float Fi);
// Paper eq. 3: C = Fp·Cs + (1 − Fp)·Cn; exactly Cn at Fp = 0.
glm::vec3 snowColor(glm::vec3 Cn, glm::vec3 Cs, float Fp);

// The smooth snow boundary (the paper's future work: a Gaussian at the boundary). Fe for the
// displacement is exposureCoefficient over a disc of radius max(sampleRadiusTexels,
// boundaryFalloffM / texelSizeM), passed through smoothstep(0, 1, ·). Across a straight shelter
// edge the disc's exposed share rises from 0 to 1 over 2·boundaryFalloffM with zero slope at
// both ends (the chord of the disc vanishes there); smoothstep flattens the ends further, so the
// snow surface rises like an erf-shaped drift instead of a cliff.
float snowBoundaryExposure(const SnowDepthMap& map, glm::vec3 posWorld, glm::vec3 normal,
                           const SnowParams& params);

// Zn of eq. 5: 0.5 + 0.5·noise ∈ [0, 1], so snow never digs below the surface.
float snowHeightNoise(float noise);

// Paper eq. 5, raised against the fall instead of along the normal: As·Fe·D·Zn·snowUp, Zn =
// snowHeightNoise(snowNoiseAt(posWorld)). The paper moves each vertex along its normal; where
// normals converge (every valley, every rock's foot) deep snow then folds the surface over
// itself and its back faces show as black slivers, and rocks swell into blobs (projects/winter
// at 0.87 m, issue 30 item 8). Snow piles up under gravity: a surface raised along one
// direction stays a height field over that direction and cannot fold. `normal` is unused (the
// exposure Fe was taken with it); the signature is kept for the callers.
// Fe: snowBoundaryExposure; D: the wind's drift factor there (snow_drift.h; 1 without drift).
// As is params.amountM: with --time, pass params whose amountM is snowAmountAt(params, t). Zero
// vector when disabled or As = 0.
glm::vec3 snowDisplacement(glm::vec3 posWorld, glm::vec3 normal, float Fe,
                           const SnowParams& params, float drift = 1.0f);

// Local snow depth in metres: |snowDisplacement| = As·Fe·D·Zn (0 when disabled).
float snowDepthAt(glm::vec3 posWorld, float Fe, const SnowParams& params, float drift = 1.0f);

// A blade shorter than the snow at its root is buried: culled (h < depth; a blade exactly as
// tall as the snow shows its tip).
bool bladeBuriedBySnow(float heightM, float snowDepthM);

// Whiteness of an exposed blade tip, 0..1: the exposure of the tip (exposureCoefficient at the
// tip, normal = snowUp) while snow lies (enabled, As > 0), else 0.
float bladeTipSnow(float tipFe, const SnowParams& params);
// The tip snow along the blade: tipSnow·smoothstep(1 − SNOW_TIP_FRACTION, 1, τ), τ = 0 root,
// 1 tip. The blade colour is snowColor(bladeColour, Cs, this).
float bladeSnowWhiteness(float tipSnow, float tau);

// Extra downward acceleration (m/s²) on a blade from the snow it carries: loadGravity·depth·Fe,
// added to |gE| along the gravity direction; 0 when disabled. depth: snowDepthAt the root,
// Fe: the tip's exposure (a sheltered blade carries no load).
float snowLoadGravity(const SnowParams& params, float snowDepthM, float Fe);

// As(t) = clamp(As + (accumulationRate − meltRate)·t, 0, maxAmountM); t < 0 counts as 0.
// Constant rates keep it closed-form, so any frame of --time is reproducible without history.
float snowAmountAt(const SnowParams& params, float timeS);

// Everything the surface pass computes at one point, for tests and the reference renderer.
struct SnowShade {
    float Fi = 0.0f;
    float Fp = 0.0f;
    glm::vec3 color{0.0f};
    glm::vec3 displacement{0.0f};
};
// Fe: exposureCoefficient; FeBoundary: snowBoundaryExposure; Cn: the snow-free colour; drift:
// D (snow_drift.h), which scales the depth and, up to 1, the coverage: Fp = Fe·Fi·min(D, 1).
SnowShade shadeSnow(const SnowParams& params, glm::vec3 posWorld, glm::vec3 normal, float Fe,
                    float FeBoundary, glm::vec3 Cn, float drift = 1.0f);

}  // namespace grass::core
