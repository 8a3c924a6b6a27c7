// The two scenes of Jahrmann 2017 shipped as projects (SPEC §14): projects/helicopter (900,000
// blades, a point wind flying over the field, no colliders, no occluders) and projects/nature
// (397,881 blades on hills, the 1000-sphere bunny collider). The scenes are not built here (a
// million blades is too much for a unit test): their blade counts are checked with the same
// estimate buildScene uses, on the project's own surface mesh.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

#include "mesh/gltf_loader.h"
#include "project/project.h"
#include "scene/scene.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

LoadedProject loadShipped(const char* name) {
    auto loaded = loadProject(test::sourceDir() / "projects" / name);
    EXPECT_TRUE(loaded) << loaded.error().str();
    return loaded ? std::move(*loaded) : LoadedProject{};
}

double estimatedBlades(const LoadedProject& loaded) {
    auto mesh = loadProjectMesh(loaded, nullptr);
    EXPECT_TRUE(mesh) << mesh.error().str();
    if (!mesh)
        return 0.0;
    const double area = surfaceArea(*mesh);
    double blades = 0.0;
    for (const GrassLayer& layer : loaded.project.layers)
        blades += estimateLayerBlades(layer.scatter, area);
    return blades;
}

TEST(PaperProjects, HelicopterHasNineHundredThousandBladesAndAFlyingPointWind) {
    const LoadedProject loaded = loadShipped("helicopter");
    const Project& project = loaded.project;
    const double blades = estimatedBlades(loaded);
    EXPECT_NEAR(blades, 900000.0, 0.05 * 900000.0);

    const WindDesc* point = nullptr;
    for (const WindDesc& wind : project.wind)
        if (wind.source.kind == WindKind::Point)
            point = &wind;
    ASSERT_NE(point, nullptr) << "the helicopter is a point wind source";
    EXPECT_GT(point->source.strength, 0.0f) << "it blows outwards";
    EXPECT_GE(point->source.path.size(), 2u) << "it flies along a path";
    for (const PathKey& key : point->source.path)
        EXPECT_GT(key.posWorld.y, 0.5f) << "above the grass at t = " << key.timeS;
    // The helicopter scene is the paper's worst case for culling: nothing occludes, nothing
    // collides.
    EXPECT_TRUE(project.colliders.empty());
    EXPECT_TRUE(project.mesh.isFile || project.mesh.procedural.shape == ProceduralShape::Plane ||
                project.mesh.procedural.hillHeight <= 1.0f)
        << "flat or gently rolling terrain";
    EXPECT_EQ(project.render.patchSize % 32u, 0u);
}

TEST(PaperProjects, NatureHasThePapersBladeCountAndAThousandSphereBunny) {
    const LoadedProject loaded = loadShipped("nature");
    const Project& project = loaded.project;
    const double blades = estimatedBlades(loaded);
    EXPECT_NEAR(blades, 397881.0, 0.05 * 397881.0);
    EXPECT_FALSE(project.mesh.isFile);
    EXPECT_EQ(project.mesh.procedural.shape, ProceduralShape::Hills) << "hills are the occluders";
    EXPECT_GE(project.mesh.procedural.hillHeight, 2.0f);

    ASSERT_EQ(project.colliders.size(), 1u);
    const ColliderDesc& bunny = project.colliders[0];
    EXPECT_EQ(bunny.shape, ColliderShape::Mesh);
    EXPECT_EQ(bunny.sphereCount, 1000u);

    auto file = resolveAssetPath(loaded.folder, bunny.file, "/colliders/0/file");
    ASSERT_TRUE(file) << file.error().str();
    auto imported = loadGltf(*file);
    ASSERT_TRUE(imported) << imported.error().str();
    EXPECT_TRUE(imported->hasNormals);
    const SurfaceMesh& mesh = imported->mesh;
    EXPECT_GE(mesh.n_faces(), 1000u);
    EXPECT_LE(mesh.n_faces(), 40000u);
    EXPECT_LT(std::filesystem::file_size(*file), 1u << 20);

    // Closed: welded by position, every edge has exactly two triangles, once in each direction
    // (consistently wound), and the enclosed volume is positive (they face outwards).
    std::map<std::array<float, 3>, std::size_t> weld;
    std::map<std::pair<std::size_t, std::size_t>, int> directed;
    double volume = 0.0;
    for (const auto face : mesh.faces()) {
        const auto p = facePositions(mesh, face);
        std::array<std::size_t, 3> id{};
        for (std::size_t i = 0; i < 3; ++i)
            id[i] = weld.try_emplace({p[i].x, p[i].y, p[i].z}, weld.size()).first->second;
        for (std::size_t i = 0; i < 3; ++i)
            ++directed[{id[i], id[(i + 1) % 3]}];
        volume += static_cast<double>(glm::dot(p[0], glm::cross(p[1], p[2]))) / 6.0;
    }
    std::size_t open = 0;
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1)
            ++open;
    }
    EXPECT_EQ(open, 0u) << "edges not shared by exactly two consistently wound triangles";
    const Bounds bounds = meshBounds(mesh);
    const glm::vec3 size = bounds.size() * bunny.scale;
    EXPECT_GT(volume, 0.0);
    EXPECT_GT(volume * std::pow(bunny.scale, 3.0), 0.05 * size.x * size.y * size.z)
        << "a solid, not a sheet";
    // A bunny about a metre across, standing on its origin (placed on the terrain by position).
    EXPECT_GT(size.y, 0.5f);
    EXPECT_LT(size.y, 3.0f);
    EXPECT_NEAR(bounds.min.y, 0.0f, 0.05f);
}

}  // namespace
}  // namespace grass::core
