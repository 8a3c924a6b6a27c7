#include "collider/sphere_packing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <limits>

#include "collider/packing_cache.h"
#include "mesh/gltf_loader.h"
#include "mesh/procedural.h"
#include "support/gltf_writer.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/rng.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

// Distances are exact point-triangle distances in float on meshes about 2 m across: rounding
// stays far below this.
constexpr double DISTANCE_ROUNDING = 1e-5;

SurfaceMesh sphereMesh(float radius, int resolution) {
    ProceduralMeshParams p;
    p.shape = ProceduralShape::Sphere;
    p.size = radius;
    p.resolution = resolution;
    return makeProceduralMesh(p);
}

SurfaceMesh torusMesh(float major, float minor, int resolution) {
    ProceduralMeshParams p;
    p.shape = ProceduralShape::Torus;
    p.size = major;
    p.minorSize = minor;
    p.resolution = resolution;
    return makeProceduralMesh(p);
}

// Axis-aligned boxes, wound outward; `skipTriangles` leaves triangles of the first box out
// (holes). Triangles 2k and 2k + 1 make face k: -x, +x, -y, +y, -z, +z.
SurfaceMesh boxesMesh(const std::vector<std::array<glm::vec3, 2>>& boxes,
                      const std::vector<int>& skipTriangles = {}) {
    SurfaceMeshBuilder builder;
    int triangle = 0;
    for (const auto& [lo, hi] : boxes) {
        std::array<std::uint32_t, 8> corner{};
        std::array<glm::vec3, 8> position{};
        for (int i = 0; i < 8; ++i) {
            position[static_cast<std::size_t>(i)] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y,
                                                     (i & 4) ? hi.z : lo.z};
            corner[static_cast<std::size_t>(i)] =
                builder.addVertex(position[static_cast<std::size_t>(i)], {0, 1, 0}, {0, 0});
        }
        const glm::vec3 centre = 0.5f * (lo + hi);
        constexpr int QUADS[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
        for (const auto& q : QUADS) {
            for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
                const auto at = [&](int k) { return static_cast<std::size_t>(t[k]); };
                if (std::find(skipTriangles.begin(), skipTriangles.end(), triangle++) !=
                    skipTriangles.end())
                    continue;
                const glm::vec3 normal = glm::cross(position[at(1)] - position[at(0)],
                                                    position[at(2)] - position[at(0)]);
                const bool outward = glm::dot(normal, position[at(0)] - centre) > 0.0f;
                builder.addTriangle(corner[at(0)], outward ? corner[at(1)] : corner[at(2)],
                                    outward ? corner[at(2)] : corner[at(1)]);
            }
        }
    }
    return builder.take();
}

// Brute-force distance from p to the mesh, in double, by a different route than the library
// (plane projection, then the edges): the independent check on every radius.
double bruteDistance(const SurfaceMesh& mesh, glm::dvec3 p) {
    const auto segment = [](glm::dvec3 q, glm::dvec3 a, glm::dvec3 b) {
        const glm::dvec3 ab = b - a;
        const double t = std::clamp(glm::dot(q - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
        return glm::length(q - (a + t * ab));
    };
    double best = std::numeric_limits<double>::infinity();
    for (const auto fh : mesh.faces()) {
        const auto corners = facePositions(mesh, fh);
        const glm::dvec3 a = corners[0], b = corners[1], c = corners[2];
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::dot(n, n) == 0.0)
            continue;
        const glm::dvec3 unit = glm::normalize(n);
        const double height = glm::dot(p - a, unit);
        const glm::dvec3 q = p - height * unit;
        const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0.0 &&
                            glm::dot(glm::cross(c - b, q - b), n) >= 0.0 &&
                            glm::dot(glm::cross(a - c, q - c), n) >= 0.0;
        const double d = inside ? std::abs(height)
                                : std::min({segment(p, a, b), segment(p, b, c), segment(p, c, a)});
        best = std::min(best, d);
    }
    return best;
}

// Volume enclosed by a closed, outward-wound mesh (divergence theorem).
double enclosedVolume(const SurfaceMesh& mesh) {
    double volume = 0.0;
    for (const auto fh : mesh.faces()) {
        const auto c = facePositions(mesh, fh);
        volume += glm::dot(glm::dvec3(c[0]), glm::cross(glm::dvec3(c[1]), glm::dvec3(c[2]))) / 6.0;
    }
    return volume;
}

SpherePacking packOk(const SurfaceMesh& mesh, std::uint32_t count, std::uint32_t resolution) {
    Result<SpherePacking> packing = packSpheres(mesh, {count, resolution});
    EXPECT_TRUE(packing.ok()) << packing.error().str();
    return packing.ok() ? std::move(packing).value() : SpherePacking{};
}

// Each centre inside the shape (analytic test) and no farther from the surface than the
// radius allows: the sphere does not cross the surface.
void expectSpheresInside(const SurfaceMesh& mesh, const SpherePacking& packing,
                         const std::function<bool(glm::vec3)>& insideShape,
                         const std::string& what) {
    ASSERT_FALSE(packing.spheres.empty()) << what;
    for (std::size_t i = 0; i < packing.spheres.size(); ++i) {
        const PackedSphere& s = packing.spheres[i];
        EXPECT_TRUE(insideShape(s.centre)) << what << " sphere " << i;
        EXPECT_GT(s.radiusM, 0.0f) << what << " sphere " << i;
        EXPECT_GE(bruteDistance(mesh, s.centre), s.radiusM - DISTANCE_ROUNDING)
            << what << " sphere " << i;
    }
}

TEST(SpherePacking, OneSphereFillsAProceduralSphere) {
    const SurfaceMesh mesh = sphereMesh(1.0f, 32);
    const SpherePacking packing = packOk(mesh, 1, 32);
    ASSERT_EQ(packing.spheres.size(), 1u);
    const PackedSphere& s = packing.spheres[0];
    // The grid has 32 voxels across, so no voxel centre is the sphere's centre: the nearest
    // are half a voxel diagonal away. The greedy takes the ball covering the most voxels, which
    // may be one voxel farther: allow a whole diagonal, and the same off the inscribed radius.
    const double h = packing.voxelSize, diagonal = std::sqrt(3.0) * h;
    EXPECT_NEAR(h, 2.0 / 32.0, 1e-6);
    EXPECT_LE(glm::length(s.centre), diagonal);
    const double inscribed = bruteDistance(mesh, glm::dvec3(0.0));
    EXPECT_GE(s.radiusM, inscribed - diagonal);
    EXPECT_LE(s.radiusM, inscribed + DISTANCE_ROUNDING);
    // One sphere inside: the union is exactly it, the coverage its volume share. Sampling
    // error: about 17000 of the 32768 samples are inside, so sigma <= 0.004; allow 3 sigma.
    const double expected =
        4.0 / 3.0 * 3.14159265358979 * std::pow(s.radiusM, 3.0) / enclosedVolume(mesh);
    EXPECT_NEAR(packing.coverage, expected, 0.012);
    EXPECT_GE(packing.insideShare, 0.999f);
    EXPECT_EQ(packing.samples, 32768u);
}

bool insideTorus(glm::vec3 p, float major, float minor) {
    const float ring = std::sqrt(p.x * p.x + p.z * p.z) - major;
    return ring * ring + p.y * p.y < minor * minor;
}

bool insideBox(glm::vec3 p, glm::vec3 lo, glm::vec3 hi) {
    return glm::all(glm::greaterThan(p, lo)) && glm::all(glm::lessThan(p, hi));
}

TEST(SpherePacking, CoverageGrowsWithSphereCountAndStaysInside) {
    const SurfaceMesh torus = torusMesh(1.0f, 0.4f, 32);
    const SurfaceMesh box =
        boxesMesh({{glm::vec3(-1.0f, -0.5f, -0.25f), glm::vec3(1.0f, 0.5f, 0.25f)}});
    for (const auto& [mesh, name] : {std::pair{&torus, "torus"}, std::pair{&box, "box"}}) {
        float previous = 0.0f;
        SpherePacking fewer;
        for (const std::uint32_t count : {8u, 32u, 128u}) {
            const SpherePacking packing = packOk(*mesh, count, 32);
            const std::string what = std::string(name) + " N=" + std::to_string(count);
            EXPECT_EQ(packing.spheres.size(), count) << what;
            // The spheres are inside by construction; only a sample misjudged at the surface
            // could count against it.
            EXPECT_GE(packing.insideShare, 0.995f) << what;
            EXPECT_GT(packing.coverage, previous) << what;
            previous = packing.coverage;
            // Greedy: the packing for fewer spheres is a prefix of this one.
            for (std::size_t i = 0; i < fewer.spheres.size(); ++i)
                EXPECT_EQ(packing.spheres[i], fewer.spheres[i]) << what << " sphere " << i;
            fewer = packing;
        }
        EXPECT_GE(previous, 0.6f) << name << " at 128 spheres";
    }
}

TEST(SpherePacking, SpheresLieInsideTheMesh) {
    const SurfaceMesh sphere = sphereMesh(1.0f, 24);
    expectSpheresInside(
        sphere, packOk(sphere, 64, 24), [](glm::vec3 p) { return glm::length(p) < 1.0f; },
        "sphere");
    const SurfaceMesh torus = torusMesh(1.0f, 0.3f, 24);
    expectSpheresInside(
        torus, packOk(torus, 64, 40), [](glm::vec3 p) { return insideTorus(p, 1.0f, 0.3f); },
        "torus");
    const glm::vec3 lo(-0.3f, 0.0f, -0.2f), hi(0.7f, 0.2f, 0.5f);
    const SurfaceMesh box = boxesMesh({{lo, hi}});
    expectSpheresInside(
        box, packOk(box, 64, 32), [&](glm::vec3 p) { return insideBox(p, lo, hi); }, "box");
}

TEST(SpherePacking, OverlappingPartsCountAsInside) {
    // Two closed boxes that overlap, as game assets built from parts often do: ray parity
    // would call the overlap outside; the winding number counts it twice inside.
    const glm::vec3 aLo(0.0f), aHi(2.0f, 1.0f, 1.0f), bLo(1.0f, 0.0f, 0.0f), bHi(3.0f, 1.0f, 1.0f);
    const SurfaceMesh mesh = boxesMesh({{aLo, aHi}, {bLo, bHi}});
    const SpherePacking packing = packOk(mesh, 32, 30);
    expectSpheresInside(
        mesh, packing,
        [&](glm::vec3 p) { return insideBox(p, aLo, aHi) || insideBox(p, bLo, bHi); },
        "overlapping boxes");
    const bool inOverlap =
        std::any_of(packing.spheres.begin(), packing.spheres.end(),
                    [](const PackedSphere& s) { return s.centre.x > 1.0f && s.centre.x < 2.0f; });
    EXPECT_TRUE(inOverlap);
    EXPECT_GE(packing.insideShare, 0.995f);
}

TEST(SpherePacking, AHoleInTheMeshDoesNotTurnItInsideOut) {
    const glm::vec3 lo(-1.0f, -0.5f, -0.5f), hi(1.0f, 0.5f, 0.5f);
    const SpherePacking closed = packOk(boxesMesh({{lo, hi}}), 32, 32);
    for (const int missing : {0, 7, 11}) {
        const SurfaceMesh mesh = boxesMesh({{lo, hi}}, {missing});
        ASSERT_EQ(mesh.n_faces(), 11u);
        const SpherePacking packing = packOk(mesh, 32, 32);
        ASSERT_FALSE(packing.spheres.empty());
        for (const PackedSphere& s : packing.spheres)
            EXPECT_TRUE(insideBox(s.centre, lo, hi)) << "missing triangle " << missing;
        // The votes outvote the rays through the hole: close to the closed box's coverage
        // (a sphere near the hole may reach through it, so not the same spheres).
        EXPECT_NEAR(packing.coverage, closed.coverage, 0.05f) << "missing triangle " << missing;
    }
}

TEST(SpherePacking, AnOpenBottomIsFilledAndNotLeaked) {
    // A rock scanned without its base: 5 of the 6 axis rays from inside still meet a wall. The
    // spheres stay above the opening: no triangle bounds them there, the outside voxels do.
    const glm::vec3 lo(-1.0f, 0.0f, -1.0f), hi(1.0f, 1.0f, 1.0f);
    const SurfaceMesh mesh = boxesMesh({{lo, hi}}, {4, 5});
    const SpherePacking packing = packOk(mesh, 32, 32);
    ASSERT_FALSE(packing.spheres.empty());
    for (const PackedSphere& s : packing.spheres) {
        EXPECT_TRUE(insideBox(s.centre, lo, hi));
        // Half a voxel: the centres just beyond the grid, which count as outside, lie that far
        // below the opening.
        EXPECT_GE(s.centre.y - s.radiusM, lo.y - 0.5f * packing.voxelSize - 1e-5f);
    }
    EXPECT_GE(packing.insideShare, 0.99f);
    EXPECT_GE(packing.coverage, 0.75f);
}

// The same triangles with each one's winding chosen by a coin toss (Rng seed `seed`).
SurfaceMesh withRandomWinding(const SurfaceMesh& mesh, std::uint64_t seed) {
    SurfaceMeshBuilder builder;
    Rng rng(seed);
    for (const auto fh : mesh.faces()) {
        const auto p = facePositions(mesh, fh);
        std::array<std::uint32_t, 3> v{};
        for (std::size_t k = 0; k < 3; ++k)
            v[k] = builder.addVertex(p[k], {0, 1, 0}, {0, 0});
        if (rng.below(2) == 0)
            builder.addTriangle(v[0], v[1], v[2]);
        else
            builder.addTriangle(v[0], v[2], v[1]);
    }
    return builder.take();
}

TEST(SpherePacking, RandomFaceWindingKeepsTheSameSpheres) {
    // With random windings, a line through one closed shell sums to 0 where the winding rule
    // holds and to an even nonzero number where parity must take over. A torus has lines that
    // cross it four times: the winding rule alone counts part of its hole as inside, which
    // shows in the measured coverage (0.78 instead of 0.817; with the parity fallback 0.81).
    const SurfaceMesh torus = torusMesh(1.0f, 0.4f, 20);
    const SpherePacking reference = packOk(torus, 16, 24);
    EXPECT_NEAR(reference.coverage, 0.8167f, 0.001f);
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        const SpherePacking packing = packOk(withRandomWinding(torus, seed), 16, 24);
        ASSERT_EQ(packing.spheres.size(), reference.spheres.size()) << "seed " << seed;
        for (std::size_t i = 0; i < packing.spheres.size(); ++i) {
            EXPECT_EQ(packing.spheres[i].centre, reference.spheres[i].centre) << "seed " << seed;
            // A flipped triangle lists its corners in another order: the distance rounds
            // differently in the last bit.
            EXPECT_NEAR(packing.spheres[i].radiusM, reference.spheres[i].radiusM, 1e-6f)
                << "seed " << seed;
        }
        // The same points are sampled; only lines with two faces wound alike on one side of a
        // sample can still mislead one of its six rays.
        EXPECT_NEAR(packing.coverage, reference.coverage, 0.015f) << "seed " << seed;
    }
}

TEST(SpherePacking, SameInputGivesIdenticalPacking) {
    const SurfaceMesh mesh = torusMesh(1.0f, 0.35f, 20);
    const SpherePacking a = packOk(mesh, 40, 24), b = packOk(mesh, 40, 24);
    EXPECT_EQ(a, b);
}

void expectError(const SurfaceMesh& mesh, SpherePackingParams params, const std::string& part) {
    const Result<SpherePacking> packing = packSpheres(mesh, params);
    ASSERT_FALSE(packing.ok()) << "packed, but should have failed with \"" << part << "\"";
    EXPECT_NE(packing.error().message.find(part), std::string::npos) << packing.error().message;
    EXPECT_EQ(packing.error().message.find('\n'), std::string::npos);
}

TEST(SpherePacking, RefusesBadInput) {
    const SurfaceMesh box = boxesMesh({{glm::vec3(0.0f), glm::vec3(1.0f)}});
    expectError(box, {0, 32}, "at least 1");
    expectError(box, {4097, 32}, "4097");
    expectError(box, {8, 7}, "resolution 7");
    expectError(box, {8, 257}, "resolution 257");
    expectError(SurfaceMesh{}, {8, 32}, "no triangles");
    ProceduralMeshParams plane;
    plane.resolution = 8;
    expectError(makeProceduralMesh(plane), {8, 32},
                "mesh has no enclosed volume to pack into spheres (is it a closed surface?)");
    // An open sheet that is not flat: two triangles of a bent quad.
    SurfaceMeshBuilder sheet;
    const auto v0 = sheet.addVertex({0.0f, 0.0f, 0.0f}, {0, 1, 0}, {0, 0});
    const auto v1 = sheet.addVertex({1.0f, 0.2f, 0.0f}, {0, 1, 0}, {0, 0});
    const auto v2 = sheet.addVertex({1.0f, 0.5f, 1.0f}, {0, 1, 0}, {0, 0});
    const auto v3 = sheet.addVertex({0.0f, 0.1f, 1.0f}, {0, 1, 0}, {0, 0});
    sheet.addTriangle(v0, v2, v1);
    sheet.addTriangle(v0, v3, v2);
    expectError(sheet.take(), {8, 32}, "no enclosed volume");
}

// ---- Cache ---------------------------------------------------------------------------------

struct CacheFixture {
    // One folder per test: CTest runs the tests of this file in parallel processes.
    fs::path dir =
        test::scratchDir(std::string("sphere_packing_cache_") +
                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::path meshFile = dir / "rock.glb";
    ~CacheFixture() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    SurfaceMesh writeBox(glm::vec3 hi) const {
        test::writeGltf(meshFile, test::singleMeshAsset(test::boxPrimitive(glm::vec3(0.0f), hi)),
                        test::BufferStorage::Glb);
        Result<GltfImport> import = loadGltf(meshFile);
        EXPECT_TRUE(import.ok()) << import.error().str();
        return import.ok() ? std::move(import->mesh) : SurfaceMesh{};
    }
};

SpherePacking loadOrPackOk(const fs::path& meshFile, const SurfaceMesh& mesh,
                           SpherePackingParams params, const fs::path& cacheFile,
                           bool expectFromCache) {
    bool fromCache = !expectFromCache;
    Result<SpherePacking> packing =
        loadOrPackSpheres(meshFile, mesh, params, cacheFile, &fromCache);
    EXPECT_TRUE(packing.ok()) << packing.error().str();
    EXPECT_EQ(fromCache, expectFromCache);
    return packing.ok() ? std::move(packing).value() : SpherePacking{};
}

TEST(SpherePackingCache, SecondCallReadsTheCacheAndGivesTheSamePacking) {
    CacheFixture f;
    const SurfaceMesh mesh = f.writeBox(glm::vec3(2.0f, 1.0f, 0.5f));
    const SpherePackingParams params{16, 24};
    const fs::path cacheFile = packingCachePath(f.dir, f.meshFile, params);
    const SpherePacking packed = loadOrPackOk(f.meshFile, mesh, params, cacheFile, false);
    ASSERT_TRUE(fs::exists(cacheFile));
    const SpherePacking cached = loadOrPackOk(f.meshFile, mesh, params, cacheFile, true);
    EXPECT_EQ(cached, packed);
    EXPECT_EQ(cached, packOk(mesh, 16, 24));
}

TEST(SpherePackingCache, ChangedMeshFileOrSphereCountRepacks) {
    CacheFixture f;
    const SurfaceMesh first = f.writeBox(glm::vec3(2.0f, 1.0f, 0.5f));
    const fs::path cacheFile = f.dir / "rock.spheres.json";
    const SpherePacking a = loadOrPackOk(f.meshFile, first, {16, 24}, cacheFile, false);
    const SurfaceMesh second = f.writeBox(glm::vec3(2.0f, 1.0f, 1.0f));
    const SpherePacking b = loadOrPackOk(f.meshFile, second, {16, 24}, cacheFile, false);
    EXPECT_NE(a, b);
    loadOrPackOk(f.meshFile, second, {16, 24}, cacheFile, true);
    // Same file, another sphere count: the key differs, so the cache is repacked even at the
    // same path.
    const SpherePacking c = loadOrPackOk(f.meshFile, second, {8, 24}, cacheFile, false);
    EXPECT_EQ(c.spheres.size(), 8u);
    loadOrPackOk(f.meshFile, second, {8, 24}, cacheFile, true);
}

TEST(SpherePackingCache, CorruptCacheIsRepackedAndOverwritten) {
    CacheFixture f;
    const SurfaceMesh mesh = f.writeBox(glm::vec3(1.0f));
    const SpherePackingParams params{8, 16};
    const fs::path cacheFile = packingCachePath(f.dir, f.meshFile, params);
    const SpherePacking packed = loadOrPackOk(f.meshFile, mesh, params, cacheFile, false);
    const Result<std::string> good = readFile(cacheFile);
    ASSERT_TRUE(good.ok());
    const std::string goodText = *good;
    for (const std::string& bad :
         {std::string("{ \"format\": \"grass-sphere-pack"), std::string("[]"), std::string(),
          goodText.substr(0, goodText.size() / 2),
          // Well-formed but a negative radius.
          std::string(goodText).replace(goodText.rfind(", ") + 2, 0, "-")}) {
        ASSERT_TRUE(writeFileAtomic(cacheFile, bad).ok());
        EXPECT_EQ(loadOrPackOk(f.meshFile, mesh, params, cacheFile, false), packed) << bad;
        EXPECT_EQ(loadOrPackOk(f.meshFile, mesh, params, cacheFile, true), packed) << bad;
    }
}

// A project folder that cannot be written (an example installed read-only, a shared drive)
// still loads: the cache only saves the next load its packing.
TEST(SpherePackingCache, AnUnwritableCacheIsANoteNotAnError) {
    CacheFixture f;
    const SurfaceMesh mesh = f.writeBox(glm::vec3(1.0f));
    const Result<SpherePacking> reference =
        loadOrPackSpheres(f.meshFile, mesh, {8, 16}, f.dir / "writable.spheres.json");
    ASSERT_TRUE(reference.ok());
    // The cache folder's place is taken by a file.
    ASSERT_TRUE(writeFileAtomic(f.dir / "blocked", "x").ok());
    const fs::path cacheFile = f.dir / "blocked" / "rock.spheres.json";
    bool fromCache = true;
    std::string note;
    const Result<SpherePacking> packing =
        loadOrPackSpheres(f.meshFile, mesh, {8, 16}, cacheFile, &fromCache, &note);
    ASSERT_TRUE(packing.ok()) << packing.error().str();
    EXPECT_FALSE(fromCache);
    EXPECT_EQ(packing->spheres, reference->spheres) << "the same packing, kept in memory";
    EXPECT_NE(note.find(cacheFile.string()), std::string::npos) << note;
    EXPECT_NE(note.find("not written"), std::string::npos) << note;
    EXPECT_FALSE(fs::exists(cacheFile));
    // A writable cache leaves no note.
    ASSERT_TRUE(
        loadOrPackSpheres(f.meshFile, mesh, {8, 16}, f.dir / "other.spheres.json", &fromCache, &note)
            .ok());
    EXPECT_TRUE(note.empty()) << note;
    // A missing mesh file is an error naming it.
    const Result<SpherePacking> missing =
        loadOrPackSpheres(f.dir / "gone.glb", mesh, {8, 16}, f.dir / "gone.spheres.json");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().path, (f.dir / "gone.glb").string());
}

TEST(SpherePackingCache, PathIsInTheProjectCacheFolder) {
    EXPECT_EQ(packingCachePath("projects/meadow", "meshes/rock.glb", {8, 32}),
              fs::path("projects/meadow/.grass-cache/rock.8-32.spheres.json"));
}

// The numbers in docs/sphere-packing.md. Not a test: run with
//   grass_tests --gtest_filter='SpherePacking.DISABLED_*' --gtest_also_run_disabled_tests
TEST(SpherePacking, DISABLED_ReportTimesAndCoverage) {
    struct Shape {
        std::string name;
        SurfaceMesh mesh;
    };
    std::vector<Shape> shapes;
    shapes.push_back({"sphere r=1, 9940 tri", sphereMesh(1.0f, 71)});
    shapes.push_back({"torus 1/0.4, 10082 tri", torusMesh(1.0f, 0.4f, 71)});
    if (auto cube = loadGltf(test::sourceDir() / "tests/data/gltf/cube.glb"); cube.ok())
        shapes.push_back({"cube.glb, 12 tri", std::move(cube->mesh)});
    const auto report = [](const Shape& shape, std::uint32_t resolution, std::uint32_t count) {
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpuStart = std::clock();
        const Result<SpherePacking> packing = packSpheres(shape.mesh, {count, resolution});
        const double cpuMs = 1000.0 * static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        const double wallMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        ASSERT_TRUE(packing.ok()) << packing.error().str();
        std::printf("| %s | %u | %u | %.0f (%.0f) | %zu | %.4f | %.4f |\n", shape.name.c_str(),
                    resolution, count, cpuMs, wallMs, packing->spheres.size(), packing->insideShare,
                    packing->coverage);
    };
    std::printf("| mesh | resolution | N | CPU ms (wall) | spheres | insideShare | coverage |\n");
    for (const Shape& shape : shapes) {
        for (const std::uint32_t count : {1u, 8u, 32u, 128u, 512u, 4096u})
            report(shape, 64, count);
        report(shape, 32, 32);
        report(shape, 128, 32);
    }
}

}  // namespace
}  // namespace grass::core
