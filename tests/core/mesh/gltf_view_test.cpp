// What a stock viewer draws of a glTF (core/mesh/gltf_view.h): every placed triangle in world
// space, coloured baseColorFactor × COLOR_0 × the instance's _COLOR_0; bad colour data refused
// with the file and the accessor named.
#include "mesh/gltf_view.h"

#include <gtest/gtest.h>

#include <cstring>

#include "support/gltf_writer.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::GltfAsset;
using test::GltfDocument;

// Appends `bytes` to the document's buffer as a new bufferView and an accessor over it.
int addAccessor(GltfDocument& doc, const void* bytes, std::size_t size, int componentType,
                const char* type, std::size_t count, bool normalized) {
    while (doc.bin.size() % 4 != 0)
        doc.bin.push_back(0);
    const std::size_t offset = doc.bin.size();
    doc.bin.resize(offset + size);
    std::memcpy(doc.bin.data() + offset, bytes, size);
    doc.json["buffers"][0]["byteLength"] = doc.bin.size();
    doc.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
    json accessor = {{"bufferView", doc.json["bufferViews"].size() - 1},
                     {"componentType", componentType}, {"count", count}, {"type", type}};
    if (normalized)
        accessor["normalized"] = true;
    doc.json["accessors"].push_back(accessor);
    return int(doc.json["accessors"].size() - 1);
}

// A 1 m quad (4 vertices) placed by one node as two GPU instances 5 m apart, with a material.
GltfDocument instancedQuad() {
    GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 1));
    asset.nodes[0].instances.resize(2);
    asset.nodes[0].instances[1].translation = {5.0f, 0.0f, 0.0f};
    GltfDocument doc = test::buildGltf(asset);
    doc.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1.0, 1.0, 1.0}}}}}};
    doc.json["meshes"][0]["primitives"][0]["material"] = 0;
    return doc;
}

json& instancing(GltfDocument& doc) {
    return doc.json["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
}

TEST(GltfView, ColoursAreBaseColourTimesVertexColourTimesInstanceColour) {
    GltfDocument doc = instancedQuad();
    // COLOR_0 as normalized unsigned bytes, RGBA: every vertex (1, 0.5, 1, 1).
    const std::uint8_t vertexColors[16] = {255, 128, 255, 255, 255, 128, 255, 255,
                                           255, 128, 255, 255, 255, 128, 255, 255};
    doc.json["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
        addAccessor(doc, vertexColors, sizeof vertexColors, 5121, "VEC4", 4, true);
    // _COLOR_0 as float RGB: the second instance blue-ish.
    const float instanceColors[6] = {1.0f, 1.0f, 1.0f, 0.2f, 0.4f, 0.8f};
    instancing(doc)["_COLOR_0"] = addAccessor(doc, instanceColors, sizeof instanceColors, 5126, "VEC3", 2, false);
    const fs::path file = test::scratchDir("gltf_view_colours") / "quad.gltf";
    test::writeGltf(file, doc);

    auto view = loadGltfView(file, 1000);
    ASSERT_TRUE(view.ok()) << view.error().str();
    ASSERT_EQ(view->positions.size(), 8u);
    ASSERT_EQ(view->indices.size(), 12u);
    EXPECT_EQ(view->placedMeshes, 2u);
    const float half = 128.0f / 255.0f;
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(glm::distance(view->colors[i], glm::vec4(0.5f, half, 1.0f, 1.0f)), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(view->colors[4 + i], glm::vec4(0.1f, 0.4f * half, 0.8f, 1.0f)), 0.0f, 1e-6f);
        // The second instance stands 5 m along x; normals stay the grid's +Y.
        EXPECT_NEAR(view->positions[4 + i].x - view->positions[i].x, 5.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(view->normals[i], glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    }
}

TEST(GltfView, WithoutColoursEverythingIsWhiteAndAMirrorKeepsTheFrontFacingOut) {
    GltfAsset asset = test::singleMeshAsset(test::gridPrimitive(1, 1, 1));
    asset.nodes[0].scale = {-1.0f, 1.0f, 1.0f};
    const fs::path file = test::scratchDir("gltf_view_plain") / "mirrored.glb";
    test::writeGltf(file, asset, test::BufferStorage::Glb);
    auto view = loadGltfView(file, 1000);
    ASSERT_TRUE(view.ok()) << view.error().str();
    ASSERT_EQ(view->indices.size(), 6u);
    for (const glm::vec4& c : view->colors)
        EXPECT_EQ(c, glm::vec4(1.0f));
    // Counter-clockwise seen from +Y before the mirror, and still after it (winding reversed).
    for (std::size_t t = 0; t < view->indices.size(); t += 3) {
        const glm::vec3 a = view->positions[view->indices[t]], b = view->positions[view->indices[t + 1]],
                        c = view->positions[view->indices[t + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
    }
    for (const glm::vec3& n : view->normals)
        EXPECT_NEAR(n.y, 1.0f, 1e-6f);
}

TEST(GltfView, BadColourDataAndTooManyVerticesAreRefusedByName) {
    const fs::path dir = test::scratchDir("gltf_view_errors");
    {
        GltfDocument doc = instancedQuad();
        const float colors[3] = {1.0f, 0.0f, 0.0f};  // one colour for two instances
        instancing(doc)["_COLOR_0"] = addAccessor(doc, colors, sizeof colors, 5126, "VEC3", 1, false);
        test::writeGltf(dir / "count.gltf", doc);
        auto view = loadGltfView(dir / "count.gltf", 1000);
        ASSERT_FALSE(view.ok());
        EXPECT_NE(view.error().str().find("count.gltf"), std::string::npos) << view.error().str();
        EXPECT_NE(view.error().str().find("_COLOR_0 holds 1 colours for 2 instances"), std::string::npos)
            << view.error().str();
    }
    {
        GltfDocument doc = instancedQuad();
        const float uv[8] = {};
        doc.json["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
            addAccessor(doc, uv, sizeof uv, 5126, "VEC2", 4, false);
        test::writeGltf(dir / "type.gltf", doc);
        auto view = loadGltfView(dir / "type.gltf", 1000);
        ASSERT_FALSE(view.ok());
        EXPECT_NE(view.error().str().find("COLOR_0 must be VEC3 or VEC4"), std::string::npos)
            << view.error().str();
    }
    {
        test::writeGltf(dir / "big.gltf", instancedQuad());
        auto view = loadGltfView(dir / "big.gltf", 7);
        ASSERT_FALSE(view.ok());
        EXPECT_NE(view.error().str().find("more than 7 vertices"), std::string::npos) << view.error().str();
    }
}

}  // namespace
}  // namespace grass::core
