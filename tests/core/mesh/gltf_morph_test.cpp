// Morph targets load at their default weights (core/mesh/gltf_morph.h): base + Σ w_i · target_i,
// the weights the node's, else the mesh's (glTF 2.0 §3.7.2.2).
#include "mesh/gltf_morph.h"

#include <gtest/gtest.h>

#include "gltf_pose_fixtures.h"
#include "mesh/gltf_loader.h"
#include "support/gltf_load_expect.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
using test::addVec3Accessor;
using test::GltfDocument;

// Like Khronos' SimpleMorph: a triangle with its apex at (0.5, 0.5), mesh "Tri" (node 0), and
// two targets that move only the apex: target 0 by (0, 2, 0), plain floats; target 1 by
// (1, 0, 0), a sparse accessor over zeros.
GltfDocument morphedTriangle(const std::vector<double>& meshWeights) {
    test::GltfPrimitive primitive;
    primitive.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 0.5f, 0}};
    GltfDocument doc = test::buildGltf(test::singleMeshAsset(primitive, "Tri"));
    const int up = addVec3Accessor(doc, {{0, 0, 0}, {0, 0, 0}, {0, 2, 0}});
    doc.json["accessors"].push_back(
        {{"componentType", test::FLOAT},
         {"count", 3},
         {"type", "VEC3"},
         {"sparse",
          {{"count", 1},
           {"indices",
            {{"bufferView", test::addBufferView(doc, std::vector<std::uint8_t>{2})},
             {"componentType", test::UNSIGNED_BYTE}}},
           {"values",
            {{"bufferView", test::addBufferView(doc, std::vector<glm::vec3>{{1, 0, 0}})}}}}}});
    const int right = static_cast<int>(doc.json["accessors"].size() - 1);
    doc.json["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", up}}, {{"POSITION", right}}};
    if (!meshWeights.empty())
        doc.json["meshes"][0]["weights"] = meshWeights;
    return doc;
}

fs::path write(const GltfDocument& doc, const std::string& name) {
    return test::writeDataUriGltf(doc, "gltf_morph", name);
}

GltfImport loadOk(const fs::path& file) { return test::loadGltfExpectingSuccess(file); }

bool anyNoteContains(const std::vector<std::string>& notes, const std::string& part) {
    for (const auto& note : notes)
        if (note.find(part) != std::string::npos)
            return true;
    return false;
}

// The highest vertex with x in [xMin, xMax): the apex of a triangle there.
glm::vec3 apex(const SurfaceMesh& mesh, float xMin = -1e9f, float xMax = 1e9f) {
    glm::vec3 best(0.0f, -1e9f, 0.0f);
    for (const auto vh : mesh.vertices()) {
        const glm::vec3 p = toGlm(mesh.point(vh));
        if (p.x >= xMin && p.x < xMax && p.y > best.y)
            best = p;
    }
    return best;
}

TEST(GltfMorph, MeshWeightsMoveTheShapeAsTheSpecSays) {
    const GltfImport import = loadOk(write(morphedTriangle({0.5, 0.5}), "mesh_weights"));
    // (0.5, 0.5) + 0.5 · (0, 2) + 0.5 · (1, 0).
    const glm::vec3 top = apex(import.mesh);
    EXPECT_NEAR(top.x, 1.0f, 1e-6f);
    EXPECT_NEAR(top.y, 1.5f, 1e-6f);
    EXPECT_TRUE(anyNoteContains(import.notes,
                                "mesh \"Tri\": morph targets applied at their default weights"));
}

// One mesh, two nodes: the first takes the mesh's weights, the second (10 m along x) its own.
TEST(GltfMorph, NodeWeightsOverrideTheMeshsWeights) {
    GltfDocument doc = morphedTriangle({0.5, 0.5});
    nlohmann::json second = doc.json["nodes"][0];
    second["name"] = "Second";
    second["translation"] = {10.0, 0.0, 0.0};
    second["weights"] = {1.0, 0.0};
    doc.json["nodes"].push_back(second);
    doc.json["scenes"][0]["nodes"] = {0, 1};
    const GltfImport import = loadOk(write(doc, "node_weights"));
    const glm::vec3 first = apex(import.mesh, -1.0f, 5.0f);
    EXPECT_NEAR(first.x, 1.0f, 1e-6f);
    EXPECT_NEAR(first.y, 1.5f, 1e-6f);
    // (10.5, 0.5) + 1 · (0, 2).
    const glm::vec3 moved = apex(import.mesh, 5.0f);
    EXPECT_NEAR(moved.x, 10.5f, 1e-6f);
    EXPECT_NEAR(moved.y, 2.5f, 1e-6f);
}

// Targets without weights are the base shape, and nothing to tell the user about.
TEST(GltfMorph, ZeroWeightsKeepTheBaseShapeWithoutANote) {
    const GltfImport import = loadOk(write(morphedTriangle({}), "no_weights"));
    EXPECT_NEAR(apex(import.mesh).y, 0.5f, 1e-6f);
    EXPECT_FALSE(anyNoteContains(import.notes, "morph")) << import.notes.size() << " notes";
}

// The targets are sound, only the weights are not: the base shape with a note serves a user
// better than refusing a file that viewers draw.
TEST(GltfMorph, MoreWeightsThanTargetsKeepTheBaseShapeWithANote) {
    const GltfImport import = loadOk(write(morphedTriangle({0.5, 0.5, 0.5}), "three_weights"));
    EXPECT_NEAR(apex(import.mesh).y, 0.5f, 1e-6f);
    EXPECT_TRUE(anyNoteContains(import.notes,
                                "mesh \"Tri\" primitive 0 has 3 default weights (the "
                                "mesh's) for 2 morph targets: its base shape used"));
}

// Where the wrong weights came from is named, so the user knows what to fix.
TEST(GltfMorph, WrongWeightsOfANodeNameTheNode) {
    GltfDocument doc = morphedTriangle({});
    doc.json["nodes"][0]["name"] = "Leaf";
    doc.json["nodes"][0]["weights"] = {1.0};
    const GltfImport import = loadOk(write(doc, "node_wrong_weights"));
    EXPECT_NEAR(apex(import.mesh).y, 0.5f, 1e-6f);
    EXPECT_TRUE(anyNoteContains(import.notes, "has 1 default weights (node 0 \"Leaf\"'s) for 2 "
                                              "morph targets: its base shape used"))
        << (import.notes.empty() ? std::string("no notes") : import.notes.front());
}

// Target data that does not match the vertices is corrupt, like any attribute of the wrong
// count: refused, with the accessor and target named.
TEST(GltfMorph, ATargetOfTheWrongCountIsRefusedByName) {
    GltfDocument doc = morphedTriangle({0.5, 0.5});
    doc.json["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] =
        addVec3Accessor(doc, {{0, 0, 0}, {0, 1, 0}});
    const std::string error = test::loadGltfError(write(doc, "short_target"));
    EXPECT_NE(error.find("(POSITION of mesh \"Tri\" primitive 0 morph target 0) has 2 elements, "
                         "but POSITION has 3"),
              std::string::npos)
        << error;
}

}  // namespace
}  // namespace grass::core
