#include "support/rules_terrain.h"

#include <cmath>
#include <fstream>
#include <glm/gtc/quaternion.hpp>

#include <gtest/gtest.h>

#include "support/gltf_writer.h"

namespace grass::test {

namespace {

// A latitude-longitude sphere whose radius varies by `bumps` (0: round), outward winding.
GltfPrimitive spherePrimitive(glm::vec3 centre, float radius, float bumps) {
    constexpr int RINGS = 12, SEGMENTS = 24;
    constexpr float PI = 3.14159265f;
    GltfPrimitive p;
    for (int r = 0; r <= RINGS; ++r)
        for (int s = 0; s <= SEGMENTS; ++s) {
            const float theta = PI * float(r) / RINGS, phi = 2.0f * PI * float(s) / SEGMENTS;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            const float scale = 1.0f + bumps * std::sin(3.0f * theta) * std::sin(2.0f * phi);
            p.positions.push_back(centre + radius * scale * n);
            p.normals.push_back(n);
        }
    for (int r = 0; r < RINGS; ++r)
        for (int s = 0; s < SEGMENTS; ++s) {
            const auto a = static_cast<std::uint32_t>(r * (SEGMENTS + 1) + s);
            const std::uint32_t b = a + 1, c = a + SEGMENTS + 1, d = c + 1;
            // Seen from outside, (a, b, d) and (a, d, c) turn counter-clockwise.
            if (r != 0)
                p.indices.insert(p.indices.end(), {a, b, d});
            if (r != RINGS - 1)
                p.indices.insert(p.indices.end(), {a, d, c});
        }
    return p;
}

GltfPrimitive withoutUvs(GltfPrimitive p, int material) {
    p.uvs.clear();
    p.material = material;
    return p;
}

}  // namespace

void writeRulesTerrain(const std::filesystem::path& file) {
    GltfAsset asset;
    asset.materials = {{"Soil", {0.30f, 0.22f, 0.13f, 1.0f}},
                       {"Rock", {0.42f, 0.40f, 0.38f, 1.0f}},
                       {"Cloud", {0.95f, 0.95f, 0.97f, 1.0f}},
                       {"Bark", {0.25f, 0.16f, 0.09f, 1.0f}},
                       {"Leaves", {0.16f, 0.36f, 0.10f, 1.0f}}};
    asset.meshes = {
        {"GroundMesh", {withoutUvs(gridPrimitive(20.0f, 20.0f, 20), 0)}},
        {"CliffMesh", {withoutUvs(gridPrimitive(4.0f, 8.0f, 4), 1)}},
        {"CloudMesh", {withoutUvs(spherePrimitive(glm::vec3(0.0f), RULES_CLOUD_RADIUS, 0.0f), 2)}},
        {"TrunkMesh", {withoutUvs(boxPrimitive({-0.2f, 0.0f, -0.2f}, {0.2f, 2.5f, 0.2f}), 3)}},
        {"CanopyMesh", {withoutUvs(spherePrimitive({0.0f, 3.2f, 0.0f}, 1.6f, 0.15f), 4)}},
    };
    const auto node = [](const char* name, int mesh) {
        GltfNode n;
        n.name = name;
        n.mesh = mesh;
        return n;
    };
    // The cliff: the grid (normal +Y) turned 70° about +Z, its lower edge (x = -2) on the ground.
    const float slope = glm::radians(RULES_CLIFF_SLOPE_DEG);
    GltfNode cliff = node("Cliff", 1);
    cliff.rotation = glm::angleAxis(slope, glm::vec3(0.0f, 0.0f, 1.0f));
    cliff.translation = {7.0f, 2.0f * std::sin(slope), 0.0f};
    GltfNode cloud = node("Cloud", 2);
    cloud.translation = RULES_CLOUD_CENTRE;
    GltfNode tree = node("Tree", -1);
    tree.children = {4, 5};
    tree.translation = RULES_TREE_BASE;
    asset.nodes = {node("Ground", 0), cliff, cloud, tree, node("Trunk", 3), node("Canopy", 4)};
    writeGltf(file, asset, BufferStorage::Glb);
}

core::LoadedProject writeRulesTerrainProject(const std::filesystem::path& folder,
                                             const std::string& projectJson) {
    writeRulesTerrain(folder / "terrain.glb");
    std::ofstream(folder / "project.json") << projectJson;
    auto loaded = core::loadProject(folder);
    EXPECT_TRUE(loaded) << loaded.error().str();
    return loaded ? std::move(*loaded) : core::LoadedProject{};
}

}  // namespace grass::test
