#include "mesh/gltf_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>
#include <limits>

#include "support/gltf_load_expect.h"
#include "support/gltf_writer.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
using test::BufferStorage;
using test::GltfAsset;
using test::GltfNode;
using test::GltfPrimitive;

testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos)
        return testing::AssertionSuccess();
    return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

bool anyNoteContains(const GltfImport& import, const std::string& part) {
    for (const auto& note : import.notes)
        if (note.find(part) != std::string::npos)
            return true;
    return false;
}

// The error of a load that must fail; it must name the file.
std::string loadError(const fs::path& file) { return test::loadGltfError(file); }

GltfImport loadOk(const fs::path& file) { return test::loadGltfExpectingSuccess(file); }

glm::vec3 point(const SurfaceMesh& mesh, SurfaceMesh::VertexHandle vh) {
    return toGlm(mesh.point(vh));
}

// Unit normal of a face from its winding (right-hand rule).
glm::vec3 windingNormal(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle fh) {
    glm::vec3 p[3];
    int i = 0;
    for (const auto vh : mesh.fv_range(fh))
        p[i++] = point(mesh, vh);
    return glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
}

glm::vec3 faceCentroid(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle fh) {
    glm::vec3 sum(0.0f);
    for (const auto vh : mesh.fv_range(fh))
        sum += point(mesh, vh);
    return sum / 3.0f;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance, const std::string& what) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(actual[i], expected[i], tolerance) << what << " component " << i;
}

// Every face's winding and its vertices' normals point away from `centre`: a closed convex
// shape seen from outside.
void expectOutwardFacesAndNormals(const SurfaceMesh& mesh, glm::vec3 centre) {
    for (const auto fh : mesh.faces()) {
        const glm::vec3 n = windingNormal(mesh, fh);
        EXPECT_GT(glm::dot(n, faceCentroid(mesh, fh) - centre), 0.0f) << "face " << fh.idx();
        for (const auto vh : mesh.fv_range(fh))
            EXPECT_GT(glm::dot(toGlm(mesh.normal(vh)), n), 0.99f)
                << "vertex " << vh.idx() << " of face " << fh.idx();
    }
}

void expectSameMesh(const GltfImport& a, const GltfImport& b) {
    ASSERT_EQ(a.mesh->n_vertices(), b.mesh->n_vertices());
    ASSERT_EQ(a.mesh->n_faces(), b.mesh->n_faces());
    for (const auto vh : a.mesh->vertices()) {
        EXPECT_EQ(a.mesh->point(vh), b.mesh->point(vh)) << "vertex " << vh.idx();
        EXPECT_EQ(a.mesh->normal(vh), b.mesh->normal(vh)) << "vertex " << vh.idx();
        EXPECT_EQ(a.mesh->texcoord2D(vh), b.mesh->texcoord2D(vh)) << "vertex " << vh.idx();
    }
    EXPECT_EQ(triangleIndices(a.mesh), triangleIndices(b.mesh));
}

glm::mat4 trs(const GltfNode& node) {
    return glm::translate(glm::mat4(1.0f), node.translation) * glm::mat4_cast(node.rotation) *
           glm::scale(glm::mat4(1.0f), node.scale);
}

// A grid placed by a rotated, scaled parent, a child under it, and a root given by a matrix.
GltfNode node(const std::string& name, int mesh) {
    GltfNode n;
    n.name = name;
    n.mesh = mesh;
    return n;
}

GltfAsset hierarchyAsset() {
    GltfAsset asset;
    asset.meshes.push_back({"Grid", {test::gridPrimitive(2.0f, 4.0f, 3)}});
    GltfNode parent = node("Parent", 0);
    parent.children = {1};
    parent.translation = {10.0f, 0.0f, -3.0f};
    parent.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    // Non-uniform scale above the child's rotation: normals then need the inverse-transpose.
    parent.scale = {2.0f, 1.5f, 0.5f};
    GltfNode child = node("Child", 0);
    child.translation = {0.0f, 1.0f, 5.0f};
    child.rotation = glm::angleAxis(glm::radians(30.0f), glm::vec3(1, 0, 0));
    child.scale = {1.0f, 3.0f, 0.5f};
    GltfNode byMatrix = node("ByMatrix", 0);
    byMatrix.matrix = glm::translate(glm::mat4(1.0f), glm::vec3(-5.0f, 2.0f, 0.0f)) *
                      glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 0, 1));
    asset.nodes = {parent, child, byMatrix};
    return asset;
}

// A ground tile placed at map coordinates (UTM-like: 512 km east, 5412 km north) by its node,
// over a grid of 1.3 cm cells. Loaded as a project's ground it is moved next to grass's origin
// in double precision: every vertex keeps its cell to 1e-6 m and the origin is the centre
// rounded to whole units. Loaded as it is (props), 32-bit floats are 0.5 m apart there and the
// cells collapse. Within 32 km, or at 5.4 km (the same numbers in millimetres), nothing moves.
TEST(GltfLoader, AGroundFarFromItsOriginIsMovedNextToGrasssOrigin) {
    const fs::path dir = test::scratchDir("gltf_far");
    const auto tileAt = [&](const std::string& name, glm::vec3 translation) {
        GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(0.13f, 0.13f, 10));
        asset.nodes[0].translation = translation;
        test::writeGltf(dir / name, asset);
        return dir / name;
    };
    const fs::path utm = tileAt("utm.gltf", {512345.0f, 120.0f, 5412345.0f});
    const GltfImport here = loadOk(tileAt("here.gltf", glm::vec3(0.0f)));

    const auto moved = loadGltf(utm, GltfPlacement::GroundNearOrigin, 1.0);
    ASSERT_TRUE(moved.ok()) << moved.error().str();
    EXPECT_EQ(moved->origin, glm::dvec3(512345.0, 120.0, 5412345.0));
    EXPECT_TRUE(anyNoteContains(*moved, "5437 km from the file's origin"));
    EXPECT_TRUE(anyNoteContains(*moved, "(512345, 120, 5412345)"));
    ASSERT_EQ(moved->mesh->n_vertices(), here.mesh->n_vertices());
    float worst = 0.0f;
    for (const auto vh : here.mesh->vertices())
        worst = std::max(worst, glm::length(point(moved->mesh, vh) - point(here.mesh, vh)));
    EXPECT_LT(worst, 1e-6f);

    const GltfImport asInFile = loadOk(utm);
    EXPECT_EQ(asInFile.origin, glm::dvec3(0.0));
    EXPECT_FALSE(anyNoteContains(asInFile, "km from the file's origin"));
    const Bounds collapsed = meshBounds(asInFile.mesh);
    EXPECT_EQ(collapsed.max.z - collapsed.min.z, 0.0f) << "0.13 m within one 0.5 m float step";

    for (const auto& [file, metresPerUnit] :
         {std::pair{tileAt("chunk.gltf", {30000.0f, 0.0f, -30000.0f}), 1.0},
          std::pair{utm, 0.001}}) {
        const auto kept = loadGltf(file, GltfPlacement::GroundNearOrigin, metresPerUnit);
        ASSERT_TRUE(kept.ok()) << kept.error().str();
        EXPECT_EQ(kept->origin, glm::dvec3(0.0)) << file;
        EXPECT_EQ(meshBounds(kept->mesh), meshBounds(loadOk(file).mesh)) << file;
    }
}

// The rule, at its edge: beyond 32 768 m along any axis (in metres), the centre rounded.
TEST(GltfLoader, GroundOriginIsTheRoundedCentreBeyond32Km) {
    EXPECT_EQ(groundOrigin(glm::dvec3(32760.0), glm::dvec3(32776.0), 1.0), glm::dvec3(0.0));
    EXPECT_EQ(groundOrigin(glm::dvec3(32770.0), glm::dvec3(32776.0), 1.0), glm::dvec3(32773.0));
    EXPECT_EQ(groundOrigin({-1.0, 0.0, -40000.4}, {1.0, 2.0, -40000.0}, 1.0),
              glm::dvec3(0.0, 1.0, -40000.0));
    EXPECT_EQ(groundOrigin(glm::dvec3(4e7), glm::dvec3(4e7 + 2.0), 0.001), glm::dvec3(4e7 + 1.0));
    EXPECT_EQ(groundOrigin(glm::dvec3(4e6), glm::dvec3(4e6 + 2.0), 0.001), glm::dvec3(0.0));
}

TEST(GltfLoader, AppliesNodeHierarchyTransforms) {
    const fs::path file = test::scratchDir("gltf_hierarchy") / "scene.gltf";
    const GltfAsset asset = hierarchyAsset();
    test::writeGltf(file, asset);
    const GltfImport import = loadOk(file);

    const glm::mat4 parent = trs(asset.nodes[0]);
    const glm::mat4 worlds[] = {parent, parent * trs(asset.nodes[1]), *asset.nodes[2].matrix};
    const std::size_t gridVertices = asset.meshes[0].primitives[0].positions.size();
    const std::size_t gridTriangles = asset.meshes[0].primitives[0].indices.size() / 3;
    EXPECT_EQ(import.mesh->n_vertices(), 3 * gridVertices);
    EXPECT_EQ(import.mesh->n_faces(), 3 * gridTriangles);

    Bounds expected{glm::vec3(std::numeric_limits<float>::max()),
                    glm::vec3(std::numeric_limits<float>::lowest())};
    double expectedArea = 0.0;
    for (const glm::mat4& world : worlds) {
        for (const glm::vec3 corner :
             {glm::vec3(-1, 0, -2), glm::vec3(1, 0, -2), glm::vec3(-1, 0, 2), glm::vec3(1, 0, 2)}) {
            const glm::vec3 p(world * glm::vec4(corner, 1.0f));
            expected.min = glm::min(expected.min, p);
            expected.max = glm::max(expected.max, p);
        }
        const glm::mat3 linear(world);
        expectedArea +=
            glm::length(glm::cross(linear * glm::vec3(2, 0, 0), linear * glm::vec3(0, 0, 4)));
    }
    const Bounds bounds = meshBounds(import.mesh);
    expectNear(bounds.min, expected.min, 1e-4f, "bounds min");
    expectNear(bounds.max, expected.max, 1e-4f, "bounds max");
    EXPECT_NEAR(surfaceArea(import.mesh), expectedArea, 1e-4 * expectedArea);
    // A flat grid's transformed normal (inverse-transpose) is its transformed plane's normal,
    // so every vertex normal must match its face's winding even under non-uniform scale.
    for (const auto fh : import.mesh->faces())
        for (const auto vh : import.mesh->fv_range(fh))
            EXPECT_GT(glm::dot(toGlm(import.mesh->normal(vh)), windingNormal(import.mesh, fh)),
                      0.9999f);
    EXPECT_TRUE(import.hasNormals);
    EXPECT_TRUE(import.hasUv);
}

TEST(GltfLoader, PlacesEveryGpuInstanceOfANode) {
    const fs::path file = test::scratchDir("gltf_gpu_instancing") / "instanced.gltf";
    GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 1));
    GltfNode& node = asset.nodes[0];
    node.translation = {0.0f, 0.0f, 10.0f};
    node.scale = {1.0f, 1.0f, 3.0f};
    node.instances.resize(3);
    node.instances[1].translation = {5.0f, 0.0f, 0.0f};
    node.instances[1].scale = {2.0f, 1.0f, 2.0f};
    node.instances[2].translation = {0.0f, 5.0f, 0.0f};
    node.instances[2].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(1, 0, 0));
    asset.extensionsRequired = {"EXT_mesh_gpu_instancing"};
    test::writeGltf(file, asset);
    const GltfImport import = loadOk(file);
    EXPECT_EQ(import.mesh->n_faces(), 2u * node.instances.size()) << "the plain mesh is not drawn";

    Bounds expected{glm::vec3(std::numeric_limits<float>::max()),
                    glm::vec3(std::numeric_limits<float>::lowest())};
    double expectedArea = 0.0;
    for (const auto& instance : node.instances) {
        GltfNode instanceTrs;
        instanceTrs.translation = instance.translation;
        instanceTrs.rotation = instance.rotation;
        instanceTrs.scale = instance.scale;
        const glm::mat4 world = trs(node) * trs(instanceTrs);
        for (const glm::vec3 corner : {glm::vec3(-0.5f, 0, -0.5f), glm::vec3(0.5f, 0, -0.5f),
                                       glm::vec3(-0.5f, 0, 0.5f), glm::vec3(0.5f, 0, 0.5f)}) {
            const glm::vec3 p(world * glm::vec4(corner, 1.0f));
            expected.min = glm::min(expected.min, p);
            expected.max = glm::max(expected.max, p);
        }
        const glm::mat3 linear(world);
        expectedArea +=
            glm::length(glm::cross(linear * glm::vec3(1, 0, 0), linear * glm::vec3(0, 0, 1)));
    }
    expectNear(meshBounds(import.mesh).min, expected.min, 1e-4f, "bounds min");
    expectNear(meshBounds(import.mesh).max, expected.max, 1e-4f, "bounds max");
    EXPECT_NEAR(surfaceArea(import.mesh), expectedArea, 1e-4 * expectedArea);
}

TEST(GltfLoader, ReportsNodeCycleInsteadOfHanging) {
    const fs::path file = test::scratchDir("gltf_cycle") / "cycle.gltf";
    GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 1));
    asset.nodes[0].children = {1};
    asset.nodes.push_back(node("Loop", -1));
    asset.nodes.back().children = {0};
    asset.sceneNodes = {0};
    test::writeGltf(file, asset);
    EXPECT_TRUE(contains(loadError(file), "cycle"));
}

TEST(GltfLoader, NegativeScaleKeepsOutwardWindingAndNormals) {
    const fs::path dir = test::scratchDir("gltf_mirror");
    GltfAsset asset = test::singleMeshAsset(test::boxPrimitive({-1, -2, -3}, {1, 2, 3}));
    asset.nodes[0].translation = {4.0f, 0.0f, 0.0f};
    asset.nodes[0].rotation =
        glm::angleAxis(glm::radians(20.0f), glm::normalize(glm::vec3(1, 1, 0)));
    for (const glm::vec3 scale :
         {glm::vec3(-1, 1, 1), glm::vec3(-2, 1, 0.5f), glm::vec3(-1, -1, -1)}) {
        asset.nodes[0].scale = scale;
        const fs::path file = dir / "mirror.gltf";
        test::writeGltf(file, asset);
        const GltfImport import = loadOk(file);
        ASSERT_EQ(import.mesh->n_faces(), 12u);
        SCOPED_TRACE("scale " + std::to_string(scale.x) + " " + std::to_string(scale.y) + " " +
                     std::to_string(scale.z));
        expectOutwardFacesAndNormals(import.mesh, glm::vec3(4.0f, 0.0f, 0.0f));
    }
}

// Found by fuzzing (tests/fuzz/regressions/glb/): finite positions far from the origin overflow
// a float cross product, and the computed normals came out NaN.
TEST(GltfLoader, ComputedNormalsStayFiniteForHugeCoordinates) {
    const fs::path dir = test::scratchDir("gltf_huge");
    const fs::path file = dir / "huge.gltf";
    test::GltfPrimitive triangle;
    triangle.positions = {{0.0f, 0.0f, 0.0f}, {3e30f, 0.0f, 0.0f}, {0.0f, 0.0f, -3e30f}};
    test::writeGltf(file, test::singleMeshAsset(triangle));
    const GltfImport import = loadOk(file);
    ASSERT_FALSE(import.hasNormals);
    for (const auto vh : import.mesh->vertices()) {
        const auto normal = import.mesh->normal(vh);
        EXPECT_NEAR(normal[0], 0.0f, 1e-6f);
        EXPECT_NEAR(normal[1], 1.0f, 1e-6f);
        EXPECT_NEAR(normal[2], 0.0f, 1e-6f);
    }
}

TEST(GltfLoader, LoadsGlbLikeTheSameGltf) {
    const fs::path dir = test::scratchDir("gltf_glb");
    const GltfAsset asset = hierarchyAsset();
    test::writeGltf(dir / "scene.gltf", asset);
    fs::remove(dir / "scene.bin");
    test::writeGltf(dir / "scene.glb", asset, BufferStorage::Glb);
    ASSERT_FALSE(fs::exists(dir / "scene.bin")) << "a .glb carries its buffer inside";
    test::writeGltf(dir / "scene.gltf", asset);
    expectSameMesh(loadOk(dir / "scene.gltf"), loadOk(dir / "scene.glb"));
}

TEST(GltfLoader, RecognisesGlbByMagicNotByExtension) {
    const fs::path dir = test::scratchDir("gltf_magic");
    const GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 2));
    test::writeGltf(dir / "binary.gltf", asset, BufferStorage::Glb);
    test::writeGltf(dir / "text.glb", asset, BufferStorage::DataUri);
    expectSameMesh(loadOk(dir / "binary.gltf"), loadOk(dir / "text.glb"));
}

// A read whose stop was requested (the editor's Cancel while a large mesh is read) ends with its
// own error naming the file, whatever stage it is in; the same file reads without one.
TEST(GltfLoader, AStopRequestedEndsTheReadNamingTheFile) {
    const fs::path dir = test::scratchDir("gltf_stopped");
    test::writeGltf(dir / "grid.glb", test::singleMeshAsset(test::gridPrimitive(8, 8, 16)),
                    BufferStorage::Glb);
    std::stop_source source;
    source.request_stop();
    auto stopped =
        loadGltf(dir / "grid.glb", GltfPlacement::GroundNearOrigin, 1.0, {}, source.get_token());
    ASSERT_FALSE(stopped.ok());
    EXPECT_EQ(stopped.error(), readStopped(dir / "grid.glb"));
    EXPECT_EQ(stopped.error().path, (dir / "grid.glb").string());
    auto read = loadGltf(dir / "grid.glb", GltfPlacement::GroundNearOrigin, 1.0, {},
                         std::stop_source().get_token());
    ASSERT_TRUE(read.ok()) << read.error().str();
    EXPECT_EQ(read->mesh->n_faces(), 512u);
}

TEST(GltfLoader, LoadsEmbeddedBase64Buffers) {
    const fs::path dir = test::scratchDir("gltf_base64");
    const GltfAsset asset = hierarchyAsset();
    test::writeGltf(dir / "external.gltf", asset);
    test::writeGltf(dir / "embedded.gltf", asset, BufferStorage::DataUri);
    std::ifstream in(dir / "embedded.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(contains(text, "data:application/octet-stream;base64,"));
    expectSameMesh(loadOk(dir / "external.gltf"), loadOk(dir / "embedded.gltf"));
}

TEST(GltfLoader, DecodesPercentEncodedBufferUri) {
    const fs::path dir = test::scratchDir("gltf_percent");
    const GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 2));
    // A '+' is literal in a URI (RFC 3986), not a space.
    test::writeGltf(dir / "scene.gltf", asset, BufferStorage::ExternalFile, "my buffer+1.bin");
    std::ifstream in(dir / "scene.gltf");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(contains(text, "my%20buffer%2B1.bin"));
    const GltfImport import = loadOk(dir / "scene.gltf");
    EXPECT_EQ(import.mesh->n_faces(), asset.meshes[0].primitives[0].indices.size() / 3);
}

TEST(GltfLoader, ReadsInterleavedAttributesWithByteStride) {
    const fs::path dir = test::scratchDir("gltf_interleaved");
    GltfPrimitive grid = test::gridPrimitive(3, 2, 4);
    test::writeGltf(dir / "separate.gltf", test::singleMeshAsset(grid));
    grid.interleaved = true;
    const test::GltfDocument doc = test::buildGltf(test::singleMeshAsset(grid));
    ASSERT_EQ(doc.json["bufferViews"][0]["byteStride"], 32);
    test::writeGltf(dir / "interleaved.gltf", doc);
    expectSameMesh(loadOk(dir / "separate.gltf"), loadOk(dir / "interleaved.gltf"));
}

TEST(GltfLoader, AppliesSparseAccessorOverBufferView) {
    const fs::path file = test::scratchDir("gltf_sparse") / "sparse.gltf";
    GltfPrimitive grid = test::gridPrimitive(2, 2, 2);  // vertex 4 is the centre
    const glm::vec3 raised(0.0f, 0.75f, 0.0f);
    grid.sparsePositions = {{4, raised}};
    test::writeGltf(file, test::singleMeshAsset(grid));
    const GltfImport import = loadOk(file);
    EXPECT_NEAR(meshBounds(import.mesh).max.y, raised.y, 1e-6f);
    EXPECT_NEAR(meshBounds(import.mesh).min.y, 0.0f, 1e-6f);
    // Four triangles meet at the raised centre; each now leans out of the plane.
    const double flatArea = 4.0;
    EXPECT_GT(surfaceArea(import.mesh), flatArea + 1e-3);
}

TEST(GltfLoader, AppliesSparseAccessorOverZerosWithoutBufferView) {
    const fs::path file = test::scratchDir("gltf_sparse_zero") / "sparse.gltf";
    GltfPrimitive triangle;
    triangle.positions.assign(3, glm::vec3(99.0f));  // ignored: only the count is written
    triangle.sparseWithoutBufferView = true;
    triangle.sparsePositions = {{1, {0.0f, 0.0f, 2.0f}}, {2, {3.0f, 0.0f, 0.0f}}};
    test::writeGltf(file, test::singleMeshAsset(triangle));
    const GltfImport import = loadOk(file);
    ASSERT_EQ(import.mesh->n_faces(), 1u);
    EXPECT_NEAR(surfaceArea(import.mesh), 0.5 * 2.0 * 3.0, 1e-6);
    EXPECT_EQ(meshBounds(import.mesh).min, glm::vec3(0.0f));
}

TEST(GltfLoader, ComputesOutwardNormalsWhenMissing) {
    const fs::path file = test::scratchDir("gltf_no_normals") / "box.gltf";
    GltfPrimitive box = test::boxPrimitive({-1, -1, -1}, {1, 1, 1});
    box.normals.clear();
    test::writeGltf(file, test::singleMeshAsset(box));
    const GltfImport import = loadOk(file);
    EXPECT_FALSE(import.hasNormals);
    EXPECT_TRUE(import.hasUv);
    EXPECT_TRUE(anyNoteContains(import, "normals computed"));
    expectOutwardFacesAndNormals(import.mesh, glm::vec3(0.0f));
    for (const auto vh : import.mesh->vertices())
        EXPECT_NEAR(glm::length(toGlm(import.mesh->normal(vh))), 1.0f, 1e-5f);
}

TEST(GltfLoader, KeepsFileNormalsAndUvsOfPrimitivesThatHaveThem) {
    const fs::path file = test::scratchDir("gltf_mixed_attributes") / "mixed.gltf";
    GltfPrimitive tilted = test::gridPrimitive(1, 1, 1);
    const glm::vec3 tilt = glm::normalize(glm::vec3(1, 1, 0));
    tilted.normals.assign(tilted.positions.size(), tilt);
    GltfPrimitive bare = test::gridPrimitive(1, 1, 1);
    bare.normals.clear();
    bare.uvs.clear();
    for (auto& p : bare.positions)
        p.y = 5.0f;
    GltfAsset asset = test::singleMeshAsset(tilted);
    asset.meshes[0].primitives.push_back(bare);
    test::writeGltf(file, asset);
    const GltfImport import = loadOk(file);
    EXPECT_FALSE(import.hasNormals);
    EXPECT_FALSE(import.hasUv);
    for (const auto vh : import.mesh->vertices()) {
        const glm::vec3 p = point(import.mesh, vh);
        const bool fromFile = p.y < 1.0f;
        expectNear(toGlm(import.mesh->normal(vh)), fromFile ? tilt : glm::vec3(0, 1, 0), 1e-5f,
                   "normal");
        const glm::vec2 uv = toGlm(import.mesh->texcoord2D(vh));
        EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
        // The grid's own UV is its position remapped to [0, 1]².
        if (fromFile) {
            EXPECT_NEAR(uv.x, p.x + 0.5f, 1e-6f);
            EXPECT_NEAR(uv.y, p.z + 0.5f, 1e-6f);
        }
    }
}

TEST(GltfLoader, GeneratesUvsInUnitSquareWhenMissing) {
    const fs::path file = test::scratchDir("gltf_no_uv") / "grid.gltf";
    GltfPrimitive grid = test::gridPrimitive(4, 2, 4);
    grid.uvs.clear();
    test::writeGltf(file, test::singleMeshAsset(grid));
    const GltfImport import = loadOk(file);
    EXPECT_FALSE(import.hasUv);
    EXPECT_TRUE(import.hasNormals);
    EXPECT_TRUE(anyNoteContains(import, "UVs generated"));
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const auto vh : import.mesh->vertices()) {
        const glm::vec2 uv = toGlm(import.mesh->texcoord2D(vh));
        lo = glm::min(lo, uv);
        hi = glm::max(hi, uv);
    }
    EXPECT_GE(lo.x, 0.0f);
    EXPECT_GE(lo.y, 0.0f);
    EXPECT_LE(hi.x, 1.0f);
    EXPECT_LE(hi.y, 1.0f);
    EXPECT_GT(hi.x - lo.x, 0.5f) << "UVs must spread over the mesh, not collapse";
}

TEST(GltfLoader, DecodesNormalizedIntegerUvs) {
    const fs::path dir = test::scratchDir("gltf_uv_norm");
    for (const auto type :
         {test::ComponentEncoding::UnsignedByte, test::ComponentEncoding::UnsignedShort}) {
        GltfPrimitive grid = test::gridPrimitive(1, 1, 3);
        grid.uvEncoding = {type, true};
        test::writeGltf(dir / "uv.gltf", test::singleMeshAsset(grid));
        const GltfImport import = loadOk(dir / "uv.gltf");
        ASSERT_TRUE(import.hasUv);
        const float step =
            type == test::ComponentEncoding::UnsignedByte ? 1.0f / 255 : 1.0f / 65535;
        // The grid's UV is its position remapped to [0, 1]².
        for (const auto vh : import.mesh->vertices()) {
            const glm::vec3 p = point(import.mesh, vh);
            const glm::vec2 uv = toGlm(import.mesh->texcoord2D(vh));
            EXPECT_NEAR(uv.x, p.x + 0.5f, step);
            EXPECT_NEAR(uv.y, p.z + 0.5f, step);
        }
    }
}

TEST(GltfLoader, ReadsQuantizedPositionsAndNormals) {
    const fs::path file = test::scratchDir("gltf_quantized") / "quantized.gltf";
    GltfPrimitive box = test::boxPrimitive({-100, -50, -20}, {100, 50, 20});
    box.positionEncoding = {test::ComponentEncoding::Short, false};
    box.normalEncoding = {test::ComponentEncoding::Byte, true};
    GltfAsset asset = test::singleMeshAsset(box);
    asset.nodes[0].scale = glm::vec3(0.01f);  // dequantization, as KHR_mesh_quantization does it
    asset.extensionsUsed = asset.extensionsRequired = {"KHR_mesh_quantization"};
    test::writeGltf(file, asset);
    const GltfImport import = loadOk(file);
    expectNear(meshBounds(import.mesh).min, {-1.0f, -0.5f, -0.2f}, 1e-6f, "min");
    expectNear(meshBounds(import.mesh).max, {1.0f, 0.5f, 0.2f}, 1e-6f, "max");
    EXPECT_TRUE(import.hasNormals);
    expectOutwardFacesAndNormals(import.mesh, glm::vec3(0.0f));
}

TEST(GltfLoader, LoadsNonIndexedTriangles) {
    const fs::path file = test::scratchDir("gltf_non_indexed") / "soup.gltf";
    const GltfPrimitive grid = test::gridPrimitive(2, 3, 3);
    GltfPrimitive soup;
    for (const std::uint32_t i : grid.indices) {
        soup.positions.push_back(grid.positions[i]);
        soup.normals.push_back(grid.normals[i]);
        soup.uvs.push_back(grid.uvs[i]);
    }
    test::writeGltf(file, test::singleMeshAsset(soup));
    const GltfImport import = loadOk(file);
    EXPECT_EQ(import.mesh->n_faces(), grid.indices.size() / 3);
    EXPECT_NEAR(surfaceArea(import.mesh), 2.0 * 3.0, 1e-5);
    for (const auto fh : import.mesh->faces())
        expectNear(windingNormal(import.mesh, fh), {0, 1, 0}, 1e-5f, "face normal");
}

TEST(GltfLoader, KeepsNonManifoldTriangles) {
    const fs::path file = test::scratchDir("gltf_non_manifold") / "pages.gltf";
    // Three triangles share the edge 0-1, like the pages of a book: no manifold has that edge,
    // yet every triangle is in the file and must be in the mesh. The third page comes when
    // the mesh holds exactly 8 vertices, so copying its vertices grows the vertex arrays
    // (under ASan this catches a reference into them kept across the growth).
    GltfPrimitive pages;
    pages.positions = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1},
                       {5, 0, 0}, {6, 0, 0}, {5, 0, 1}, {-1, 0, 0}};
    pages.indices = {0, 1, 2, 0, 3, 1, 4, 6, 5, 1, 0, 7};
    test::writeGltf(file, test::singleMeshAsset(pages));
    const GltfImport import = loadOk(file);
    EXPECT_EQ(import.mesh->n_faces(), 4u);
    EXPECT_NEAR(surfaceArea(import.mesh), 4 * 0.5, 1e-6);
    expectNear(meshBounds(import.mesh).min, {-1, 0, 0}, 0.0f, "min");
    expectNear(meshBounds(import.mesh).max, {6, 1, 1}, 0.0f, "max");
    EXPECT_TRUE(anyNoteContains(import, "non-manifold"));
}

TEST(GltfLoader, UnrollsTriangleStripsWithAlternatingWinding) {
    const fs::path file = test::scratchDir("gltf_strip") / "strip.gltf";
    // A ribbon along x: even vertices at z = 0, odd ones at z = 1.
    GltfPrimitive strip;
    strip.mode = test::PrimitiveMode::TriangleStrip;
    const int length = 5;
    for (int i = 0; i <= length; ++i)
        for (const float z : {0.0f, 1.0f})
            strip.positions.push_back({float(i), 0.0f, z});
    test::writeGltf(file, test::singleMeshAsset(strip));
    const GltfImport import = loadOk(file);
    EXPECT_EQ(import.mesh->n_faces(), strip.positions.size() - 2);
    EXPECT_NEAR(surfaceArea(import.mesh), double(length), 1e-5);
    for (const auto fh : import.mesh->faces())
        expectNear(windingNormal(import.mesh, fh), {0, 1, 0}, 1e-5f, "face normal");
}

TEST(GltfLoader, UnrollsIndexedTriangleFans) {
    const fs::path file = test::scratchDir("gltf_fan") / "fan.gltf";
    // Hub at the origin, rim on the unit circle turning from +x towards -z: seen from +Y,
    // each (rim, next rim, hub) turns counter-clockwise.
    GltfPrimitive fan;
    fan.mode = test::PrimitiveMode::TriangleFan;
    const int spokes = 5;
    const float step = glm::radians(45.0f);
    fan.positions.push_back(glm::vec3(0.0f));
    for (int k = 0; k < spokes; ++k)
        fan.positions.push_back({std::cos(-step * float(k)), 0.0f, std::sin(-step * float(k))});
    // Indices in reverse storage order, to check the fan follows the indices.
    std::reverse(fan.positions.begin() + 1, fan.positions.end());
    fan.indices = {0};
    for (int k = spokes; k >= 1; --k)
        fan.indices.push_back(static_cast<std::uint32_t>(k));
    fan.indexType = test::IndexType::UnsignedByte;
    test::writeGltf(file, test::singleMeshAsset(fan));
    const GltfImport import = loadOk(file);
    EXPECT_EQ(import.mesh->n_faces(), std::size_t(spokes - 1));
    EXPECT_NEAR(surfaceArea(import.mesh), (spokes - 1) * 0.5 * std::sin(double(step)), 1e-5);
    for (const auto fh : import.mesh->faces())
        expectNear(windingNormal(import.mesh, fh), {0, 1, 0}, 1e-5f, "face normal");
}

TEST(GltfLoader, IgnoresLinesAndPointsWithANote) {
    const fs::path file = test::scratchDir("gltf_lines") / "lines.gltf";
    const GltfPrimitive grid = test::gridPrimitive(1, 1, 2);
    GltfPrimitive lines;
    lines.mode = test::PrimitiveMode::Lines;
    lines.positions = {{0, 0, 0}, {10, 10, 10}};
    GltfPrimitive points = lines;
    points.mode = test::PrimitiveMode::Points;
    GltfAsset asset = test::singleMeshAsset(grid, "Fence");
    asset.meshes[0].primitives.push_back(lines);
    asset.meshes[0].primitives.push_back(points);
    test::writeGltf(file, asset);
    const GltfImport import = loadOk(file);
    EXPECT_EQ(import.mesh->n_faces(), grid.indices.size() / 3);
    EXPECT_LT(meshBounds(import.mesh).max.y, 1.0f) << "line vertices must not enter the mesh";
    EXPECT_TRUE(anyNoteContains(import, "mesh \"Fence\" primitive 1: lines ignored"));
    EXPECT_TRUE(anyNoteContains(import, "mesh \"Fence\" primitive 2: points ignored"));
}

TEST(GltfLoader, PlacesEveryMeshOnceWhenTheFileHasNoScene) {
    const fs::path file = test::scratchDir("gltf_no_scene") / "loose.gltf";
    GltfAsset asset;
    asset.meshes.push_back({"A", {test::gridPrimitive(1, 1, 1)}});
    asset.meshes.push_back({"B", {test::gridPrimitive(1, 1, 2)}});
    asset.withScene = false;
    test::writeGltf(file, asset);
    const GltfImport import = loadOk(file);
    EXPECT_EQ(import.mesh->n_faces(), 2u + 8u);
    EXPECT_TRUE(anyNoteContains(import, "no scenes"));
}

TEST(GltfLoader, IgnoresMissingAndBrokenTextures) {
    const fs::path file = test::scratchDir("gltf_textures") / "textured.gltf";
    test::GltfDocument doc = test::buildGltf(test::singleMeshAsset(test::gridPrimitive(1, 1, 1)));
    doc.json["images"] = {
        {{"uri", "missing.png"}}, {{"uri", "../outside.png"}}, {{"bufferView", 99}}};
    doc.json["textures"] = {{{"source", 0}}, {{"source", 2}}};
    doc.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    doc.json["meshes"][0]["primitives"][0]["material"] = 0;
    test::writeGltf(file, doc);
    EXPECT_EQ(loadOk(file).mesh->n_faces(), 2u);
}

TEST(GltfLoader, IgnoresAppearanceOnlyRequiredExtensionsWithANote) {
    const fs::path file = test::scratchDir("gltf_unlit") / "unlit.gltf";
    GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 1));
    asset.extensionsUsed = asset.extensionsRequired = {"KHR_materials_unlit"};
    test::writeGltf(file, asset);
    EXPECT_TRUE(anyNoteContains(loadOk(file), "KHR_materials_unlit"));
}

// --- Bad input: each load fails with one line naming the file and the problem. ---

TEST(GltfLoader, ReportsMissingFile) {
    const fs::path file = test::scratchDir("gltf_missing") / "nowhere.gltf";
    EXPECT_TRUE(contains(loadError(file), "file not found"));
}

TEST(GltfLoader, ReportsMissingBufferFile) {
    const fs::path dir = test::scratchDir("gltf_missing_bin");
    test::writeGltf(dir / "scene.gltf", test::singleMeshAsset(test::gridPrimitive(1, 1, 1)));
    fs::remove(dir / "scene.bin");
    const std::string message = loadError(dir / "scene.gltf");
    EXPECT_TRUE(contains(message, "scene.bin"));
    EXPECT_TRUE(contains(message, "not found"));
}

TEST(GltfLoader, ReportsTruncatedJson) {
    const fs::path file = test::scratchDir("gltf_truncated_json") / "cut.gltf";
    test::writeGltf(file, test::singleMeshAsset(test::gridPrimitive(1, 1, 1)),
                    BufferStorage::DataUri);
    fs::resize_file(file, fs::file_size(file) / 2);
    const std::string message = loadError(file);
    EXPECT_TRUE(contains(message, "JSON"));
    EXPECT_TRUE(contains(message, "truncated"));
}

TEST(GltfLoader, ReportsTruncatedGlb) {
    const fs::path file = test::scratchDir("gltf_truncated_glb") / "cut.glb";
    const GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 4));
    for (const double keep : {0.9, 0.5, 0.05}) {
        test::writeGltf(file, asset, BufferStorage::Glb);
        fs::resize_file(file, static_cast<std::uintmax_t>(double(fs::file_size(file)) * keep));
        EXPECT_TRUE(contains(loadError(file), "truncated")) << "kept " << keep;
    }
}

TEST(GltfLoader, ReportsBufferShorterThanAccessor) {
    const fs::path file = test::scratchDir("gltf_short_buffer") / "short.gltf";
    test::GltfDocument doc = test::buildGltf(test::singleMeshAsset(test::gridPrimitive(1, 1, 2)));
    auto& primitive = doc.json["meshes"][0]["primitives"][0];
    const int position = primitive["attributes"]["POSITION"];
    auto& accessor = doc.json["accessors"][static_cast<std::size_t>(position)];
    accessor["count"] = accessor["count"].get<int>() * 100;
    doc.json["bufferViews"][accessor["bufferView"].get<std::size_t>()]["byteLength"] = 1 << 20;
    test::writeGltf(file, doc);
    const std::string message = loadError(file);
    EXPECT_TRUE(contains(message, "accessor " + std::to_string(position) + " (POSITION of mesh"));
    EXPECT_TRUE(contains(message, "past the end of buffer 0"));
    EXPECT_TRUE(contains(message, "truncated or corrupt"));
}

TEST(GltfLoader, ReportsTruncatedBufferFile) {
    const fs::path dir = test::scratchDir("gltf_short_bin");
    test::writeGltf(dir / "scene.gltf", test::singleMeshAsset(test::gridPrimitive(1, 1, 2)));
    fs::resize_file(dir / "scene.bin", fs::file_size(dir / "scene.bin") / 2);
    const std::string message = loadError(dir / "scene.gltf");
    EXPECT_TRUE(contains(message, "buffer 0"));
    EXPECT_TRUE(contains(message, "truncated"));
}

TEST(GltfLoader, ReportsIndexOutOfRange) {
    const fs::path file = test::scratchDir("gltf_bad_index") / "bad.gltf";
    GltfPrimitive grid = test::gridPrimitive(1, 1, 2);
    grid.indices[4] = static_cast<std::uint32_t>(grid.positions.size());
    test::writeGltf(file, test::singleMeshAsset(grid));
    const std::string message = loadError(file);
    EXPECT_TRUE(contains(message, "index out of range"));
    EXPECT_TRUE(contains(message, std::to_string(grid.positions.size()) + " vertices"));
}

TEST(GltfLoader, ReportsNonFinitePosition) {
    const fs::path file = test::scratchDir("gltf_nan") / "nan.gltf";
    GltfPrimitive grid = test::gridPrimitive(1, 1, 1);
    grid.positions[2].y = std::numeric_limits<float>::quiet_NaN();
    test::writeGltf(file, test::singleMeshAsset(grid));
    const std::string message = loadError(file);
    EXPECT_TRUE(contains(message, "non-finite"));
    EXPECT_TRUE(contains(message, "(POSITION of mesh \"Mesh\" primitive 0)"));
}

TEST(GltfLoader, ReportsAttributeCountMismatch) {
    const fs::path file = test::scratchDir("gltf_count_mismatch") / "mismatch.gltf";
    GltfPrimitive grid = test::gridPrimitive(1, 1, 2);
    grid.normals.pop_back();
    test::writeGltf(file, test::singleMeshAsset(grid));
    EXPECT_TRUE(contains(loadError(file), "NORMAL of mesh"));
}

TEST(GltfLoader, RefusesBufferUriOutsideTheFolder) {
    const fs::path dir = test::scratchDir("gltf_escape");
    fs::create_directories(dir / "model");
    const fs::path file = dir / "model" / "scene.gltf";
    test::writeGltf(file, test::singleMeshAsset(test::gridPrimitive(1, 1, 1)),
                    BufferStorage::ExternalFile, "../secret.bin");
    ASSERT_TRUE(fs::exists(dir / "secret.bin"));
    const std::string message = loadError(file);
    EXPECT_TRUE(contains(message, "\"../secret.bin\""));
    EXPECT_TRUE(contains(message, "folder"));
}

TEST(GltfLoader, RefusesAbsoluteBufferUri) {
    const fs::path dir = test::scratchDir("gltf_absolute");
    test::GltfDocument doc = test::buildGltf(test::singleMeshAsset(test::gridPrimitive(1, 1, 1)));
    test::writeGltf(dir / "real.gltf", doc);
    const std::string absolute = fs::absolute(dir / "real.bin").generic_string();
    doc.json["buffers"][0]["uri"] = absolute;
    test::writeGltf(dir / "absolute.gltf", doc);
    const std::string message = loadError(dir / "absolute.gltf");
    EXPECT_TRUE(contains(message, absolute));
    EXPECT_TRUE(contains(message, "absolute"));
}

// Draco and meshopt: gltf_compressed_test.cpp.

TEST(GltfLoader, ReportsFilesThatAreNotGltf) {
    const fs::path dir = test::scratchDir("gltf_not_gltf");
    const std::pair<std::string, std::string> files[] = {
        {"notes.gltf", "hello, this is text"},
        {"image.glb", "\x89PNG\r\n\x1a\n not a model"},
        {"package.gltf", R"({"name": "grass", "version": "1.0"})"},
        {"empty.gltf", ""}};
    for (const auto& [name, contents] : files) {
        std::ofstream(dir / name, std::ios::binary) << contents;
        const std::string message = loadError(dir / name);
        EXPECT_TRUE(contains(message, "glTF")) << message;
    }
}

// Artists bring meshes in whatever their tool saves: a file that is another mesh format is named
// as such, with the way to a glTF.
TEST(GltfLoader, AnotherMeshFormatIsNamedWithTheWayToGltf) {
    const fs::path dir = test::scratchDir("gltf_other_formats");
    const std::pair<std::string, std::string> files[] = {
        {"rock.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n"},
        {"rock.fbx", std::string("Kaydara FBX Binary  \0\x1a\0", 23)},
        {"scan.bin", "ply\nformat ascii 1.0\nend_header\n"},
        {"part.STL", "solid part\nendsolid part\n"}};
    const char* kinds[] = {"an OBJ file", "an FBX file", "a PLY file", "an STL file"};
    for (std::size_t i = 0; i < std::size(files); ++i) {
        std::ofstream(dir / files[i].first, std::ios::binary) << files[i].second;
        const std::string message = loadError(dir / files[i].first);
        EXPECT_TRUE(contains(message, kinds[i])) << message;
        EXPECT_TRUE(contains(message, "export the mesh as .glb or .gltf")) << message;
    }
    // A text file that is no known format says only that it is not glTF.
    std::ofstream(dir / "notes.txt") << "hello";
    EXPECT_FALSE(contains(loadError(dir / "notes.txt"), "looks like"));
}

TEST(GltfLoader, ReportsAbsurdlyDeepJsonInsteadOfOverflowingTheStack) {
    const fs::path file = test::scratchDir("gltf_deep_json") / "deep.gltf";
    const std::size_t depth = 200000;
    std::ofstream(file) << R"({"asset": {"version": "2.0"}, "extras": )" << std::string(depth, '[')
                        << std::string(depth, ']') << "}";
    EXPECT_TRUE(contains(loadError(file), "nested"));
}

TEST(GltfLoader, ReportsFileWithoutTriangles) {
    const fs::path file = test::scratchDir("gltf_only_lines") / "lines.gltf";
    GltfPrimitive lines;
    lines.mode = test::PrimitiveMode::LineStrip;
    lines.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    test::writeGltf(file, test::singleMeshAsset(lines));
    EXPECT_TRUE(contains(loadError(file), "contains no triangles"));
}

// glTF's data: URIs follow RFC 2397, whose data may be percent-encoded octets instead of base64;
// tinygltf reads only base64. Before, such a buffer refused the model ("not base64").
TEST(GltfLoader, ReadsAPercentEncodedDataUriBuffer) {
    const fs::path dir = test::scratchDir("gltf_percent_data_uri");
    const GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 2));
    test::writeGltf(dir / "plain.gltf", asset);
    const GltfImport plain = loadOk(dir / "plain.gltf");
    test::GltfDocument doc = test::buildGltf(asset);
    std::string encoded;
    for (const std::uint8_t byte : doc.bin) {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%%%02X", unsigned(byte));
        encoded += hex;
    }
    doc.json["buffers"][0]["uri"] = "data:application/octet-stream," + encoded;
    std::ofstream(dir / "percent.gltf") << doc.json.dump();
    expectSameMesh(loadOk(dir / "percent.gltf"), plain);
    // Shorter than it says, or without the comma before its data: refused, saying so.
    doc.json["buffers"][0]["uri"] = "data:application/octet-stream," + encoded.substr(0, 30);
    std::ofstream(dir / "short.gltf") << doc.json.dump();
    EXPECT_TRUE(contains(loadError(dir / "short.gltf"), "truncated"));
    doc.json["buffers"][0]["uri"] = "data:application/octet-stream";
    std::ofstream(dir / "nocomma.gltf") << doc.json.dump();
    EXPECT_TRUE(contains(loadError(dir / "nocomma.gltf"), "without the comma"));
}

// A buffer that no bufferView reads holds nothing of the geometry: glTF allows one without any
// source (the glTF validator's own valid files have placeholders, a missing file's and a
// non-base64 data: URI's). Before, the first such buffer refused the whole model ("buffer 1 has
// no uri …"). A buffer in use keeps every check (ReportsMissingBufferFile).
TEST(GltfLoader, ABufferThatNoViewReadsIsNotRead) {
    const fs::path dir = test::scratchDir("gltf_unused_buffers");
    const GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 2));
    const GltfImport plain = loadOk([&] {
        test::writeGltf(dir / "plain.gltf", asset);
        return dir / "plain.gltf";
    }());
    test::GltfDocument doc = test::buildGltf(asset);
    doc.json["buffers"].push_back({{"byteLength", 4096}});                             // no source
    doc.json["buffers"].push_back({{"byteLength", 16}, {"uri", "gone.bin"}});          // missing
    doc.json["buffers"].push_back({{"byteLength", 1}, {"uri", "data:text/plain,0"}});  // not base64
    doc.json["buffers"].push_back({{"byteLength", 1e15}, {"uri", "../../etc/passwd"}});
    for (const auto storage : {BufferStorage::ExternalFile, BufferStorage::Glb}) {
        const fs::path file = dir / (storage == BufferStorage::Glb ? "extra.glb" : "extra.gltf");
        test::writeGltf(file, doc, storage);
        expectSameMesh(loadOk(file), plain);
    }
    // The same buffer read by a view (here an unused one) is checked as before.
    doc.json["bufferViews"].push_back({{"buffer", 2}, {"byteLength", 8}});
    test::writeGltf(dir / "read.gltf", doc);
    EXPECT_TRUE(contains(loadError(dir / "read.gltf"), "gone.bin"));
}

// A grass export imported as ground (New from mesh, `grass render --mesh`): its terrain is the
// ground, the blades under its blade group nodes are not. Before, grass grew on the exported
// blades too, and meadow's export made a 902k-triangle ground of its 18k-triangle terrain.
// The export marks the group (extras "grass_blades": true); older exports are known by the
// scene's "grass_runtime" extras and a root named "<layer> blades".
GltfAsset terrainAndBladeGroup() {
    GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(4, 4, 2), "terrain");  // 8 triangles
    asset.meshes.push_back({"unit blade", {test::gridPrimitive(0.1f, 0.1f, 1)}});   // 2 triangles
    GltfNode cell;  // node 1
    cell.name = "grass blades cell 0";
    cell.mesh = 1;
    cell.instances.resize(3);
    asset.nodes.push_back(cell);
    GltfNode group;  // node 2
    group.name = "grass blades";
    group.children = {1};
    asset.nodes.push_back(group);
    asset.sceneNodes = {0, 2};
    return asset;
}

TEST(GltfLoader, AGrassExportsBladesAreLeftOutOfTheGround) {
    const fs::path dir = test::scratchDir("gltf_grass_export");
    const GltfAsset asset = terrainAndBladeGroup();

    test::GltfDocument marked = test::buildGltf(asset);
    marked.json["nodes"][2]["extras"] = {{"grass_blades", true}};
    test::writeGltf(dir / "marked.gltf", marked);
    const GltfImport ground = loadOk(dir / "marked.gltf");
    EXPECT_EQ(ground.mesh->n_faces(), 8u);
    EXPECT_TRUE(anyNoteContains(ground, "a grass export: its blades left out (3 placements)"));

    test::GltfDocument older = test::buildGltf(asset);
    older.json["scenes"][0]["extras"] = {{"grass_runtime", {{"version", 1}}}};
    test::writeGltf(dir / "older.gltf", older);
    EXPECT_EQ(loadOk(dir / "older.gltf").mesh->n_faces(), 8u);

    // Without either sign it is somebody's scene with a node called "... blades": all of it.
    test::writeGltf(dir / "plain.gltf", asset);
    EXPECT_EQ(loadOk(dir / "plain.gltf").mesh->n_faces(), 8u + 3u * 2u);
    test::GltfDocument unmarked = test::buildGltf(asset);
    unmarked.json["nodes"][2]["extras"] = {{"grass_blades", false}};
    test::writeGltf(dir / "unmarked.gltf", unmarked);
    EXPECT_EQ(loadOk(dir / "unmarked.gltf").mesh->n_faces(), 8u + 3u * 2u);

    // Blades alone are no ground, and the error says why.
    test::GltfDocument bladesOnly = marked;
    bladesOnly.json["scenes"][0]["nodes"] = {2};
    test::writeGltf(dir / "blades-only.gltf", bladesOnly);
    EXPECT_TRUE(contains(loadError(dir / "blades-only.gltf"), "only the blades of a grass export"));
}


// CESIUM_RTC (3D Tiles): the centre is not added (it would only be moved back), the model is
// grown in its local frame, and the note says so; required, it is not refused as an unknown
// extension that may change the geometry.
TEST(GltfLoader, ACesiumRtcCentreIsNotedNotApplied) {
    const fs::path file = test::scratchDir("gltf_cesium_rtc") / "tile.gltf";
    test::GltfDocument doc = test::buildGltf(test::singleMeshAsset(test::gridPrimitive(4, 4, 2)));
    doc.json["extensions"]["CESIUM_RTC"] = {{"center", {6378137.0, 0.0, 0.0}}};
    doc.json["extensionsUsed"] = {"CESIUM_RTC"};
    doc.json["extensionsRequired"] = {"CESIUM_RTC"};
    test::writeGltf(file, doc);
    const GltfImport tile = loadOk(file);
    EXPECT_EQ(tile.mesh->n_faces(), 8u);
    EXPECT_TRUE(anyNoteContains(tile, "CESIUM_RTC centre (6378137.0, 0.0, 0.0) not applied"));
    EXPECT_EQ(tile.origin, glm::dvec3(0.0)) << "left where the file has it";
}

}  // namespace
}  // namespace grass::core
