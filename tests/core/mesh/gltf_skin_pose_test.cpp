// Skinned meshes load in their skeleton's rest pose (core/mesh/gltf_skin_pose.h), as viewers
// show them, and broken skins are refused with the skin, accessor or mesh named.
#include "mesh/gltf_skin_pose.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>

#include "gltf_pose_fixtures.h"
#include "mesh/gltf_loader.h"
#include "mesh/gltf_view.h"
#include "support/gltf_load_expect.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
using test::addAccessor;
using test::GltfAsset;
using test::GltfDocument;
using test::GltfNode;

GltfNode joint(const std::string& name, glm::vec3 translation) {
    GltfNode node;
    node.name = name;
    node.translation = translation;
    return node;
}

// `primitive`, named "Body", placed by node 0 with skin 0 ("Armature", over `joints`, nodes 1..)
// and moved 100 m by that node: a skinned mesh ignores its node's transform (spec §3.7.3).
// JOINTS_0 and WEIGHTS_0 are left to the test.
GltfDocument skinnedAsset(test::GltfPrimitive primitive, const std::vector<GltfNode>& joints) {
    GltfAsset asset = test::singleMeshAsset(std::move(primitive), "Body");
    asset.nodes[0].translation = {100.0f, 0.0f, 0.0f};
    asset.nodes.insert(asset.nodes.end(), joints.begin(), joints.end());
    GltfDocument doc = test::buildGltf(asset);
    nlohmann::json jointNodes = nlohmann::json::array();
    for (std::size_t k = 0; k < joints.size(); ++k)
        jointNodes.push_back(k + 1);
    doc.json["skins"] = {{{"name", "Armature"}, {"joints", jointNodes}}};
    doc.json["nodes"][0]["skin"] = 0;
    return doc;
}

nlohmann::json& attributes(GltfDocument& doc) {
    return doc.json["meshes"][0]["primitives"][0]["attributes"];
}

// Three vertices each bound to the joints and weights given (JOINTS_0 as UNSIGNED_SHORT,
// WEIGHTS_0 as FLOAT).
void bindTriangle(GltfDocument& doc, const std::vector<std::uint16_t>& joints,
                  const std::vector<glm::vec4>& weights) {
    attributes(doc)["JOINTS_0"] = addAccessor(doc, joints, test::UNSIGNED_SHORT, "VEC4", 3);
    attributes(doc)["WEIGHTS_0"] = addAccessor(doc, weights, test::FLOAT, "VEC4", 3);
}

test::GltfPrimitive triangle() {
    test::GltfPrimitive primitive;
    primitive.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    return primitive;
}

fs::path write(const GltfDocument& doc, const std::string& name) {
    return test::writeDataUriGltf(doc, "gltf_skin", name);
}

GltfImport loadOk(const fs::path& file) { return test::loadGltfExpectingSuccess(file); }

std::string loadError(const fs::path& file) { return test::loadGltfError(file); }

bool anyNoteContains(const std::vector<std::string>& notes, const std::string& part) {
    for (const auto& note : notes)
        if (note.find(part) != std::string::npos)
            return true;
    return false;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, const std::string& what) {
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(actual[i], expected[i], 1e-5f) << what << " component " << i;
}

// Like Khronos' CesiumMan: a 1.8 m figure modelled +Z up whose root joint turns it +Y up.
TEST(GltfSkin, AFigureModelledZUpStandsUpOnItsRootJoint) {
    GltfNode root = joint("Root", glm::vec3(0.0f));
    root.rotation = glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0));
    GltfDocument doc =
        skinnedAsset(test::boxPrimitive({-0.2f, -0.1f, 0.0f}, {0.2f, 0.1f, 1.8f}), {root});
    const std::size_t n = 24;  // the box's vertices
    attributes(doc)["JOINTS_0"] =
        addAccessor(doc, std::vector<std::uint8_t>(4 * n, 0), test::UNSIGNED_BYTE, "VEC4", n);
    attributes(doc)["WEIGHTS_0"] =
        addAccessor(doc, std::vector<glm::vec4>(n, {1, 0, 0, 0}), test::FLOAT, "VEC4", n);
    // Identity inverse bind matrices, given explicitly.
    doc.json["skins"][0]["inverseBindMatrices"] =
        addAccessor(doc, std::vector<glm::mat4>(1, glm::mat4(1.0f)), test::FLOAT, "MAT4", 1);
    const fs::path file = write(doc, "z_up_figure");

    const GltfImport import = loadOk(file);
    const Bounds bounds = meshBounds(import.mesh);
    expectNear(bounds.min, {-0.2f, 0.0f, -0.1f}, "min");
    expectNear(bounds.max, {0.2f, 1.8f, 0.1f}, "max");
    EXPECT_TRUE(anyNoteContains(import.notes,
                                "mesh \"Body\" is skinned: placed in its "
                                "skeleton's rest pose (skin \"Armature\")"));
    // The stock viewer's picture shares the walk: it stands too.
    const auto view = loadGltfView(file, 1000);
    ASSERT_TRUE(view.ok()) << view.error().str();
    float top = 0.0f;
    for (const glm::vec3& p : view->positions)
        top = std::max(top, p.y);
    EXPECT_NEAR(top, 1.8f, 1e-5f);
}

// Joint matrices T(1, 0, 0) (a joint at x = 2 over an inverse bind matrix of x = -1) and
// T(0, 4, 0), half each: the average, T(0.5, 2, 0). The weights are normalized bytes 128/255
// each, summing to 1.004: divided by their sum they are exactly a half. A vertex without weight
// stays as stored.
TEST(GltfSkin, TwoJointsAtHalfWeightEachAverageTheirTransforms) {
    GltfDocument doc = skinnedAsset(triangle(), {joint("A", {2, 0, 0}), joint("B", {0, 4, 0})});
    attributes(doc)["JOINTS_0"] =
        addAccessor(doc, std::vector<std::uint16_t>{0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0},
                    test::UNSIGNED_SHORT, "VEC4", 3);
    attributes(doc)["WEIGHTS_0"] =
        addAccessor(doc, std::vector<std::uint8_t>{128, 128, 0, 0, 128, 128, 0, 0, 0, 0, 0, 0},
                    test::UNSIGNED_BYTE, "VEC4", 3, true);
    const std::vector<glm::mat4> inverseBind{glm::translate(glm::mat4(1.0f), glm::vec3(-1, 0, 0)),
                                             glm::mat4(1.0f)};
    doc.json["skins"][0]["inverseBindMatrices"] =
        addAccessor(doc, inverseBind, test::FLOAT, "MAT4", 2);

    const GltfImport import = loadOk(write(doc, "two_joints"));
    // (0,0,0) -> (0.5,2,0), (1,0,0) -> (1.5,2,0), (0,1,0) unweighted.
    const Bounds bounds = meshBounds(import.mesh);
    expectNear(bounds.min, {0.0f, 1.0f, 0.0f}, "min");
    expectNear(bounds.max, {1.5f, 2.0f, 0.0f}, "max");
}

TEST(GltfSkin, MissingInverseBindMatricesAreTheIdentity) {
    GltfDocument doc = skinnedAsset(triangle(), {joint("Up", {0, 3, 0})});
    bindTriangle(doc, std::vector<std::uint16_t>(12, 0), std::vector<glm::vec4>(3, {1, 0, 0, 0}));
    ASSERT_FALSE(doc.json["skins"][0].contains("inverseBindMatrices"));

    const Bounds bounds = meshBounds(loadOk(write(doc, "no_inverse_bind")).mesh);
    expectNear(bounds.min, {0.0f, 3.0f, 0.0f}, "min");
    expectNear(bounds.max, {1.0f, 4.0f, 0.0f}, "max");
}

TEST(GltfSkin, AJointIndexBeyondTheSkinIsRefusedByName) {
    GltfDocument doc = skinnedAsset(triangle(), {joint("Up", {0, 3, 0})});
    bindTriangle(doc, {0, 0, 0, 0, 5, 0, 0, 0, 0, 0, 0, 0},
                 std::vector<glm::vec4>(3, {1, 0, 0, 0}));
    const std::string error = loadError(write(doc, "joint_out_of_range"));
    EXPECT_NE(error.find("mesh \"Body\" primitive 0: JOINTS_0 holds joint 5 at element 1, but "
                         "skin \"Armature\" has 1 joints"),
              std::string::npos)
        << error;
}

// Unweighted slots may hold any index: exporters pad with them and viewers draw such files.
TEST(GltfSkin, AnUnweightedJointIndexBeyondTheSkinIsIgnored) {
    GltfDocument doc = skinnedAsset(triangle(), {joint("Up", {0, 3, 0})});
    bindTriangle(doc, {0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0},
                 std::vector<glm::vec4>(3, {1, 0, 0, 0}));
    EXPECT_NEAR(meshBounds(loadOk(write(doc, "padded_joints")).mesh).min.y, 3.0f, 1e-5f);
}

TEST(GltfSkin, BrokenSkinsAreRefusedByName) {
    const auto brokenBy = [](const std::function<void(GltfDocument&)>& damage) {
        GltfDocument doc = skinnedAsset(triangle(), {joint("A", {0, 3, 0}), joint("B", {0, 1, 0})});
        bindTriangle(doc, std::vector<std::uint16_t>(12, 0),
                     std::vector<glm::vec4>(3, {1, 0, 0, 0}));
        damage(doc);
        return loadError(write(doc, "broken"));
    };
    const std::string shortMatrices = brokenBy([](GltfDocument& doc) {
        doc.json["skins"][0]["inverseBindMatrices"] =
            addAccessor(doc, std::vector<glm::mat4>(1, glm::mat4(1.0f)), test::FLOAT, "MAT4", 1);
    });
    EXPECT_NE(shortMatrices.find("(inverseBindMatrices of skin \"Armature\") holds 1 matrices "
                                 "for 2 joints"),
              std::string::npos)
        << shortMatrices;
    const std::string notANode =
        brokenBy([](GltfDocument& doc) { doc.json["skins"][0]["joints"][1] = 9; });
    EXPECT_NE(notANode.find("skin \"Armature\": joint 1 is node 9, but the file has 3 nodes"),
              std::string::npos)
        << notANode;
    const std::string noSuchSkin =
        brokenBy([](GltfDocument& doc) { doc.json["nodes"][0]["skin"] = 4; });
    EXPECT_NE(noSuchSkin.find("node 0 \"Body\" refers to skin 4, but the file has 1 skins"),
              std::string::npos)
        << noSuchSkin;
    const std::string weightsOnly =
        brokenBy([](GltfDocument& doc) { attributes(doc).erase("JOINTS_0"); });
    EXPECT_NE(weightsOnly.find("has WEIGHTS_0 without JOINTS_0"), std::string::npos) << weightsOnly;
    const std::string shortJoints = brokenBy([](GltfDocument& doc) {
        attributes(doc)["JOINTS_0"] =
            addAccessor(doc, std::vector<std::uint16_t>(8, 0), test::UNSIGNED_SHORT, "VEC4", 2);
    });
    EXPECT_NE(shortJoints.find("(JOINTS of mesh \"Body\" primitive 0) has 2 elements, but "
                               "POSITION has 3"),
              std::string::npos)
        << shortJoints;
}

}  // namespace
}  // namespace grass::core
