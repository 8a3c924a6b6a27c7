#include "mesh/surface_mesh.h"

#include <gtest/gtest.h>

namespace grass::core {
namespace {

TEST(SurfaceMesh, NonManifoldFacesKeepTheirGeometry) {
    // Three triangles on one edge (a "fin"): OpenMesh refuses the third; it must still be there
    // with its own vertex copies at the same positions, normals and UVs.
    SurfaceMeshBuilder builder;
    const auto a = builder.addVertex({0, 0, 0}, {0, 1, 0}, {0, 0});
    const auto b = builder.addVertex({1, 0, 0}, {0, 1, 0}, {1, 0});
    const auto c = builder.addVertex({0, 0, 1}, {0, 1, 0}, {0, 1});
    const auto d = builder.addVertex({0, 0, -1}, {0, 1, 0}, {0, 0.5f});
    const auto e = builder.addVertex({0, 1, 0}, {0, 0, 1}, {0.5f, 0.5f});
    builder.addTriangle(a, b, c);
    builder.addTriangle(b, a, d);
    builder.addTriangle(a, b, e);
    // Many refused faces force OpenMesh to grow its arrays while copies are made.
    for (int i = 0; i < 200; ++i)
        builder.addTriangle(a, b, e);
    SurfaceMesh mesh = builder.take();
    EXPECT_EQ(mesh.n_faces(), 203u);
    EXPECT_GE(builder.duplicatedForManifold(), 201u);
    const Bounds bounds = meshBounds(mesh);
    EXPECT_EQ(bounds.min, glm::vec3(0, 0, -1));
    EXPECT_EQ(bounds.max, glm::vec3(1, 1, 1));
    EXPECT_NEAR(surfaceArea(mesh), 0.5 * 203, 1e-6);
}

// A move hands the mesh over (the same vertices in memory, nothing copied); a copy is a deep one
// that the original's later edits do not reach.
TEST(SurfaceMesh, AMovableMeshMovesWithoutCopyingAndCopiesDeeply) {
    SurfaceMeshBuilder builder;
    const auto a = builder.addVertex({0, 0, 0}, {0, 1, 0}, {0, 0});
    const auto b = builder.addVertex({1, 0, 0}, {0, 1, 0}, {1, 0});
    const auto c = builder.addVertex({0, 0, 1}, {0, 1, 0}, {0, 1});
    builder.addTriangle(a, b, c);
    MovableSurfaceMesh mesh = builder.take();
    const SurfaceMesh* held = &*mesh;
    const OpenMesh::Vec3f* points = held->points();
    MovableSurfaceMesh moved = std::move(mesh);
    EXPECT_EQ(&*moved, held);
    EXPECT_EQ(moved->points(), points) << "the vertex array itself was handed over";
    MovableSurfaceMesh assigned;
    assigned = std::move(moved);
    EXPECT_EQ(assigned->points(), points);

    MovableSurfaceMesh copy = assigned;
    EXPECT_NE(copy->points(), points);
    assigned->set_point(assigned->vertex_handle(0), OpenMesh::Vec3f(5, 5, 5));
    EXPECT_EQ(copy->point(copy->vertex_handle(0)), OpenMesh::Vec3f(0, 0, 0));
    EXPECT_EQ(copy->n_faces(), 1u);
    const SurfaceMesh& asMesh = copy;  // converts where a SurfaceMesh& is taken
    EXPECT_EQ(meshBounds(asMesh).max, glm::vec3(1, 0, 1));
}

TEST(SurfaceMesh, DegenerateTrianglesAreSkippedAndCounted) {
    SurfaceMeshBuilder builder;
    const auto a = builder.addVertex({0, 0, 0}, {0, 1, 0}, {0, 0});
    const auto b = builder.addVertex({1, 0, 0}, {0, 1, 0}, {1, 0});
    builder.addTriangle(a, a, b);
    EXPECT_EQ(builder.degenerateTriangles(), 1u);
    EXPECT_EQ(builder.take()->n_faces(), 0u);
}

TEST(SurfaceMesh, ComputedNormalsAreAreaWeighted) {
    // A big triangle facing +Y and a small one facing +X share vertex 0: its normal leans to +Y.
    SurfaceMeshBuilder builder;
    const auto o = builder.addVertex({0, 0, 0}, {}, {});
    const auto x = builder.addVertex({0, 0, 10}, {}, {});
    const auto z = builder.addVertex({10, 0, 0}, {}, {});
    const auto y = builder.addVertex({0, 1, 0}, {}, {});
    builder.addTriangle(o, x, z);  // normal +Y, area 50
    builder.addTriangle(o, y, x);  // normal +X, area 5
    SurfaceMesh mesh = builder.take();
    computeAreaWeightedNormals(mesh);
    const glm::vec3 n = toGlm(mesh.normal(mesh.vertex_handle(0)));
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    EXPECT_NEAR(n.y / n.x, 10.0f, 1e-3f);
}

TEST(SurfaceMesh, GeneratedUvsSpanTheLargestAxes) {
    SurfaceMeshBuilder builder;
    const auto a = builder.addVertex({-2, 0.1f, -1}, {}, {});
    const auto b = builder.addVertex({2, 0.0f, -1}, {}, {});
    const auto c = builder.addVertex({2, 0.2f, 1}, {}, {});
    builder.addTriangle(a, b, c);
    SurfaceMesh mesh = builder.take();
    generatePlanarUVs(mesh);
    // X (4 m) and Z (2 m) are the largest; both scaled by 1/4 so texels stay square.
    EXPECT_EQ(toGlm(mesh.texcoord2D(mesh.vertex_handle(0))), glm::vec2(0, 0));
    EXPECT_EQ(toGlm(mesh.texcoord2D(mesh.vertex_handle(1))), glm::vec2(1, 0));
    EXPECT_EQ(toGlm(mesh.texcoord2D(mesh.vertex_handle(2))), glm::vec2(1, 0.5f));
}

}  // namespace
}  // namespace grass::core
