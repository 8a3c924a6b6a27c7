// Star billboard grass objects (SPEC §8): placement, the star vertex layout and clusters, the
// CPU wind and fade the shaders mirror, and the grass texture.
#include "billboard/star_billboards.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <set>
#include <tuple>

#include "billboard/grass_texture.h"
#include "mesh/procedural.h"
#include "support/test_paths.h"
#include "util/rng.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

SurfaceMesh plane(float side) {
    ProceduralMeshParams p;
    p.shape = ProceduralShape::Plane;
    p.size = side;
    p.resolution = 8;
    return makeProceduralMesh(p);
}

StarBillboardParams params(float density, float clusterSizeM = 1.0f) {
    StarBillboardParams p;
    p.density = density;
    p.heightRangeM = {0.2f, 0.4f};
    p.widthToHeight = 1.5f;
    p.clusterSizeM = clusterSizeM;
    return p;
}

TEST(StarBillboards, CountIsDensityTimesArea) {
    // The count is density × area rounded stochastically: within 1 of it, for every seed.
    const SurfaceMesh mesh = plane(4.0f);
    for (std::uint64_t seed = 0; seed < 20; ++seed) {
        const auto objects = placeGrassObjects(mesh, params(25.3f), seed);
        EXPECT_NEAR(static_cast<double>(objects.size()), 25.3 * 16.0, 1.0) << "seed " << seed;
    }
    EXPECT_TRUE(placeGrassObjects(mesh, params(0.0f), 1).empty());
}

TEST(StarBillboards, PlacementIsDeterministicBySeed) {
    const SurfaceMesh mesh = plane(3.0f);
    const auto a = placeGrassObjects(mesh, params(20.0f), 7);
    const auto b = placeGrassObjects(mesh, params(20.0f), 7);
    const auto c = placeGrassObjects(mesh, params(20.0f), 8);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
}

TEST(StarBillboards, ObjectsStandOnTheSurfaceWithinTheirRanges) {
    const SurfaceMesh mesh = plane(3.0f);
    const StarBillboardParams p = params(30.0f);
    for (const GrassObject& o : placeGrassObjects(mesh, p, 3)) {
        EXPECT_NEAR(o.centre.y, 0.0f, 1e-5f);
        EXPECT_LE(std::abs(o.centre.x), 1.5f + 1e-5f);
        EXPECT_LE(std::abs(o.centre.z), 1.5f + 1e-5f);
        EXPECT_NEAR(glm::length(o.up), 1.0f, 1e-5f);
        EXPECT_NEAR(o.up.y, 1.0f, 1e-5f);
        EXPECT_GE(o.height, p.heightRangeM.x);
        EXPECT_LE(o.height, p.heightRangeM.y);
        EXPECT_FLOAT_EQ(o.width, o.height * p.widthToHeight);
    }
}

TEST(StarBillboards, ObjectsAreSortedByGridCellCluster) {
    const SurfaceMesh mesh = plane(4.0f);
    const float cell = 1.0f;
    const auto objects = placeGrassObjects(mesh, params(20.0f, cell), 5);
    ASSERT_FALSE(objects.empty());
    // A 4 m plane centred at the origin on a 1 m grid: 16 cells, all occupied at this density.
    std::set<std::uint32_t> clusters;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        clusters.insert(objects[i].cluster);
        if (i > 0) {
            EXPECT_LE(objects[i - 1].cluster, objects[i].cluster);
        }
    }
    EXPECT_EQ(clusters.size(), 16u);
    EXPECT_EQ(*clusters.rbegin(), 15u);
    // Same cluster ⇔ same cell.
    for (const GrassObject& a : objects)
        for (const GrassObject& b : objects) {
            const bool sameCell = glm::floor(a.centre / cell) == glm::floor(b.centre / cell);
            ASSERT_EQ(sameCell, a.cluster == b.cluster);
        }
}

TEST(StarBillboards, StarsHaveTwelveVerticesInThreeQuadsSixtyDegreesApart) {
    std::vector<GrassObject> objects(2);
    objects[0].centre = {1.0f, 0.5f, -2.0f};
    objects[0].up = glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f));
    objects[0].height = 0.4f;
    objects[0].width = 0.5f;
    objects[0].rotationRad = 0.3f;
    objects[1].centre = {-1.0f, 0.0f, 0.0f};
    const StarMesh mesh = buildStarVertices(objects);
    ASSERT_EQ(mesh.vertices.size(), 2u * STAR_VERTICES_PER_OBJECT);
    EXPECT_EQ(STAR_VERTICES_PER_OBJECT, 12u);
    EXPECT_EQ(mesh.objectCount(), 2u);
    for (std::size_t o = 0; o < 2; ++o) {
        const GrassObject& object = objects[o];
        const glm::vec3 up = glm::normalize(object.up);
        glm::vec3 across[3];
        for (std::size_t q = 0; q < 3; ++q) {
            const StarVertex* v = &mesh.vertices[o * 12 + q * 4];
            // Lower left, lower right, upper right, upper left; v = 0 at the top (image rows).
            const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
            for (std::size_t k = 0; k < 4; ++k) {
                EXPECT_EQ(v[k].uv, uvs[k]);
                EXPECT_EQ(v[k].sway, k >= 2 ? 1.0f : 0.0f);
                EXPECT_NEAR(glm::distance(v[k].normal, up), 0.0f, 1e-6f);
                EXPECT_EQ(v[k].objectCentre, object.centre);
            }
            // Vertical edges run along up, one height long.
            EXPECT_NEAR(glm::distance(v[3].position - v[0].position, up * object.height), 0.0f,
                        1e-5f);
            EXPECT_NEAR(glm::distance(v[2].position - v[1].position, up * object.height), 0.0f,
                        1e-5f);
            // The bottom edge is centred on the root, one width long, perpendicular to up.
            EXPECT_NEAR(glm::distance(0.5f * (v[0].position + v[1].position), object.centre), 0.0f,
                        1e-5f);
            across[q] = v[1].position - v[0].position;
            EXPECT_NEAR(glm::length(across[q]), object.width, 1e-5f);
            EXPECT_NEAR(glm::dot(across[q], up), 0.0f, 1e-5f);
            across[q] = glm::normalize(across[q]);
        }
        EXPECT_NEAR(glm::dot(across[0], across[1]), 0.5f, 1e-5f);
        EXPECT_NEAR(glm::dot(across[1], across[2]), 0.5f, 1e-5f);
        EXPECT_NEAR(glm::dot(across[0], across[2]), -0.5f, 1e-5f);
    }
}

TEST(StarBillboards, ClustersCoverEveryObjectOnceContiguously) {
    const SurfaceMesh mesh = plane(3.0f);
    auto objects = placeGrassObjects(mesh, params(15.0f, 0.7f), 11);
    // Shuffle so buildStarVertices has to group them itself.
    Rng rng(99);
    for (std::size_t i = objects.size(); i > 1; --i)
        std::swap(objects[i - 1], objects[rng.below(static_cast<std::uint32_t>(i))]);
    const StarMesh star = buildStarVertices(objects);
    ASSERT_EQ(star.vertices.size(), objects.size() * STAR_VERTICES_PER_OBJECT);
    std::uint32_t expectedFirst = 0;
    std::multiset<std::tuple<float, float, float>> fromClusters;
    for (std::size_t c = 0; c < star.clusters.size(); ++c) {
        const StarCluster& cluster = star.clusters[c];
        EXPECT_EQ(cluster.firstVertex, expectedFirst) << "cluster " << c;
        EXPECT_EQ(cluster.vertexCount % STAR_VERTICES_PER_OBJECT, 0u);
        expectedFirst += cluster.vertexCount;
        glm::vec3 sum(0.0f);
        for (std::uint32_t v = 0; v < cluster.vertexCount; ++v) {
            const StarVertex& vertex = star.vertices[cluster.firstVertex + v];
            EXPECT_LE(glm::distance(vertex.position, cluster.centre), cluster.radius + 1e-5f);
            if (v % STAR_VERTICES_PER_OBJECT == 0) {
                sum += vertex.objectCentre;
                fromClusters.insert(
                    {vertex.objectCentre.x, vertex.objectCentre.y, vertex.objectCentre.z});
            }
        }
        const float n = static_cast<float>(cluster.vertexCount / STAR_VERTICES_PER_OBJECT);
        if (n > 0.0f) {
            EXPECT_NEAR(glm::distance(sum / n, cluster.centre), 0.0f, 1e-4f);
        }
    }
    EXPECT_EQ(expectedFirst, star.vertices.size());
    std::multiset<std::tuple<float, float, float>> fromObjects;
    for (const GrassObject& o : objects)
        fromObjects.insert({o.centre.x, o.centre.y, o.centre.z});
    EXPECT_EQ(fromClusters, fromObjects);
}

TEST(StarBillboards, IndicesMakeTwoTrianglesPerQuad) {
    const auto indices = starQuadIndices(2);
    ASSERT_EQ(indices.size(), 2u * STAR_INDICES_PER_OBJECT);
    const std::vector<std::uint32_t> firstQuad = {0, 1, 2, 0, 2, 3};
    EXPECT_EQ(std::vector<std::uint32_t>(indices.begin(), indices.begin() + 6), firstQuad);
    EXPECT_EQ(indices.back(), 2u * STAR_VERTICES_PER_OBJECT - 1);
}

// The reduced picture's billboards: one object in n, a cluster's kept objects a contiguous run
// of the list of every n-th object.
TEST(StarBillboards, KeptObjectsAreEveryNthObjectOfACluster) {
    // Every object of a cluster [first, first + count) that is a multiple of n, no other.
    for (std::uint32_t n : {1u, 2u, 3u, 16u})
        for (std::uint32_t first = 0; first < 40; ++first)
            for (std::uint32_t count = 0; count < 40; ++count) {
                const KeptObjects kept = keptObjects(first, count, n);
                std::vector<std::uint32_t> expected, got;
                for (std::uint32_t o = first; o < first + count; ++o)
                    if (o % n == 0)
                        expected.push_back(o);
                for (std::uint32_t j = kept.first; j < kept.first + kept.count; ++j)
                    got.push_back(j * n);
                ASSERT_EQ(got, expected) << "n " << n << ", first " << first << ", count " << count;
            }
}

TEST(BillboardWind, OffsetIsHorizontalAndWithinTheAmplitude) {
    for (std::uint64_t seed = 0; seed < 1000; ++seed) {
        Rng rng(seed);
        BillboardWind wind;
        wind.directionXZ = {rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f)};
        wind.amplitudeM = rng.uniform(0.0f, 0.3f);
        wind.frequencyHz = rng.uniform(0.1f, 2.0f);
        const glm::vec3 p(rng.uniform(-50.0f, 50.0f), rng.uniform(-5.0f, 5.0f),
                          rng.uniform(-50.0f, 50.0f));
        const glm::vec3 offset = billboardWindOffset(p, rng.uniform(0.0f, 100.0f), wind);
        EXPECT_EQ(offset.y, 0.0f) << "seed " << seed;
        EXPECT_LE(glm::length(offset), wind.amplitudeM * (1.0f + 1e-5f)) << "seed " << seed;
    }
    BillboardWind still;
    still.amplitudeM = 0.0f;
    EXPECT_EQ(billboardWindOffset({1, 2, 3}, 4.5f, still), glm::vec3(0.0f));
}

TEST(BillboardWind, OffsetSwaysOverTimeAndMostlyDownwind) {
    BillboardWind wind;
    wind.directionXZ = {0.0f, 2.0f};
    wind.amplitudeM = 0.1f;
    wind.frequencyHz = 0.5f;
    float minAlong = 1.0f, maxAlong = -1.0f;
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 o =
            billboardWindOffset({0.3f, 0, 0.7f}, 0.05f * static_cast<float>(i), wind);
        minAlong = std::min(minAlong, o.z);
        maxAlong = std::max(maxAlong, o.z);
    }
    // Main sway 0.8·amplitude·(0.5 + 0.5 sin) downwind: it never blows upwind and spans most of
    // its range over 10 s (5 periods).
    EXPECT_GE(minAlong, -1e-6f);
    EXPECT_GT(maxAlong - minAlong, 0.07f);
}

TEST(BillboardWind, LowerVerticesNeverMove) {
    // What the vertex shader does: position + sway × offset, in every mode.
    std::vector<GrassObject> objects(3);
    objects[1].centre = {2, 0, 1};
    objects[2].up = glm::normalize(glm::vec3(1, 1, 0));
    const StarMesh mesh = buildStarVertices(objects);
    BillboardWind wind;
    wind.amplitudeM = 0.2f;
    for (float t = 0.0f; t < 5.0f; t += 0.37f)
        for (const StarVertex& v : mesh.vertices) {
            const glm::vec3 moved = v.position + v.sway * billboardWindOffset(v.position, t, wind);
            if (v.sway == 0.0f) {
                EXPECT_EQ(moved, v.position);
            } else {
                EXPECT_LE(glm::distance(moved, v.position), wind.amplitudeM * (1.0f + 1e-5f));
            }
        }
}

TEST(BillboardFade, RampsInAndOutWithSmoothstep) {
    const BillboardFade fade{2.0f, 4.0f, 10.0f, 20.0f};
    EXPECT_EQ(billboardFade(0.0f, fade), 0.0f);
    EXPECT_EQ(billboardFade(2.0f, fade), 0.0f);
    EXPECT_NEAR(billboardFade(3.0f, fade), 0.5f, 1e-6f);
    EXPECT_EQ(billboardFade(4.0f, fade), 1.0f);
    EXPECT_EQ(billboardFade(10.0f, fade), 1.0f);
    EXPECT_NEAR(billboardFade(15.0f, fade), 0.5f, 1e-6f);
    EXPECT_EQ(billboardFade(20.0f, fade), 0.0f);
    EXPECT_EQ(billboardFade(1000.0f, fade), 0.0f);
    // Defaults: visible at every distance. Empty ramps are steps.
    EXPECT_EQ(billboardFade(0.0f, BillboardFade{}), 1.0f);
    EXPECT_EQ(billboardFade(1.0e6f, BillboardFade{}), 1.0f);
    EXPECT_EQ(billboardFade(4.9f, BillboardFade{5.0f, 5.0f, 8.0f, 8.0f}), 0.0f);
    EXPECT_EQ(billboardFade(5.0f, BillboardFade{5.0f, 5.0f, 8.0f, 8.0f}), 1.0f);
    EXPECT_EQ(billboardFade(8.0f, BillboardFade{5.0f, 5.0f, 8.0f, 8.0f}), 0.0f);
}

const glm::vec3 ROOT{0.1f, 0.3f, 0.05f};
const glm::vec3 TIP{0.5f, 0.8f, 0.2f};

std::size_t opaqueInRows(const Rgba8Pixels& image, int firstRow, int endRow) {
    std::size_t n = 0;
    for (int row = firstRow; row < endRow; ++row)
        for (int col = 0; col < image.width; ++col)
            n += image.pixels[4 * static_cast<std::size_t>(row * image.width + col) + 3] > 128;
    return n;
}

TEST(GrassTexture, HasBothTransparentAndOpaquePixels) {
    const Rgba8Pixels image = generateGrassTexture(64, 64, 7, 1, ROOT, TIP);
    ASSERT_EQ(image.pixels.size(), 64u * 64u * 4u);
    std::size_t opaque = 0, transparent = 0;
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) {
        opaque += image.pixels[i] == 255;
        transparent += image.pixels[i] == 0;
    }
    const double n = 64.0 * 64.0;
    // Seven blades a few pixels wide: between 5 % and 60 % of the texels, and gaps elsewhere.
    EXPECT_GT(static_cast<double>(opaque) / n, 0.05);
    EXPECT_LT(static_cast<double>(opaque) / n, 0.6);
    EXPECT_GT(static_cast<double>(transparent) / n, 0.3);
}

TEST(GrassTexture, OpaquePixelsAreMostlyAtTheBottom) {
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
        const Rgba8Pixels image = generateGrassTexture(64, 128, 6, seed, ROOT, TIP);
        const std::size_t top = opaqueInRows(image, 0, 64);
        const std::size_t bottom = opaqueInRows(image, 64, 128);
        EXPECT_GT(bottom, 2 * top) << "seed " << seed;
        // Every blade is rooted in the bottom row.
        EXPECT_GE(opaqueInRows(image, 127, 128), 6u) << "seed " << seed;
    }
}

TEST(GrassTexture, ColourGoesFromRootToTip) {
    const Rgba8Pixels image = generateGrassTexture(32, 32, 5, 2, ROOT, TIP);
    // The first transparent texel of a row carries the plain colour ramp (blades add a ±20 %
    // shade): row 31 (bottom) is at 0.5/32 of the height, row 0 at 31.5/32.
    const auto rampGreen = [&](int row) {
        for (int col = 0; col < 32; ++col) {
            const std::uint8_t* p = &image.pixels[4 * static_cast<std::size_t>(row * 32 + col)];
            if (p[3] == 0)
                return static_cast<float>(p[1]);
        }
        ADD_FAILURE() << "row " << row << " has no transparent texel";
        return 0.0f;
    };
    EXPECT_NEAR(rampGreen(31), 255.0f * glm::mix(ROOT.g, TIP.g, 0.5f / 32.0f), 1.0f);
    EXPECT_NEAR(rampGreen(0), 255.0f * glm::mix(ROOT.g, TIP.g, 31.5f / 32.0f), 1.0f);
}

TEST(GrassTexture, IsDeterministicBySeed) {
    EXPECT_EQ(generateGrassTexture(48, 48, 6, 3, ROOT, TIP).pixels,
              generateGrassTexture(48, 48, 6, 3, ROOT, TIP).pixels);
    EXPECT_NE(generateGrassTexture(48, 48, 6, 3, ROOT, TIP).pixels,
              generateGrassTexture(48, 48, 6, 4, ROOT, TIP).pixels);
}

TEST(GrassTexture, LoadKeepsTheStoredColoursAndFillsTransparentTexels) {
    const fs::path file = test::scratchDir("grass_texture_round_trip") / "grass.png";
    const Rgba8Pixels image = generateGrassTexture(40, 30, 5, 9, ROOT, TIP);
    {
        // As a paint program stores it: unassociated alpha, black where transparent.
        Rgba8Pixels stored = image;
        for (std::size_t i = 0; i < stored.pixels.size(); i += 4)
            if (stored.pixels[i + 3] == 0)
                stored.pixels[i] = stored.pixels[i + 1] = stored.pixels[i + 2] = 0;
        auto out = OIIO::ImageOutput::create(file.string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(40, 30, 4, OIIO::TypeDesc::UINT8);
        spec.attribute("oiio:UnassociatedAlpha", 1);
        ASSERT_TRUE(out->open(file.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, stored.pixels.data()));
        ASSERT_TRUE(out->close());
    }
    const auto loaded = loadGrassTexture(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    ASSERT_EQ(loaded->width, 40);
    ASSERT_EQ(loaded->height, 30);
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
        ASSERT_EQ(loaded->pixels[i + 3], image.pixels[i + 3]) << "texel " << i / 4;
        if (image.pixels[i + 3] > 0) {
            // Blade texels exactly as stored, edges not premultiplied.
            for (std::size_t c = 0; c < 3; ++c)
                ASSERT_EQ(loaded->pixels[i + c], image.pixels[i + c]) << "texel " << i / 4;
        } else {
            // Gaps borrow the blades' green, not black.
            ASSERT_GT(loaded->pixels[i + 1], 40) << "texel " << i / 4;
        }
    }
}

TEST(GrassTexture, LoadErrorsNameTheFile) {
    const fs::path dir = test::scratchDir("grass_texture_errors");
    const fs::path missing = dir / "missing.png";
    const auto notFound = loadGrassTexture(missing);
    ASSERT_FALSE(notFound.ok());
    EXPECT_EQ(notFound.error().path, missing.string());
    EXPECT_NE(notFound.error().str().find("missing.png"), std::string::npos);

    // RGB, no alpha channel.
    const fs::path rgb = dir / "rgb.png";
    {
        auto out = OIIO::ImageOutput::create(rgb.string());
        ASSERT_TRUE(out);
        const std::vector<std::uint8_t> pixels(4 * 4 * 3, 128);
        ASSERT_TRUE(out->open(rgb.string(), OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::UINT8)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data()));
        ASSERT_TRUE(out->close());
    }
    const auto noAlpha = loadGrassTexture(rgb);
    ASSERT_FALSE(noAlpha.ok());
    EXPECT_EQ(noAlpha.error().path, rgb.string());
    EXPECT_NE(noAlpha.error().message.find("alpha"), std::string::npos) << noAlpha.error().str();

    // RGBA, but opaque everywhere.
    const fs::path opaque = dir / "opaque.png";
    const std::vector<std::uint8_t> solid(4 * 4 * 4, 255);
    ASSERT_TRUE(writeRgba8Image(opaque, 4, 4, solid).ok());
    const auto allOpaque = loadGrassTexture(opaque);
    ASSERT_FALSE(allOpaque.ok());
    EXPECT_EQ(allOpaque.error().path, opaque.string());

    // Not an image at all.
    const fs::path text = dir / "notes.png";
    { std::ofstream(text) << "not an image"; }
    const auto garbage = loadGrassTexture(text);
    ASSERT_FALSE(garbage.ok());
    EXPECT_EQ(garbage.error().path, text.string());
}

}  // namespace
}  // namespace grass::core
