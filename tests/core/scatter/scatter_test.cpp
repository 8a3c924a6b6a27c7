#include "scatter/scatter.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh/procedural.h"
#include "scatter/poisson_disk.h"
#include "scatter/surface_sampler.h"
#include "util/rng.h"

namespace grass::core {
namespace {

constexpr float TWO_PI = 6.28318530717958647692f;

SurfaceMesh plane(float side, int resolution = 8) {
    ProceduralMeshParams p;
    p.shape = ProceduralShape::Plane;
    p.size = side;
    p.resolution = resolution;
    return makeProceduralMesh(p);
}

SurfaceMesh sphere(float radius, int resolution = 32) {
    ProceduralMeshParams p;
    p.shape = ProceduralShape::Sphere;
    p.size = radius;
    p.resolution = resolution;
    return makeProceduralMesh(p);
}

ScatterParams uniformOnly(float density) {
    ScatterParams p;
    p.density = density;
    p.clumpSpacing = 0.0f;
    return p;
}

ScatterParams clumpsOnly(float spacing, int perClump, float radius) {
    ScatterParams p;
    p.density = 0.0f;
    p.clumpSpacing = spacing;
    p.bladesPerClump = perClump;
    p.clumpRadius = radius;
    return p;
}

// 64 × 64 map, left half (u < 0.5) black, right half white.
MapImage halfBlackMap() {
    MapImage map = makeConstantMap(64, 64, 1.0f);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 32; ++x)
            map.texels[static_cast<std::size_t>(y * 64 + x)] = 0.0f;
    return map;
}

// A scene makes the sampler once for all its layers and re-grows (Scene::sampler): the
// candidates from it are the mesh's, uniform and clumped, blade for blade.
TEST(Scatter, ASamplerMadeOnceGivesTheMeshsCandidates) {
    const SurfaceMesh mesh = sphere(1.5f, 24);
    SurfaceSampler sampler(mesh);
    sampler.buildNeighbourhoodIndex();
    ScatterParams both = clumpsOnly(0.3f, 6, 0.1f);
    both.density = 40.0f;
    ASSERT_TRUE(scatterNeedsNeighbourhoods(both));
    EXPECT_FALSE(scatterNeedsNeighbourhoods(uniformOnly(40.0f)));
    for (const ScatterParams& params : {uniformOnly(40.0f), both}) {
        const ScatterCandidates fromMesh = scatterCandidates(mesh, params, 11);
        const ScatterCandidates fromSampler = scatterCandidates(sampler, params, 11);
        ASSERT_GT(fromMesh.blades.size(), 100u);
        ASSERT_EQ(fromSampler.blades.size(), fromMesh.blades.size());
        EXPECT_EQ(fromSampler.clumps.size(), fromMesh.clumps.size());
        EXPECT_EQ(fromSampler.uniformCount, fromMesh.uniformCount);
        for (std::size_t i = 0; i < fromMesh.blades.size(); ++i) {
            ASSERT_EQ(fromSampler.blades[i].v0Theta, fromMesh.blades[i].v0Theta) << i;
            ASSERT_EQ(fromSampler.faces[i], fromMesh.faces[i]) << i;
            ASSERT_EQ(fromSampler.thinning[i].keep, fromMesh.thinning[i].keep) << i;
        }
    }
}

// Without a map every candidate is kept: the count is exactly llround(density × area).
TEST(Scatter, CountIsDensityTimesArea) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        const SurfaceMesh p = plane(10.0f);
        const ScatterResult onPlane = scatterBlades(p, uniformOnly(50.0f), nullptr, seed);
        EXPECT_EQ(onPlane.blades.size(), 5000u) << "seed " << seed;
        EXPECT_EQ(onPlane.uniformCount, 5000u);
        EXPECT_EQ(onPlane.uvs.size(), onPlane.blades.size());

        const SurfaceMesh s = sphere(1.5f);
        const ScatterResult onSphere = scatterBlades(s, uniformOnly(120.0f), nullptr, seed);
        EXPECT_EQ(onSphere.blades.size(),
                  static_cast<std::size_t>(std::llround(120.0 * surfaceArea(s))))
            << "seed " << seed;
    }
}

// Each of N = density × area candidates is kept with probability p = ∫map dA / A = 0.5, so the
// count is Binomial(N, p): mean Np, σ = √(Np(1 − p)); we accept |count − Np| ≤ 3σ. Blades lie
// only where the bilinear map is above 0: u ≥ 31.5/64 (texel 31's centre; the ramp to texel 32
// is symmetric about u = 0.5, so ∫map is still exactly half).
TEST(Scatter, DensityMapScalesCountAndPlacesBladesOnWhite) {
    const MapImage map = halfBlackMap();
    for (const std::uint64_t seed : {11u, 12u, 13u, 14u}) {
        for (const bool onSphere : {false, true}) {
            const SurfaceMesh mesh = onSphere ? sphere(2.0f) : plane(8.0f);
            const ScatterResult r = scatterBlades(mesh, uniformOnly(100.0f), &map, seed);
            const auto n = static_cast<double>(std::llround(100.0 * surfaceArea(mesh)));
            const double mean = 0.5 * n, sigma = std::sqrt(n * 0.25);
            EXPECT_NEAR(static_cast<double>(r.blades.size()), mean, 3.0 * sigma)
                << "seed " << seed << (onSphere ? " sphere" : " plane");
            for (std::size_t i = 0; i < r.blades.size(); ++i) {
                ASSERT_GE(r.uvs[i].x, 31.5f / 64.0f) << "seed " << seed;
                if (!onSphere) {
                    ASSERT_GE(r.blades[i].v0().x, 8.0f * (31.5f / 64.0f - 0.5f) - 1e-4f);
                }
            }
        }
    }
}

// Chi-square test of uniformity: 20 000 blades over a 10 × 10 grid of cells (expected 200
// each), 99 degrees of freedom; the critical value at p = 0.001 is 148.2.
TEST(Scatter, UniformBladesAreUniformOnPlane) {
    const SurfaceMesh mesh = plane(10.0f, 3);
    for (const std::uint64_t seed : {21u, 22u, 23u}) {
        const ScatterResult r = scatterBlades(mesh, uniformOnly(200.0f), nullptr, seed);
        ASSERT_EQ(r.blades.size(), 20000u);
        std::vector<int> cells(100, 0);
        for (const Blade& b : r.blades) {
            const int cx = std::clamp(static_cast<int>((b.v0().x + 5.0f)), 0, 9);
            const int cz = std::clamp(static_cast<int>((b.v0().z + 5.0f)), 0, 9);
            ++cells[static_cast<std::size_t>(cz * 10 + cx)];
        }
        double chi2 = 0.0;
        for (const int c : cells)
            chi2 += (c - 200.0) * (c - 200.0) / 200.0;
        EXPECT_LT(chi2, 148.2) << "seed " << seed;
    }
}

// The same test on a UV sphere, whose triangles shrink towards the poles: it fails unless
// triangles are picked by area. Cells of equal area by Archimedes: 10 bands of equal height
// (y / r) × 10 sectors of longitude; 20 000 blades, 99 dof, critical value 148.2 at p = 0.001.
// The inscribed mesh's cells differ from equal by < 1 %, a bias of < 2 blades per cell.
TEST(Scatter, UniformBladesAreUniformOnSphere) {
    const SurfaceMesh mesh = sphere(1.0f, 24);
    const float density = static_cast<float>(20000.0 / surfaceArea(mesh));
    for (const std::uint64_t seed : {24u, 25u}) {
        const ScatterResult r = scatterBlades(mesh, uniformOnly(density), nullptr, seed);
        ASSERT_EQ(r.blades.size(), 20000u);
        std::vector<int> cells(100, 0);
        for (const Blade& b : r.blades) {
            const glm::vec3 d = glm::normalize(b.v0());
            const int band = std::clamp(static_cast<int>((d.y + 1.0f) * 5.0f), 0, 9);
            const float phi = std::atan2(d.z, d.x) + 3.14159265f;
            const int sector = std::clamp(static_cast<int>(phi / TWO_PI * 10.0f), 0, 9);
            ++cells[static_cast<std::size_t>(band * 10 + sector)];
        }
        double chi2 = 0.0;
        for (const int c : cells)
            chi2 += (c - 200.0) * (c - 200.0) / 200.0;
        EXPECT_LT(chi2, 148.2) << "seed " << seed;
    }
}

TEST(Scatter, BladesAreInRangesAndStandOnTheSurface) {
    ScatterParams params = uniformOnly(40.0f);
    params.blade = BladeRanges{0.3f, 0.4f, 0.01f, 0.02f, 3.0f, 5.0f};
    const SurfaceMesh mesh = sphere(1.0f, 48);
    const ScatterResult r = scatterBlades(mesh, params, nullptr, 5);
    ASSERT_FALSE(r.blades.empty());
    for (const Blade& b : r.blades) {
        EXPECT_GE(b.h(), 0.3f);
        EXPECT_LE(b.h(), 0.4f);
        EXPECT_GE(b.w(), 0.01f);
        EXPECT_LE(b.w(), 0.02f);
        EXPECT_GE(b.s(), 3.0f);
        EXPECT_LE(b.s(), 5.0f);
        EXPECT_GE(b.theta(), 0.0f);
        EXPECT_LT(b.theta(), TWO_PI);
        EXPECT_NEAR(glm::length(b.up()), 1.0f, 1e-5f);
        // up is the interpolated sphere normal; roots lie on the (inscribed) mesh.
        EXPECT_GT(glm::dot(b.up(), glm::normalize(b.v0())), 0.999f);
        EXPECT_NEAR(glm::length(b.v0()), 1.0f, 0.005f);
        EXPECT_EQ(b.v2(), b.v0() + b.h() * b.up());
    }
}

void expectMinimumDistance(const std::vector<glm::vec3>& points, float spacing,
                           std::uint64_t seed) {
    float closest = 1e30f;
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j)
            closest = std::min(closest, glm::length(points[i] - points[j]));
    EXPECT_GE(closest, spacing) << "seed " << seed;
}

// Dart throwing stops near random sequential adsorption's jamming density, about 60 % of the
// hexagonal capacity; we ask for at least 45 % (a sign the darts are not cut short).
TEST(Scatter, ClumpCentresKeepPoissonDiskDistance) {
    for (const std::uint64_t seed : {31u, 32u}) {
        const SurfaceMesh p = plane(10.0f);
        const ScatterResult onPlane = scatterBlades(p, clumpsOnly(0.5f, 4, 0.1f), nullptr, seed);
        expectMinimumDistance(onPlane.clumpCentres, 0.5f, seed);
        EXPECT_EQ(onPlane.clumpCount, onPlane.clumpCentres.size());
        EXPECT_GE(static_cast<double>(onPlane.clumpCount), 0.45 * poissonDiskCapacity(100.0, 0.5f))
            << "seed " << seed;

        const SurfaceMesh s = sphere(2.0f);
        const ScatterResult onSphere = scatterBlades(s, clumpsOnly(0.4f, 4, 0.1f), nullptr, seed);
        expectMinimumDistance(onSphere.clumpCentres, 0.4f, seed);
        EXPECT_GT(onSphere.clumpCount, 100u);
    }
}

// Clump blades come in groups of bladesPerClump, one group per centre (no map, density 0):
// each lies on the mesh (a triangle within 1e-4 m) and within clumpRadius of its centre.
TEST(Scatter, ClumpBladesLieOnSurfaceNearTheirCentre) {
    for (const bool onSphere : {false, true}) {
        // A coarse plane: clumps near its edges must not spill off them.
        const SurfaceMesh mesh = onSphere ? sphere(1.0f, 12) : plane(4.0f, 1);
        SurfaceSampler sampler(mesh);
        sampler.buildNeighbourhoodIndex();
        const int perClump = 9;
        const float radius = 0.2f;
        const ScatterResult r =
            scatterBlades(mesh, clumpsOnly(0.5f, perClump, radius), nullptr, 41);
        ASSERT_GT(r.clumpCount, 10u);
        ASSERT_EQ(r.blades.size(), r.clumpCount * static_cast<std::size_t>(perClump));
        std::vector<std::uint32_t> near;
        for (std::size_t i = 0; i < r.blades.size(); ++i) {
            const glm::vec3 root = r.blades[i].v0();
            const glm::vec3 centre = r.clumpCentres[i / static_cast<std::size_t>(perClump)];
            EXPECT_LE(glm::length(root - centre), radius * (1.0f + 1e-5f));
            sampler.trianglesNear(root, 1e-4f, near);
            EXPECT_FALSE(near.empty()) << "blade " << i << " is off the mesh";
            if (!onSphere) {
                EXPECT_LE(std::abs(root.x), 2.0f);
                EXPECT_LE(std::abs(root.z), 2.0f);
            }
        }
    }
}

// Neighbourhood sampling is uniform over the surface inside the ball, whether it proposes
// from whole triangles (a fine plane) or from the disc the ball cuts from a huge triangle (a
// one-quad plane): on a flat surface ρ²/r² is then uniform on [0, 1], mean 1/2, σ of the mean
// √(1/12)/√N = 0.002 for N = 20 000; we accept 3σ = 0.006.
TEST(Scatter, NeighbourhoodSamplesAreUniformInTheDisc) {
    for (const int resolution : {1, 64}) {
        const SurfaceMesh mesh = plane(8.0f, resolution);
        SurfaceSampler sampler(mesh);
        sampler.buildNeighbourhoodIndex();
        Rng rng(61);
        std::vector<SurfaceSample> points;
        const glm::vec3 centre(0.3f, 0.0f, -0.2f);
        const float radius = 0.5f;
        ASSERT_EQ(sampler.sampleNear(centre, radius, 20000, 1000000, rng, points), 20000u);
        double meanRho2 = 0.0, meanX = 0.0;
        for (const SurfaceSample& s : points) {
            const glm::vec3 d = s.position - centre;
            ASSERT_NEAR(s.position.y, 0.0f, 1e-6f);
            ASSERT_LE(glm::length(d), radius * (1.0f + 1e-5f));
            meanRho2 += static_cast<double>(glm::dot(d, d) / (radius * radius)) / 20000.0;
            meanX += static_cast<double>(d.x / radius) / 20000.0;
        }
        EXPECT_NEAR(meanRho2, 0.5, 0.006) << "resolution " << resolution;
        // x/r on a uniform disc: mean 0, σ = 1/2, σ of the mean 0.0035; 3σ = 0.011.
        EXPECT_NEAR(meanX, 0.0, 0.011) << "resolution " << resolution;
    }
}

// A face with no area (collinear corners) is never picked, alone or beside a real one.
TEST(Scatter, SamplerNeverPicksZeroAreaTriangles) {
    // A triangle soup (no shared vertices): faces 0 and 3 are collinear, 1 and 2 have area 1/2.
    SurfaceMeshBuilder builder;
    const auto addFace = [&builder](glm::vec3 p, glm::vec3 q, glm::vec3 r) {
        const auto i = builder.addVertex(p, {0, 1, 0}, {0, 0});
        const auto j = builder.addVertex(q, {0, 1, 0}, {1, 0});
        const auto k = builder.addVertex(r, {0, 1, 0}, {0, 1});
        builder.addTriangle(i, j, k);
    };
    addFace({0, 0, 0}, {2, 0, 0}, {1, 0, 0});
    addFace({0, 0, 0}, {0, 0, 1}, {1, 0, 0});
    addFace({1, 0, 0}, {0, 0, 1}, {1, 0, 1});
    addFace({1, 0, 0}, {2, 0, 0}, {3, 0, 0});
    const SurfaceMesh mesh = builder.take();
    SurfaceSampler sampler(mesh);
    ASSERT_NEAR(sampler.totalArea(), 1.0, 1e-6);
    Rng rng(71);
    int first = 0;
    for (int i = 0; i < 10000; ++i) {
        const SurfaceSample s = sampler.sample(rng);
        ASSERT_TRUE(s.triangle == 1 || s.triangle == 2) << "picked face " << s.triangle;
        first += s.triangle == 1 ? 1 : 0;
    }
    // Equal areas: Binomial(10 000, 1/2), σ = 50, 3σ = 150.
    EXPECT_NEAR(first, 5000, 150);
}

TEST(Scatter, ClumpsFollowTheDensityMap) {
    const MapImage map = halfBlackMap();
    const SurfaceMesh mesh = plane(10.0f);
    const ScatterResult r = scatterBlades(mesh, clumpsOnly(0.4f, 6, 0.15f), &map, 51);
    ASSERT_GT(r.clumpCount, 50u);
    for (const glm::vec3& c : r.clumpCentres)
        EXPECT_GT(c.x, -0.1f);
    for (std::size_t i = 0; i < r.blades.size(); ++i)
        EXPECT_GE(r.uvs[i].x, 31.5f / 64.0f);
}

// Painting the map only removes blades where it paints: every blade scattered with the map
// is one of those scattered without it, identical (position, size, angle), uniform and clump.
TEST(Scatter, MapOnlyThinsTheField) {
    ScatterParams params = uniformOnly(40.0f);
    params.clumpSpacing = 0.5f;
    const SurfaceMesh mesh = plane(6.0f);
    const MapImage map = halfBlackMap();
    const ScatterResult full = scatterBlades(mesh, params, nullptr, 81);
    const ScatterResult half = scatterBlades(mesh, params, &map, 81);
    ASSERT_GT(half.blades.size(), full.blades.size() / 3);
    ASSERT_LT(half.blades.size(), full.blades.size() * 2 / 3);
    std::size_t j = 0;  // both lists keep the order of the candidates
    for (const Blade& b : half.blades) {
        while (j < full.blades.size() && !(full.blades[j] == b))
            ++j;
        ASSERT_LT(j, full.blades.size()) << "a blade moved when the map changed";
    }
}

TEST(Scatter, SameSeedSameFieldOtherSeedOtherField) {
    ScatterParams params = uniformOnly(30.0f);
    params.clumpSpacing = 0.6f;
    const SurfaceMesh mesh = sphere(1.5f);
    const ScatterResult a = scatterBlades(mesh, params, nullptr, 77);
    const ScatterResult b = scatterBlades(mesh, params, nullptr, 77);
    const ScatterResult c = scatterBlades(mesh, params, nullptr, 78);
    EXPECT_EQ(a.blades, b.blades);
    EXPECT_EQ(a.uvs, b.uvs);
    EXPECT_EQ(a.clumpCentres, b.clumpCentres);
    EXPECT_NE(a.blades, c.blades);
    EXPECT_GT(a.clumpCount, 0u);
}

TEST(Scatter, DegenerateInputsGiveNoBlades) {
    const ScatterResult none = scatterBlades(SurfaceMesh{}, ScatterParams{}, nullptr, 1);
    EXPECT_TRUE(none.blades.empty());

    // Collinear points: a face with no area.
    SurfaceMeshBuilder builder;
    const auto a = builder.addVertex({0, 0, 0}, {0, 1, 0}, {0, 0});
    const auto b = builder.addVertex({1, 0, 0}, {0, 1, 0}, {1, 0});
    const auto c = builder.addVertex({2, 0, 0}, {0, 1, 0}, {1, 1});
    builder.addTriangle(a, b, c);
    ScatterParams withClumps;
    withClumps.clumpSpacing = 0.1f;
    EXPECT_TRUE(scatterBlades(builder.take(), withClumps, nullptr, 1).blades.empty());

    const SurfaceMesh mesh = plane(5.0f);
    EXPECT_TRUE(scatterBlades(mesh, uniformOnly(0.0f), nullptr, 1).blades.empty());
    EXPECT_TRUE(scatterBlades(mesh, uniformOnly(-3.0f), nullptr, 1).blades.empty());
    EXPECT_TRUE(scatterBlades(mesh, uniformOnly(std::nanf("")), nullptr, 1).blades.empty());
    EXPECT_TRUE(scatterBlades(mesh, clumpsOnly(0.5f, 0, 0.1f), nullptr, 1).blades.empty());
    const MapImage black = makeConstantMap(4, 4, 0.0f);
    EXPECT_TRUE(scatterBlades(mesh, uniformOnly(100.0f), &black, 1).blades.empty());
}

// 1e12 blades/m² on 25 m²: clamped, with a warning. A black map keeps the test instant.
TEST(Scatter, HugeRequestIsClampedWithWarning) {
    const MapImage black = makeConstantMap(4, 4, 0.0f);
    const ScatterResult r = scatterBlades(plane(5.0f), uniformOnly(1e12f), &black, 1);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("50000000"), std::string::npos) << r.warnings[0];
}

}  // namespace
}  // namespace grass::core
