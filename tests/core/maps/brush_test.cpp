#include "maps/brush.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "maps/texel_surface.h"
#include "mesh/procedural.h"
#include "util/rng.h"

namespace grass::core {
namespace {

constexpr float PI_F = 3.14159265f;

SurfaceMesh shape(ProceduralShape s, float size, float minor, int resolution) {
    ProceduralMeshParams p;
    p.shape = s;
    p.size = size;
    p.minorSize = minor;
    p.resolution = resolution;
    return makeProceduralMesh(p);
}

std::uint32_t texelIndex(const TexelSurface& surface, int i, int j) {
    return static_cast<std::uint32_t>(j * surface.width() + i);
}

MapImage noiseMap(int width, int height, std::uint64_t seed) {
    MapImage map = makeConstantMap(width, height, 0.0f);
    Rng rng(seed);
    for (float& t : map.texels)
        t = rng.uniform();
    return map;
}

bool bitIdentical(const MapImage& a, const MapImage& b) {
    return a.texels.size() == b.texels.size() &&
           std::memcmp(a.texels.data(), b.texels.data(), a.texels.size() * sizeof(float)) == 0;
}

// After one Add dab of `strength` on a zero map, every covered texel holds strength · falloff of
// its own 3D distance, and every uncovered texel is still 0.
void expectSingleDabProfile(const MapImage& map, const TexelSurface& surface, glm::vec3 centre,
                            const BrushSettings& brush) {
    for (std::uint32_t t = 0; t < surface.texelCount(); ++t) {
        if (!surface.isCovered(t)) {
            ASSERT_EQ(map.texels[t], 0.0f) << "uncovered texel " << t;
            continue;
        }
        const float d = glm::length(surface.position(t) - centre);
        const float expected = brush.strength * brushFalloff(brush.falloff, d / brush.radiusM);
        ASSERT_NEAR(map.texels[t], expected, 1e-6f) << "texel " << t << " at distance " << d;
    }
}

// ---- TexelSurface -------------------------------------------------------------------------

TEST(TexelSurface, PlaneTexelsLieUnderTheirUvCentres) {
    const SurfaceMesh plane = shape(ProceduralShape::Plane, 10.0f, 1.0f, 8);
    const TexelSurface surface(plane, 64, 32);
    EXPECT_EQ(surface.coveredCount(), 64u * 32u);
    for (int j = 0; j < 32; ++j) {
        for (int i = 0; i < 64; ++i) {
            const std::uint32_t t = texelIndex(surface, i, j);
            // The plane maps u to x and v to z over [-5, 5].
            const glm::vec3 expected(((static_cast<float>(i) + 0.5f) / 64.0f - 0.5f) * 10.0f, 0.0f,
                                     ((static_cast<float>(j) + 0.5f) / 32.0f - 0.5f) * 10.0f);
            ASSERT_LT(glm::length(surface.position(t) - expected), 1e-4f) << i << ", " << j;
            ASSERT_NEAR(surface.normal(t).y, 1.0f, 1e-6f);
            // Texels are 10/64 by 10/32 m: the size is the longer side.
            ASSERT_NEAR(surface.texelSizeM(t), 10.0f / 32.0f, 1e-5f);
        }
    }
}

TEST(TexelSurface, MarginCoversTexelsWithinOneTexelOfTheTriangle) {
    // One triangle with texel-space corners (4, 4), (12, 4), (4, 12) on a 16² map, placed in 3D
    // as (4u, 0, 4v). Its hypotenuse is x + y = 16.
    SurfaceMeshBuilder builder;
    const auto vertex = [&](float u, float v) {
        return builder.addVertex({4.0f * u, 0.0f, 4.0f * v}, {0, 1, 0}, {u, v});
    };
    builder.addTriangle(vertex(0.25f, 0.25f), vertex(0.75f, 0.25f), vertex(0.25f, 0.75f));
    const SurfaceMesh mesh = builder.take();
    const TexelSurface surface(mesh, 16, 16);
    for (int j = 0; j < 16; ++j) {
        for (int i = 0; i < 16; ++i) {
            // Centre (i + ½, j + ½): per-axis distance to the legs is < 1 for i, j ≥ 3 and to the
            // far corners for i, j ≤ 12; to the hypotenuse it is (i + j + 1 − 16) / 2 < 1.
            const bool expected = i >= 3 && j >= 3 && i <= 12 && j <= 12 && i + j <= 16;
            const std::uint32_t t = texelIndex(surface, i, j);
            ASSERT_EQ(surface.isCovered(t), expected) << i << ", " << j;
            if (expected) {
                // Inside or extrapolated, the position follows the triangle's linear map.
                const glm::vec3 p(4.0f * (static_cast<float>(i) + 0.5f) / 16.0f, 0.0f,
                                  4.0f * (static_cast<float>(j) + 0.5f) / 16.0f);
                ASSERT_LT(glm::length(surface.position(t) - p), 1e-5f) << i << ", " << j;
            }
        }
    }
}

TEST(TexelSurface, OverlappingUvsKeepTheFirstTriangle) {
    // Two copies of one UV triangle, at y = 0 and y = 1: the texels belong to the first.
    SurfaceMeshBuilder builder;
    for (const float y : {0.0f, 1.0f}) {
        const auto a = builder.addVertex({0, y, 0}, {0, 1, 0}, {0, 0});
        const auto b = builder.addVertex({1, y, 0}, {0, 1, 0}, {1, 0});
        const auto c = builder.addVertex({0, y, 1}, {0, 1, 0}, {0, 1});
        builder.addTriangle(a, b, c);
    }
    const SurfaceMesh mesh = builder.take();
    const TexelSurface surface(mesh, 8, 8);
    for (std::uint32_t t = 0; t < surface.texelCount(); ++t) {
        if (surface.isCovered(t)) {
            EXPECT_EQ(surface.position(t).y, 0.0f) << t;
        }
    }
}

TEST(TexelSurface, RadiusQueryMatchesBruteForce) {
    const SurfaceMesh torus = shape(ProceduralShape::Torus, 2.0f, 0.5f, 24);
    const TexelSurface surface(torus, 96, 80);
    std::vector<std::uint32_t> covered;
    for (std::uint32_t t = 0; t < surface.texelCount(); ++t) {
        if (surface.isCovered(t))
            covered.push_back(t);
    }
    ASSERT_EQ(covered.size(), surface.coveredCount());
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        Rng rng(seed);
        const glm::vec3 centre =
            surface.position(covered[rng.below(static_cast<std::uint32_t>(covered.size()))]) +
            glm::vec3(rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f));
        const float radius = rng.uniform(0.02f, 1.5f);
        std::vector<std::uint32_t> found = surface.texelsWithin(centre, radius);
        std::sort(found.begin(), found.end());
        std::vector<std::uint32_t> expected;
        for (const std::uint32_t t : covered) {
            const glm::vec3 d = surface.position(t) - centre;
            if (glm::dot(d, d) <= radius * radius)
                expected.push_back(t);
        }
        ASSERT_EQ(found, expected) << "seed " << seed;
    }
    EXPECT_TRUE(surface.texelsWithin(surface.position(covered[0]), -1.0f).empty());
    EXPECT_TRUE(surface.texelsWithin(surface.position(covered[0]), std::nanf("")).empty());
    // An infinite radius finds everything (and must not overflow the cell range).
    EXPECT_EQ(surface.texelsWithin({0, 0, 0}, std::numeric_limits<float>::infinity()).size(),
              covered.size());
}

// ---- Falloff and settings -----------------------------------------------------------------

TEST(BrushFalloff, IsOneAtCentreZeroAtRimAndNonIncreasing) {
    for (const BrushFalloff f :
         {BrushFalloff::Smooth, BrushFalloff::Linear, BrushFalloff::Constant}) {
        EXPECT_EQ(brushFalloff(f, 0.0f), 1.0f);
        EXPECT_EQ(brushFalloff(f, -0.5f), 1.0f);
        EXPECT_EQ(brushFalloff(f, 1.0f), 0.0f);
        EXPECT_EQ(brushFalloff(f, 3.0f), 0.0f);
        EXPECT_EQ(brushFalloff(f, std::nanf("")), 0.0f);
        float previous = 1.0f;
        for (int k = 0; k <= 1000; ++k) {
            const float value = brushFalloff(f, static_cast<float>(k) / 1000.0f);
            ASSERT_LE(value, previous) << "at " << k;
            ASSERT_GE(value, 0.0f);
            previous = value;
        }
    }
    EXPECT_NEAR(brushFalloff(BrushFalloff::Smooth, 0.5f), 0.5f, 1e-6f);
    // 1 − smoothstep: 1 − 0.25² · (3 − 0.5).
    EXPECT_NEAR(brushFalloff(BrushFalloff::Smooth, 0.25f), 0.84375f, 1e-6f);
    EXPECT_NEAR(brushFalloff(BrushFalloff::Linear, 0.5f), 0.5f, 1e-6f);
    EXPECT_EQ(brushFalloff(BrushFalloff::Constant, 0.999f), 1.0f);
}

TEST(Brush, InvalidSettingsAreSanitised) {
    const float nan = std::nanf(""), inf = std::numeric_limits<float>::infinity();
    BrushSettings s;
    s.radiusM = nan;
    s.strength = nan;
    s.setValue = 2.0f;
    s.dabSpacing = -1.0f;
    BrushSettings clean = sanitizedBrush(s);
    EXPECT_EQ(clean.radiusM, 0.0f);
    EXPECT_EQ(clean.strength, 0.0f);
    EXPECT_EQ(clean.setValue, 1.0f);
    EXPECT_EQ(clean.dabSpacing, 0.25f);
    s.radiusM = inf;
    s.strength = 7.0f;
    s.setValue = -3.0f;
    s.dabSpacing = 0.0001f;
    clean = sanitizedBrush(s);
    EXPECT_EQ(clean.radiusM, 0.0f);
    EXPECT_EQ(clean.strength, 1.0f);
    EXPECT_EQ(clean.setValue, 0.0f);
    EXPECT_EQ(clean.dabSpacing, 0.05f);
    EXPECT_EQ(sanitizedBrush(BrushSettings{}), BrushSettings{});
}

// ---- Painting on a plane ------------------------------------------------------------------

// A 10 m plane under a 100² map: texels are 0.1 m apart.
struct PlaneFixture {
    SurfaceMesh mesh = shape(ProceduralShape::Plane, 10.0f, 1.0f, 8);
    TexelSurface surface{mesh, 100, 100};
};

TEST(Brush, AddDabGainsStrengthAtCentreAndNothingBeyondRadius) {
    const PlaneFixture plane;
    MapImage map = makeConstantMap(100, 100, 0.0f);
    const std::uint32_t centreTexel = texelIndex(plane.surface, 50, 50);
    const glm::vec3 centre = plane.surface.position(centreTexel);
    BrushSettings brush;
    brush.radiusM = 1.0f;
    brush.strength = 0.3f;
    const PaintRecord record = paintStroke(map, plane.surface, brush, std::span(&centre, 1));
    EXPECT_EQ(map.texels[centreTexel], 0.3f);
    expectSingleDabProfile(map, plane.surface, centre, brush);
    int painted = 0;
    for (std::uint32_t t = 0; t < map.texels.size(); ++t) {
        const float d = glm::length(plane.surface.position(t) - centre);
        // The radius is in metres: 10 texels, not a UV or texel distance.
        if (d > 1.0f + 1e-4f) {
            ASSERT_EQ(map.texels[t], 0.0f) << t;
        }
        if (d < 1.0f - 1e-3f) {
            ASSERT_GT(map.texels[t], 0.0f) << t;
            ++painted;
        }
    }
    // π r² / (0.1 m)² texels, give or take the ring at the rim.
    EXPECT_NEAR(painted, 314, 20);
    // Half way out the smooth falloff gives half the strength.
    EXPECT_NEAR(map.texels[texelIndex(plane.surface, 55, 50)], 0.15f, 1e-5f);
    // The record's bounds hold the disc, padded by 1.5 texels, and no more.
    ASSERT_FALSE(record.empty());
    EXPECT_TRUE(std::is_sorted(record.texelIndex.begin(), record.texelIndex.end()));
    EXPECT_NEAR(record.touchedBounds.min.x, centre.x - 1.0f - 0.15f, 0.11f);
    EXPECT_NEAR(record.touchedBounds.max.z, centre.z + 1.0f + 0.15f, 0.11f);
    EXPECT_NEAR(record.touchedBounds.min.y, -0.15f, 1e-4f);
}

TEST(Brush, FastStrokeLeavesNoGaps) {
    const PlaneFixture plane;
    MapImage map = makeConstantMap(100, 100, 0.0f);
    // Two hits 8 m apart, as from one frame of a fast drag; the line runs along row 50.
    const float z = plane.surface.position(texelIndex(plane.surface, 0, 50)).z;
    const std::vector<glm::vec3> hits{{-4.0f, 0.0f, z}, {4.0f, 0.0f, z}};
    BrushSettings brush;
    brush.radiusM = 0.5f;
    brush.strength = 0.05f;
    PaintStroke stroke(map, plane.surface, brush);
    stroke.addHits(hits);
    // A dab every radius / 4 = 0.125 m: 8 / 0.125 + 1.
    EXPECT_EQ(stroke.dabCount(), 65u);
    float lo = 1.0f, hi = 0.0f;
    for (int i = 15; i <= 84; ++i) {
        lo = std::min(lo, map.texels[texelIndex(plane.surface, i, 50)]);
        hi = std::max(hi, map.texels[texelIndex(plane.surface, i, 50)]);
    }
    EXPECT_GT(lo, 0.05f);
    // Along the middle of the stroke the build-up is even: no dab scallops.
    EXPECT_GT(lo, 0.95f * hi);
}

TEST(Brush, StrokeFedInPiecesEqualsWholeStroke) {
    const PlaneFixture plane;
    const std::vector<glm::vec3> hits{
        {-3.0f, 0.0f, 1.0f}, {-2.7f, 0.0f, 0.8f}, {-1.0f, 0.0f, 0.0f}, {0.5f, 0.0f, -2.0f}};
    BrushSettings brush;
    brush.radiusM = 0.7f;
    brush.mode = BrushMode::Smooth;
    brush.strength = 0.8f;
    MapImage whole = noiseMap(100, 100, 3), pieces = whole;
    const PaintRecord wholeRecord = paintStroke(whole, plane.surface, brush, hits);
    PaintStroke stroke(pieces, plane.surface, brush);
    stroke.addHits(std::span(hits).subspan(0, 2));
    stroke.addHits(std::span(hits).subspan(2));
    EXPECT_TRUE(bitIdentical(whole, pieces));
    EXPECT_EQ(stroke.record(), wholeRecord);
}

TEST(Brush, AddClampsAtOneAndSubtractAtZero) {
    const PlaneFixture plane;
    const std::vector<glm::vec3> hits{{-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    BrushSettings brush;
    brush.radiusM = 1.0f;
    brush.strength = 1.0f;
    brush.falloff = BrushFalloff::Constant;
    MapImage high = makeConstantMap(100, 100, 0.9f);
    paintStroke(high, plane.surface, brush, hits);
    EXPECT_EQ(*std::max_element(high.texels.begin(), high.texels.end()), 1.0f);
    EXPECT_EQ(*std::min_element(high.texels.begin(), high.texels.end()), 0.9f);
    brush.mode = BrushMode::Subtract;
    MapImage low = makeConstantMap(100, 100, 0.1f);
    paintStroke(low, plane.surface, brush, hits);
    EXPECT_EQ(*std::min_element(low.texels.begin(), low.texels.end()), 0.0f);
    EXPECT_EQ(*std::max_element(low.texels.begin(), low.texels.end()), 0.1f);
}

TEST(Brush, SetReachesSetValueAtCentre) {
    const PlaneFixture plane;
    MapImage map = noiseMap(100, 100, 5);
    const std::uint32_t centreTexel = texelIndex(plane.surface, 40, 60);
    const glm::vec3 centre = plane.surface.position(centreTexel);
    BrushSettings brush;
    brush.mode = BrushMode::Set;
    brush.setValue = 0.7f;
    brush.strength = 1.0f;
    brush.radiusM = 0.5f;
    paintStroke(map, plane.surface, brush, std::span(&centre, 1));
    EXPECT_EQ(map.texels[centreTexel], 0.7f);
    // At half strength each stroke halves the distance to setValue.
    brush.strength = 0.5f;
    const std::uint32_t other = texelIndex(plane.surface, 70, 20);
    const glm::vec3 otherCentre = plane.surface.position(other);
    for (int k = 0; k < 12; ++k)
        paintStroke(map, plane.surface, brush, std::span(&otherCentre, 1));
    EXPECT_NEAR(map.texels[other], 0.7f, 1.0f / 4096.0f);
}

TEST(Brush, SmoothReducesNoiseAndKeepsConstantMap) {
    const PlaneFixture plane;
    MapImage map = noiseMap(100, 100, 11);
    const MapImage original = map;
    const glm::vec3 centre(0.0f, 0.0f, 0.0f);
    BrushSettings brush;
    brush.mode = BrushMode::Smooth;
    brush.strength = 1.0f;
    brush.radiusM = 1.0f;
    brush.falloff = BrushFalloff::Constant;
    paintStroke(map, plane.surface, brush, std::span(&centre, 1));
    const auto variance = [&](const MapImage& m) {
        double sum = 0.0, sum2 = 0.0;
        int n = 0;
        for (std::uint32_t t = 0; t < m.texels.size(); ++t) {
            if (glm::length(plane.surface.position(t) - centre) < 0.8f) {
                sum += m.texels[t];
                sum2 += m.texels[t] * m.texels[t];
                ++n;
            }
        }
        return sum2 / n - (sum / n) * (sum / n);
    };
    // A 3 × 3 box mean of independent noise has 1/9 of its variance.
    EXPECT_LT(variance(map), 0.2 * variance(original));
    for (std::uint32_t t = 0; t < map.texels.size(); ++t) {
        if (glm::length(plane.surface.position(t) - centre) > 1.0f) {
            ASSERT_EQ(map.texels[t], original.texels[t]) << t;
        }
    }
    MapImage constant = makeConstantMap(100, 100, 0.3f);
    const MapImage constantBefore = constant;
    const PaintRecord record = paintStroke(constant, plane.surface, brush, std::span(&centre, 1));
    EXPECT_TRUE(bitIdentical(constant, constantBefore));
    EXPECT_TRUE(record.empty());
}

// ---- Seams --------------------------------------------------------------------------------

TEST(Brush, DabOnTorusSeamPaintsBothSides) {
    // Torus: u (around Y) has its seam at u = 0/1 on the +X half-plane z = 0, v (around the
    // tube) at v = 0/1 on the outer equator.
    const SurfaceMesh torus = shape(ProceduralShape::Torus, 2.0f, 0.5f, 64);
    const TexelSurface surface(torus, 128, 128);
    BrushSettings brush;
    brush.radiusM = 0.3f;
    brush.strength = 0.8f;
    // The top of the tube at u = 0: a mesh vertex, v = 0.25.
    const glm::vec3 top(2.0f, 0.5f, 0.0f);
    MapImage map = makeConstantMap(128, 128, 0.0f);
    paintStroke(map, surface, brush, std::span(&top, 1));
    expectSingleDabProfile(map, surface, top, brush);
    // Rows 31 and 32 straddle v = 0.25; columns 0 and 127 lie either side of the seam.
    for (const int j : {31, 32}) {
        const float left = map.texels[texelIndex(surface, 0, j)];
        const float right = map.texels[texelIndex(surface, 127, j)];
        EXPECT_GT(left, 0.6f) << j;
        EXPECT_NEAR(left, right, 0.01f) << j;
    }
    const float nearZero = map.sample({0.001f, 0.25f}), nearOne = map.sample({0.999f, 0.25f});
    EXPECT_GT(nearZero, 0.6f);
    EXPECT_NEAR(nearZero, nearOne, 0.01f);

    // The corner where both seams meet (outer equator at u = 0) paints all four UV corners.
    const glm::vec3 corner(2.5f, 0.0f, 0.0f);
    MapImage cornerMap = makeConstantMap(128, 128, 0.0f);
    paintStroke(cornerMap, surface, brush, std::span(&corner, 1));
    expectSingleDabProfile(cornerMap, surface, corner, brush);
    const float c00 = cornerMap.at(0, 0);
    EXPECT_GT(c00, 0.6f);
    EXPECT_NEAR(cornerMap.at(127, 0), c00, 0.01f);
    EXPECT_NEAR(cornerMap.at(0, 127), c00, 0.01f);
    EXPECT_NEAR(cornerMap.at(127, 127), c00, 0.01f);
}

TEST(Brush, SmoothBlursAcrossTheTorusSeam) {
    const SurfaceMesh torus = shape(ProceduralShape::Torus, 2.0f, 0.5f, 64);
    const TexelSurface surface(torus, 128, 128);
    // 0 on the u < ½ half, 1 on the other: the u = 0/1 seam is a step from 0 to 1.
    MapImage map = makeConstantMap(128, 128, 0.0f);
    for (int j = 0; j < 128; ++j) {
        for (int i = 64; i < 128; ++i)
            map.texels[texelIndex(surface, i, j)] = 1.0f;
    }
    BrushSettings brush;
    brush.mode = BrushMode::Smooth;
    brush.strength = 1.0f;
    brush.falloff = BrushFalloff::Constant;
    brush.radiusM = 0.2f;
    const glm::vec3 top(2.0f, 0.5f, 0.0f);
    paintStroke(map, surface, brush, std::span(&top, 1));
    // Column 0's UV neighbours are all 0; only its 3D neighbours across the seam can lift it.
    for (const int j : {30, 31, 32, 33}) {
        EXPECT_GT(map.at(0, j), 0.1f) << j;
        EXPECT_LT(map.at(127, j), 0.9f) << j;
        // Away from the seam (and from the u = ½ step) nothing changes.
        EXPECT_EQ(map.at(10, j), 0.0f) << j;
        EXPECT_EQ(map.at(117, j), 1.0f) << j;
    }
}

TEST(Brush, DabOnMoebiusSeamPaintsBothSidesFlipped) {
    // Möbius strip: the seam u = 0/1 joins (0, v) to (1, 1 − v), both on the +X axis at
    // x = size + (2v − 1) · minor.
    const SurfaceMesh strip = shape(ProceduralShape::Moebius, 2.0f, 0.5f, 64);
    const TexelSurface surface(strip, 128, 128);
    BrushSettings brush;
    brush.radiusM = 0.3f;
    brush.strength = 0.8f;
    // u = 0, v = 0.3 (t = −0.2): on the mesh, since the seam edge is straight.
    const glm::vec3 centre(1.8f, 0.0f, 0.0f);
    MapImage map = makeConstantMap(128, 128, 0.0f);
    paintStroke(map, surface, brush, std::span(&centre, 1));
    expectSingleDabProfile(map, surface, centre, brush);
    // Row 38 (v ≈ 0.301) at u ≈ 0 meets row 127 − 38 = 89 (v ≈ 0.699) at u ≈ 1.
    const float left = map.texels[texelIndex(surface, 0, 38)];
    EXPECT_GT(left, 0.6f);
    EXPECT_NEAR(map.texels[texelIndex(surface, 127, 89)], left, 0.01f);
    // Without the flip, row 38 at u ≈ 1 is the strip's other edge, 0.4 m away: unpainted.
    EXPECT_EQ(map.texels[texelIndex(surface, 127, 38)], 0.0f);
    for (const float v : {0.25f, 0.3f, 0.35f}) {
        const float nearZero = map.sample({0.001f, v}), nearOne = map.sample({0.999f, 1.0f - v});
        EXPECT_GT(nearZero, 0.3f) << v;
        EXPECT_NEAR(nearZero, nearOne, 0.02f) << v;
    }
}

// ---- Undo, redo and no-ops ----------------------------------------------------------------

std::vector<glm::vec3> torusStroke(const TexelSurface& surface) {
    // Surface points along a path that crosses the u seam twice.
    std::vector<glm::vec3> hits;
    for (const auto& [i, j] : {std::pair{5, 10}, {1, 14}, {62, 20}, {60, 26}, {2, 30}})
        hits.push_back(surface.position(texelIndex(surface, i, j)));
    return hits;
}

TEST(Brush, UndoAndRedoAreBitExactForEveryMode) {
    const SurfaceMesh torus = shape(ProceduralShape::Torus, 2.0f, 0.5f, 32);
    const TexelSurface surface(torus, 64, 64);
    const std::vector<glm::vec3> hits = torusStroke(surface);
    for (const BrushMode mode :
         {BrushMode::Add, BrushMode::Subtract, BrushMode::Smooth, BrushMode::Set}) {
        const auto name = static_cast<int>(mode);
        const MapImage original = noiseMap(64, 64, 17);
        MapImage map = original;
        BrushSettings brush;
        brush.mode = mode;
        brush.radiusM = 0.4f;
        brush.strength = 0.6f;
        brush.setValue = 0.25f;
        const PaintRecord record = paintStroke(map, surface, brush, hits);
        const MapImage painted = map;
        ASSERT_FALSE(record.empty()) << name;
        ASSERT_FALSE(bitIdentical(painted, original)) << name;
        ASSERT_EQ(record.before.size(), record.texelIndex.size());
        ASSERT_EQ(record.after.size(), record.texelIndex.size());
        EXPECT_TRUE(std::adjacent_find(record.texelIndex.begin(), record.texelIndex.end(),
                                       std::greater_equal<>()) == record.texelIndex.end())
            << "indices strictly ascending, mode " << name;
        std::vector<bool> listed(map.texels.size(), false);
        for (std::size_t k = 0; k < record.texelIndex.size(); ++k) {
            const std::uint32_t t = record.texelIndex[k];
            listed[t] = true;
            ASSERT_EQ(record.before[k], original.texels[t]) << name;
            ASSERT_EQ(record.after[k], painted.texels[t]) << name;
        }
        for (std::uint32_t t = 0; t < map.texels.size(); ++t) {
            if (!listed[t]) {
                ASSERT_EQ(painted.texels[t], original.texels[t]) << "unlisted change, " << name;
            }
        }
        undoPaint(map, record);
        EXPECT_TRUE(bitIdentical(map, original)) << name;
        redoPaint(map, record);
        EXPECT_TRUE(bitIdentical(map, painted)) << name;
        undoPaint(map, record);
        EXPECT_TRUE(bitIdentical(map, original)) << name;
    }
}

TEST(Brush, ZeroStrengthOrNoRadiusChangesNothing) {
    const SurfaceMesh torus = shape(ProceduralShape::Torus, 2.0f, 0.5f, 32);
    const TexelSurface surface(torus, 64, 64);
    const std::vector<glm::vec3> hits = torusStroke(surface);
    const MapImage original = noiseMap(64, 64, 23);
    for (const BrushMode mode :
         {BrushMode::Add, BrushMode::Subtract, BrushMode::Smooth, BrushMode::Set}) {
        for (const auto& [radius, strength] : {std::pair{0.4f, 0.0f},
                                               {0.4f, -1.0f},
                                               {0.4f, std::nanf("")},
                                               {0.0f, 1.0f},
                                               {-1.0f, 1.0f},
                                               {std::nanf(""), 1.0f}}) {
            MapImage map = original;
            BrushSettings brush;
            brush.mode = mode;
            brush.radiusM = radius;
            brush.strength = strength;
            const PaintRecord record = paintStroke(map, surface, brush, hits);
            EXPECT_TRUE(record.empty()) << static_cast<int>(mode) << " r " << radius;
            EXPECT_TRUE(bitIdentical(map, original)) << static_cast<int>(mode) << " r " << radius;
        }
    }
}

}  // namespace
}  // namespace grass::core
