// A file mesh's unit and up axis (core/mesh/mesh_frame.h) and the bulk of a surface
// (core/mesh/surface_bulk.h), which the first camera frames.
#include "mesh/mesh_frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "mesh/procedural.h"
#include "mesh/surface_bulk.h"

namespace grass::core {
namespace {

// A square plane of `size` in the XZ plane, `resolution` quads a side.
SurfaceMesh planeMesh(float size, int resolution) {
    ProceduralMeshParams params;
    params.shape = ProceduralShape::Plane;
    params.size = size;
    params.resolution = resolution;
    return *makeProceduralMesh(params);
}

TEST(MeshFrame, UnitsParseByNameOrNumberAndRefuseTheRest) {
    EXPECT_EQ(parseMeshUnit("mm").value(), 0.001f);
    EXPECT_EQ(parseMeshUnit("in").value(), 0.0254f);
    EXPECT_EQ(parseMeshUnit("0.5").value(), 0.5f);
    EXPECT_EQ(meshUnitText(0.01f), "cm");
    EXPECT_EQ(meshUnitText(0.5f), "0.5");
    for (const char* bad : {"parsec", "", "-1", "0", "1e9", "nan", "2m"}) {
        const auto parsed = parseMeshUnit(bad);
        ASSERT_FALSE(parsed.ok()) << bad;
        EXPECT_NE(parsed.error().message.find("mm, cm, m, in, ft"), std::string::npos) << parsed.error().message;
    }
    EXPECT_EQ(parseUpAxis("+Z").value(), UpAxis::Z);
    EXPECT_EQ(parseUpAxis("y").value(), UpAxis::Y);
    EXPECT_FALSE(parseUpAxis("-Z").ok());
}

TEST(MeshFrame, MillimetresWithZUpBecomeMetresWithYUp) {
    // 2000 mm, lying in the file's XZ plane: standing up once Z is up.
    SurfaceMesh mesh = planeMesh(2000.0f, 2);
    applyMeshFrame(mesh, 0.001f, UpAxis::Z);
    const Bounds bounds = meshBounds(mesh);
    EXPECT_NEAR(bounds.size().x, 2.0f, 1e-5f);
    EXPECT_NEAR(bounds.size().y, 2.0f, 1e-5f) << "the file's Z (its depth) is now height";
    EXPECT_NEAR(bounds.size().z, 0.0f, 1e-6f);
    for (const auto vh : mesh.vertices()) {
        // The plane's +Y normal (the file's up is Z, so +Y was "towards the viewer") is −Z now.
        const auto n = mesh.normal(vh);
        EXPECT_NEAR(n[2], -1.0f, 1e-6f);
    }
    // A rotation keeps each face's winding consistent with its normals.
    for (const auto fh : mesh.faces()) {
        OpenMesh::Vec3f p[3];
        int k = 0;
        for (const auto vh : mesh.fv_range(fh))
            p[k++] = mesh.point(vh);
        EXPECT_LT(OpenMesh::cross(p[1] - p[0], p[2] - p[0])[2], 0.0f);
    }
}

TEST(SurfaceBulk, LeavesOutSmallFarPartsButKeepsTheField) {
    SurfaceMesh mesh = planeMesh(30.0f, 30);
    // A 1 m "cloud" 400 m up and 300 m off to the side: 0.1 % of the area.
    const auto a = mesh.add_vertex({300.0f, 400.0f, 0.0f}), b = mesh.add_vertex({301.0f, 400.0f, 0.0f}),
               c = mesh.add_vertex({300.0f, 400.0f, 1.0f});
    mesh.add_face(a, c, b);
    const Bounds whole = meshBounds(mesh);
    const Bounds bulk = surfaceBulkBounds(mesh);
    EXPECT_GT(whole.max.y, 399.0f);
    EXPECT_LT(bulk.max.y, 2.0f) << "the cloud is left out";
    EXPECT_LT(bulk.max.x, 16.0f);
    // The field itself stays almost whole: the outer 2 % of its area on each side, at most.
    EXPECT_LT(bulk.min.x, -14.0f);
    EXPECT_GT(bulk.max.x, 14.0f);
    EXPECT_LT(bulk.min.z, -14.0f);
    EXPECT_GT(bulk.max.z, 14.0f);
}

// A wall of few, large triangles (Khronos' TextureSettingsTest: 72 triangles, 10 m wide): its area
// stands at the triangles' corners, so the bulk reaches the wall's edges. With the area at the
// centroids, eight 1.25 × 10 m columns of two triangles each lost 0.83 m at the top and at the
// bottom, and the first camera, framing that box, cut the wall off.
TEST(SurfaceBulk, AWallOfLargeTrianglesKeepsItsEdges) {
    SurfaceMesh mesh;
    for (int column = 0; column < 8; ++column) {
        const float x0 = 1.25f * float(column), x1 = x0 + 1.25f;
        const auto a = mesh.add_vertex({x0, 0.0f, 0.0f}), b = mesh.add_vertex({x1, 0.0f, 0.0f}),
                   c = mesh.add_vertex({x1, 10.0f, 0.0f}), d = mesh.add_vertex({x0, 10.0f, 0.0f});
        mesh.add_face(a, b, c);
        mesh.add_face(a, c, d);
    }
    const Bounds bulk = surfaceBulkBounds(mesh);
    EXPECT_LT(bulk.min.y, 0.05f);
    EXPECT_GT(bulk.max.y, 9.95f);
    EXPECT_LT(bulk.min.x, 0.05f);
    EXPECT_GT(bulk.max.x, 9.95f);
}

// The definition the selection must keep: every corner of every triangle with a third of its area,
// sorted along the axis, and the first coordinate at which the running sum reaches the share.
float sortedCornerQuantile(const SurfaceMesh& mesh, int axis, double share) {
    std::vector<std::pair<float, double>> corners;
    double total = 0.0;
    for (const auto fh : mesh.faces()) {
        const auto p = facePositions(mesh, fh);
        const double area = 0.5 * double(glm::length(glm::cross(p[1] - p[0], p[2] - p[0])));
        for (const glm::vec3& corner : p)
            corners.emplace_back(corner[axis], area / 3.0);
        total += area;
    }
    std::sort(corners.begin(), corners.end());
    double sum = 0.0;
    for (const auto& [coordinate, weight] : corners)
        if ((sum += weight) >= share * total)
            return coordinate;
    return corners.back().first;
}

// A hilly grid whose vertices its triangles share, plus loose triangles strewn far off: the
// bulk (before its margin) lies on the quantiles of the sorted corners, whichever way they are
// found.
TEST(SurfaceBulk, QuantilesAreThoseOfTheSortedCorners) {
    SurfaceMesh mesh = planeMesh(40.0f, 48);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> jitter(-0.4f, 0.4f), far(-300.0f, 300.0f);
    for (const auto vh : mesh.vertices()) {
        auto point = mesh.point(vh);
        point[1] += jitter(random) * 5.0f;
        mesh.set_point(vh, point);
    }
    for (int i = 0; i < 40; ++i) {
        const OpenMesh::Vec3f at(far(random), far(random), far(random));
        const auto a = mesh.add_vertex(at),
                   b = mesh.add_vertex(at + OpenMesh::Vec3f(2.0f, jitter(random), 0.0f)),
                   c = mesh.add_vertex(at + OpenMesh::Vec3f(0.0f, jitter(random), 2.0f));
        mesh.add_face(a, c, b);
    }
    // The margin: the mean of the triangles' square-rooted areas.
    double edges = 0.0;
    for (const auto fh : mesh.faces()) {
        const auto p = facePositions(mesh, fh);
        edges += std::sqrt(0.5 * double(glm::length(glm::cross(p[1] - p[0], p[2] - p[0]))));
    }
    const float margin = float(edges / double(mesh.n_faces()));
    const Bounds whole = meshBounds(mesh);
    for (const double outside : {0.04, 0.3}) {
        const Bounds bulk = surfaceBulkBounds(mesh, outside);
        for (int axis = 0; axis < 3; ++axis) {
            const float low = sortedCornerQuantile(mesh, axis, 0.5 * outside);
            const float high = sortedCornerQuantile(mesh, axis, 1.0 - 0.5 * outside);
            EXPECT_NEAR(bulk.min[axis], std::max(whole.min[axis], low - margin), 1e-4f)
                << "axis " << axis << ", outside " << outside;
            EXPECT_NEAR(bulk.max[axis], std::min(whole.max[axis], high + margin), 1e-4f)
                << "axis " << axis << ", outside " << outside;
        }
    }
}

}  // namespace
}  // namespace grass::core
