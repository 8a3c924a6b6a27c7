// The bending cues of SPEC §10 (issue 30 item 1): each cue's formula at a point, the neighbour
// shade against its closed form on a lattice, the cues off growing blades bit for bit as before,
// and the article's claim that sway grows with a vertex's height.
#include "scene/bending_cues.h"

#include <gtest/gtest.h>

#include <cstring>

#include <cmath>

#include "blade/bezier.h"
#include "mesh/procedural.h"
#include "physics/physics.h"
#include "physics/wind.h"
#include "scene/layer_growth.h"

namespace grass::core {
namespace {

constexpr float PI = 3.14159265358979f;
constexpr float DEG = PI / 180.0f;

float angleBetween(glm::vec3 a, glm::vec3 b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f));
}

// The normal of ground sloping `slopeDeg` from level, falling towards +x.
glm::vec3 slopeNormal(float slopeDeg) {
    return glm::vec3(std::sin(slopeDeg * DEG), std::cos(slopeDeg * DEG), 0.0f);
}

Blade candidateOn(glm::vec3 normal, float theta, glm::vec3 v0 = glm::vec3(0.0f)) {
    return makeRestBlade(v0, normal, 0.4f, 0.02f, 60.0f, theta);
}

// The tip's lean from up and the unit direction of its sideways part.
float leanOf(const Blade& b) { return angleBetween(b.v2() - b.v0(), b.up()); }
glm::vec3 sidewaysOf(const Blade& b) {
    const glm::vec3 d = b.v2() - b.v0();
    return glm::normalize(d - glm::dot(d, b.up()) * b.up());
}

TEST(BendingCues, SlopeLeansEveryBladeDownhillByItsShareOfTheSlope) {
    BendingCues cues;
    cues.slope = 0.5f;
    const glm::vec3 normal = slopeNormal(40.0f);
    const glm::vec3 downhill = glm::normalize(glm::vec3(std::cos(40.0f * DEG), -std::sin(40.0f * DEG), 0.0f));
    // Fronts facing uphill, downhill and across: every blade ends up leaning downhill.
    for (const float theta : {0.0f, 1.0f, 2.5f, 4.0f, 5.5f}) {
        const Blade c = candidateOn(normal, theta);
        const CandidateBend bend = candidateBend(cues, c, 0.0f, RuleWorld{});
        EXPECT_NEAR(bend.leanRad, 20.0f * DEG, 1e-5f);
        EXPECT_NEAR(glm::length(bend.downhill - downhill), 0.0f, 1e-5f);
        const Blade bent = bentRestBlade(c, c.h(), c.w(), 0.0f, bend, 0.0f);
        EXPECT_NEAR(leanOf(bent), 20.0f * DEG, 1e-3f) << "theta " << theta;
        // Turned by π at most, the width axis stays the candidate's (the front is what turns).
        EXPECT_GT(glm::dot(sidewaysOf(bent), downhill), std::cos(90.0f * DEG)) << "theta " << theta;
        EXPECT_NEAR(std::abs(glm::dot(widthDirection(normal, bent.theta()),
                                      widthDirection(normal, theta))),
                    1.0f, 1e-5f);
        EXPECT_EQ(bent.s(), c.s());  // no sway asked for
        // Validation keeps the blade's length (its estimate, SPEC §3) at h.
        EXPECT_NEAR(bezierLengthEstimate(bent.v0(), bent.v1(), bent.v2()), c.h(), 1e-3f * c.h());
    }
}

TEST(BendingCues, SlopeFollowsCentreGravityOnAPlanet) {
    BendingCues cues;
    cues.slope = 1.0f;
    RuleWorld planet;
    planet.gravity = glm::vec4(0.0f, 0.0f, 0.0f, 9.81f);
    planet.gravityMode = GravityMode::Centre;
    // On the planet's side (+x), ground tilted 30° from the radial up.
    const glm::vec3 radial(1.0f, 0.0f, 0.0f);
    const glm::vec3 normal(std::cos(30.0f * DEG), std::sin(30.0f * DEG), 0.0f);
    const Blade c = candidateOn(normal, 0.7f, 10.0f * radial);
    const CandidateBend bend = candidateBend(cues, c, 0.0f, planet);
    EXPECT_NEAR(bend.leanRad, 30.0f * DEG, 1e-4f);
    // Downhill points towards the centre's side of the tangent plane (down along -radial).
    EXPECT_LT(glm::dot(bend.downhill, radial), 0.0f);
    EXPECT_NEAR(glm::dot(bend.downhill, normal), 0.0f, 1e-5f);
}

TEST(BendingCues, LevelGroundAndCuesOffLeaveTheBladeAsItWas) {
    const Blade c = candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 1.3f, glm::vec3(2.0f, 0.5f, -1.0f));
    BendingCues cues;
    cues.slope = 1.0f;
    const CandidateBend bend = candidateBend(cues, c, 0.0f, RuleWorld{});
    EXPECT_EQ(bend.leanRad, 0.0f);
    EXPECT_EQ(bend.downhill, glm::vec3(0.0f));
    EXPECT_EQ(bentRestBlade(c, c.h(), c.w(), 0.0f, bend, 0.0f), c);
    EXPECT_TRUE(bendingIsOff(BendingCues{}));
    EXPECT_FALSE(bendingIsOff(cues));
    ScatterCandidates candidates;
    candidates.blades = {c, c};
    EXPECT_TRUE(candidateBends(BendingCues{}, candidates, {}, RuleWorld{}).empty());
}

TEST(BendingCues, NeighbourLeanIsTheShareOfTheShade) {
    BendingCues cues;
    cues.neighboursDeg = 30.0f;
    const Blade c = candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 0.4f);
    const CandidateBend bend = candidateBend(cues, c, 0.5f, RuleWorld{});
    EXPECT_NEAR(bend.leanRad, 15.0f * DEG, 1e-6f);
    EXPECT_EQ(bend.downhill, glm::vec3(0.0f));
    const Blade bent = bentRestBlade(c, c.h(), c.w(), 0.0f, bend, 0.0f);
    EXPECT_NEAR(leanOf(bent), 15.0f * DEG, 1e-3f);
    // Towards the blade's front: the side front gravity pulls it to.
    const glm::vec3 front = glm::cross(c.up(), widthDirection(c.up(), c.theta()));
    EXPECT_GT(glm::dot(sidewaysOf(bent), glm::normalize(front)), 0.999f);
}

TEST(BendingCues, TheLeansAddUpToTheGrowthModelsBound) {
    BendingCues cues;
    cues.neighboursDeg = 40.0f;
    const Blade c = candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 0.0f);
    const CandidateBend bend = candidateBend(cues, c, 1.0f, RuleWorld{});
    EXPECT_NEAR(leanOf(bentRestBlade(c, c.h(), c.w(), 10.0f * DEG, bend, 0.0f)), 50.0f * DEG, 1e-3f);
    EXPECT_NEAR(leanOf(bentRestBlade(c, c.h(), c.w(), 35.0f * DEG, bend, 0.0f)), 60.0f * DEG, 1e-3f);
}

TEST(BendingCues, SwayLowersTheStiffnessOfLeaningBladesOnly) {
    const Blade c = candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 0.0f);
    CandidateBend bend;
    bend.leanRad = 30.0f * DEG;
    EXPECT_NEAR(bentRestBlade(c, c.h(), c.w(), 0.0f, bend, 0.5f).s(), c.s() * 0.75f, 1e-4f);
    EXPECT_NEAR(bentRestBlade(c, c.h(), c.w(), 0.0f, bend, 1.0f).s(), c.s() * 0.5f, 1e-4f);
    EXPECT_EQ(bentRestBlade(c, c.h(), c.w(), 0.0f, CandidateBend{}, 1.0f).s(), c.s());
}

// Roots on a square lattice of `perM2` blades per m² over [-half, half]², every blade of
// height h except the centre one (the first), of height centreH.
ScatterCandidates lattice(float perM2, float half, float h, float centreH) {
    ScatterCandidates candidates;
    const float spacing = 1.0f / std::sqrt(perM2);
    const int n = static_cast<int>(half / spacing);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    candidates.blades.push_back(makeRestBlade(glm::vec3(0.0f), up, centreH, 0.01f, 50.0f, 0.0f));
    for (int z = -n; z <= n; ++z)
        for (int x = -n; x <= n; ++x)
            if (x != 0 || z != 0)
                candidates.blades.push_back(makeRestBlade(
                    glm::vec3(static_cast<float>(x) * spacing, 0.0f, static_cast<float>(z) * spacing), up, h, 0.01f, 50.0f, 0.0f));
    return candidates;
}

TEST(BendingCues, ShadeOnALatticeIsTheClosedForm) {
    // The Gaussian's sum over a lattice much finer than σ is its integral, ρ, less the blade
    // itself and the tail beyond 3σ: ρ = n·(1 − e^−4.5) − 1/(2πσ²).
    const float sigma = 0.15f;
    for (const float perM2 : {100.0f, 300.0f}) {
        const ScatterCandidates candidates = lattice(perM2, 0.6f, 0.4f, 0.4f);
        const std::vector<float> shade = neighbourShade(candidates, {}, sigma);
        const float rho = perM2 * (1.0f - std::exp(-4.5f)) - 1.0f / (2.0f * PI * sigma * sigma);
        EXPECT_NEAR(shade[0], 1.0f - std::exp(-NEIGHBOUR_CROSS_SECTION_M2 * rho), 0.005f)
            << perM2 << " per m²";
    }
}

TEST(BendingCues, ShadeGrowsWithDensityAndNeighbourHeightAndIsZeroAlone) {
    const float sigma = 0.15f;
    const auto centre = [&](float perM2, float h, float centreH) {
        return neighbourShade(lattice(perM2, 0.6f, h, centreH), {}, sigma)[0];
    };
    EXPECT_LT(centre(50.0f, 0.4f, 0.4f), centre(100.0f, 0.4f, 0.4f));
    EXPECT_LT(centre(100.0f, 0.4f, 0.4f), centre(300.0f, 0.4f, 0.4f));
    EXPECT_LT(centre(100.0f, 0.2f, 0.4f), centre(100.0f, 0.4f, 0.4f));  // shorter neighbours
    EXPECT_LT(centre(100.0f, 0.4f, 0.4f), centre(100.0f, 0.8f, 0.4f));  // taller neighbours
    // Beyond twice the blade's height a neighbour shades no more.
    EXPECT_FLOAT_EQ(centre(100.0f, 0.8f, 0.4f), centre(100.0f, 2.0f, 0.4f));

    ScatterCandidates alone;
    alone.blades = {candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 0.0f),
                    candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 0.0f, glm::vec3(5.0f, 0.0f, 0.0f))};
    const std::vector<float> apart = neighbourShade(alone, {}, sigma);
    EXPECT_EQ(apart[0], 0.0f);
    EXPECT_EQ(apart[1], 0.0f);

    // Neighbours the placement rules remove shade nobody.
    const ScatterCandidates dense = lattice(300.0f, 0.6f, 0.4f, 0.4f);
    std::vector<float> removed(dense.blades.size(), 0.0f);
    EXPECT_EQ(neighbourShade(dense, removed, sigma)[0], 0.0f);
}

// After some candidates' rule factors changed (a collider moved), the shade of those within
// reach of them, made again alone, is bit for bit what the whole field's shade gives; the rest
// is as before.
TEST(BendingCues, ShadeAroundChangedCandidatesIsTheWholeFieldsShade) {
    const float sigma = 0.1f;
    const ScatterCandidates field = lattice(300.0f, 2.0f, 0.4f, 0.4f);
    std::vector<float> before(field.blades.size(), 1.0f);
    std::vector<float> after = before;
    std::vector<std::uint32_t> changed;
    for (std::uint32_t i = 0; i < field.blades.size(); ++i)
        if (glm::length(field.blades[i].v0() - glm::vec3(0.5f, 0.0f, 0.3f)) < 0.25f) {
            after[i] = 0.0f;
            changed.push_back(i);
        }
    ASSERT_GT(changed.size(), 5u);
    const std::vector<float> first = neighbourShade(field, before, sigma);
    std::vector<float> shade = first;
    const auto around = neighbourShadeAround(field, after, sigma, changed);
    EXPECT_LT(around.size(), field.blades.size() / 4) << "only the neighbourhood";
    for (const auto& [i, value] : around)
        shade[i] = value;
    const std::vector<float> whole = neighbourShade(field, after, sigma);
    ASSERT_EQ(shade.size(), whole.size());
    std::size_t differ = 0, moved = 0;
    for (std::size_t i = 0; i < whole.size(); ++i) {
        differ += std::memcmp(&shade[i], &whole[i], sizeof(float)) != 0;
        moved += whole[i] != first[i] ? 1 : 0;
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(moved, changed.size()) << "the change reached neighbours beyond the changed";
}

TEST(BendingCues, ADenseFieldLeansMoreInItsMiddleThanAtItsEdge) {
    ProceduralMeshParams params;
    params.shape = ProceduralShape::Plane;
    params.size = 2.0f;
    params.resolution = 4;
    const SurfaceMesh mesh = makeProceduralMesh(params);
    ScatterParams scatter;
    scatter.density = 300.0f;
    LayerSource source;
    source.candidates = scatterCandidates(mesh, scatter, 7);
    const GrownField straight = growField(source, 64);
    BendingCues cues;
    cues.neighboursDeg = 40.0f;
    source.bends = candidateBends(cues, source.candidates, {}, RuleWorld{});
    const GrownField bent = growField(source, 64);
    double middle = 0.0, edge = 0.0;
    int middleCount = 0, edgeCount = 0;
    for (std::size_t slot = 0; slot < bent.patched.blades.size(); ++slot) {
        if (bent.patched.sourceIndex[slot] == UINT32_MAX)
            continue;
        EXPECT_LT(leanOf(straight.patched.blades[slot]), 1e-3f);  // acos of ~1
        const Blade& b = bent.patched.blades[slot];
        const float r = std::max(std::abs(b.v0().x), std::abs(b.v0().z));
        if (r < 0.4f) {
            middle += leanOf(b);
            ++middleCount;
        } else if (r > 0.95f) {
            edge += leanOf(b);
            ++edgeCount;
        }
    }
    ASSERT_GT(middleCount, 50);
    ASSERT_GT(edgeCount, 50);
    middle /= middleCount;
    edge /= edgeCount;
    // 300 per m² shades the middle to about 0.87: 35° of the 40.
    EXPECT_NEAR(middle, 0.87 * 40.0 * DEG, 4.0 * DEG);
    EXPECT_LT(edge, 0.8 * middle);
}

// Article 003's third cue: sway grows with a vertex's height. The root stays, the tip moves,
// and a point at height t of the Bézier moves by 2t(1 − t)·Δv1 + t²·Δv2.
TEST(BendingCues, SwayGrowsWithTheVertexHeight) {
    PhysicsParams params;
    params.dtS = 1.0f / 60.0f;
    WindSource wind;
    wind.strength = 3.0f;
    wind.wavelengthM = 0.0f;
    wind.gust = 0.0f;
    Blade blade = candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 0.3f);
    const Blade rest = blade;
    float eta = 0.0f;
    for (int step = 0; step < 30; ++step)
        stepBlade(blade, eta, restTip(rest), params, {wind}, {}, static_cast<float>(step) * params.dtS);
    float previous = 0.0f;
    for (const float t : {0.25f, 0.5f, 0.75f, 1.0f}) {
        const float moved = glm::length(bezierPoint(blade.v0(), blade.v1(), blade.v2(), t) -
                                        bezierPoint(rest.v0(), rest.v1(), rest.v2(), t));
        EXPECT_GT(moved, previous * 1.2f) << "t " << t;
        previous = moved;
    }
    EXPECT_EQ(bezierPoint(blade.v0(), blade.v1(), blade.v2(), 0.0f), rest.v0());
}

TEST(BendingCues, ALeaningBladeWithSwaySwaysFurtherInTheSameWind) {
    PhysicsParams params;
    params.dtS = 1.0f / 60.0f;
    WindSource wind;
    wind.strength = 3.0f;
    wind.direction = glm::vec3(0.0f, 0.0f, 1.0f);
    wind.wavelengthM = 0.0f;
    wind.gust = 0.0f;
    const Blade c = candidateOn(glm::vec3(0.0f, 1.0f, 0.0f), 0.0f);
    CandidateBend bend;
    bend.leanRad = 30.0f * DEG;
    const auto swayed = [&](float sway) {
        Blade blade = bentRestBlade(c, c.h(), c.w(), 0.0f, bend, sway);
        const glm::vec3 tip = restTip(blade);
        float eta = 0.0f;
        for (int step = 0; step < 60; ++step)
            stepBlade(blade, eta, tip, params, {wind}, {}, static_cast<float>(step) * params.dtS);
        return glm::length(blade.v2() - tip);
    };
    EXPECT_GT(swayed(0.8f), 1.3f * swayed(0.0f));
}

}  // namespace
}  // namespace grass::core
