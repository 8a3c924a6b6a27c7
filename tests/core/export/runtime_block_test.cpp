// Issue 28: every export carries the scene's behaviour (core/export/runtime_block.h) — the raw
// export in manifest.json's "runtime" with the meshes and the baked shading as files, glTF in its
// scene's extras.grass_runtime with the baked shading as instance attributes — and what travels
// is the project's, value for value.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <tuple>

#include <nlohmann/json.hpp>

#include "export/export.h"
#include "mesh/gltf_loader.h"
#include "scene/frame_lighting.h"
#include "support/gltf_writer.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Windy {
    LoadedProject loaded;
    Scene scene;
};

// tests/data/projects/windy: a gusty breeze, a vortex on a path, a ball rolling through.
Windy buildWindy() {
    auto loaded = loadProject(test::sourceDir() / "tests/data/projects/windy");
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = buildScene(*loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return {std::move(*loaded), std::move(*scene)};
}

json readJson(const fs::path& file) {
    auto text = readFile(file);
    EXPECT_TRUE(text.ok()) << file;
    return text ? json::parse(*text) : json();
}

glm::vec3 vec3Of(const json& v) {
    return {v[0].get<float>(), v[1].get<float>(), v[2].get<float>()};
}

ExportReport exportAs(const Windy& windy, ExportFormat format, const fs::path& dir) {
    ExportOptions options;
    options.format = format;
    options.outDir = dir;
    auto report = exportProject(windy.loaded, windy.scene, options, {});
    EXPECT_TRUE(report.ok()) << report.error().str();
    return report ? *report : ExportReport{};
}

TEST(RuntimeBlock, TheRawExportCarriesTheProjectsBehaviour) {
    const Windy windy = buildWindy();
    const fs::path dir = test::scratchDir("runtime_block_raw");
    exportAs(windy, ExportFormat::Raw, dir);
    const json manifest = readJson(dir / "manifest.json");
    const json& runtime = manifest["runtime"];
    const Project& project = windy.loaded.project;
    EXPECT_EQ(runtime["version"], 1);

    EXPECT_EQ(runtime["physics"]["step_s"].get<float>(), project.physics.dtS);
    EXPECT_EQ(runtime["physics"]["gravity_strength"].get<float>(), project.physics.gravity.w);
    EXPECT_EQ(runtime["physics"]["crushed_recovery_floor"].get<float>(),
              project.physics.crushedRecoveryFloor);
    ASSERT_EQ(runtime["wind"].size(), 2u);
    EXPECT_EQ(runtime["wind"][0]["kind"], "directional");
    EXPECT_EQ(runtime["wind"][0]["gust"].get<float>(), project.wind[0].source.gust);
    EXPECT_EQ(runtime["wind"][1]["kind"], "vortex");
    EXPECT_EQ(runtime["wind"][1]["name"], "twister");
    ASSERT_EQ(runtime["wind"][1]["path"].size(), project.wind[1].source.path.size());
    EXPECT_EQ(vec3Of(runtime["wind"][1]["path"][1]["position"]),
              project.wind[1].source.path[1].posWorld);

    ASSERT_EQ(runtime["colliders"].size(), 1u);
    const json& ball = runtime["colliders"][0];
    EXPECT_EQ(ball["name"], "ball");
    EXPECT_EQ(ball["sphere_count"], 1);
    ASSERT_EQ(ball["path"].size(), 2u);
    EXPECT_EQ(ball["path"][1]["time_s"].get<float>(), 1.0f);
    EXPECT_EQ(runtime["spheres"][0]["radius_m"].get<float>(), 0.4f);

    const LightingBlock lighting = frameLighting(project.lighting, project.sun,
                                                 project.render.skyColor, project.render.groundColor);
    EXPECT_EQ(vec3Of(runtime["lighting"]["sun_direction"]), lighting.sunDirection);
    EXPECT_EQ(runtime["lighting"]["sss"].get<float>(), lighting.sss);
    EXPECT_EQ(runtime["render"]["strip_segments"], project.render.stripSegments);
    EXPECT_EQ(runtime["render"]["lod_distance_m"].get<float>(), project.render.lodDistanceM);
    EXPECT_EQ(vec3Of(runtime["camera"]["target"]), project.cameras[0].target);

    // The meshes: the terrain with every vertex and triangle, then the ball's prop.
    ASSERT_EQ(runtime["meshes"].size(), 2u);
    const json& terrain = runtime["meshes"][0];
    EXPECT_EQ(terrain["vertex_count"], windy.scene.mesh->n_vertices());
    EXPECT_EQ(terrain["index_count"], 3 * windy.scene.mesh->n_faces());
    EXPECT_EQ(fs::file_size(dir / terrain["file"].get<std::string>()),
              32 * windy.scene.mesh->n_vertices() + 12 * windy.scene.mesh->n_faces());
    EXPECT_EQ(ball["mesh"], 1);

    // The baked shading, slot for slot as the renderer uploads it.
    const LayerField& layer = windy.scene.layers[0];
    auto shading = readFile(dir / manifest["layers"][0]["shading"]["file"].get<std::string>());
    ASSERT_TRUE(shading.ok());
    ASSERT_EQ(shading->size(), layer.shading.size() * sizeof(BladeShading));
    EXPECT_EQ(std::memcmp(shading->data(), layer.shading.data(), shading->size()), 0);
}

TEST(RuntimeBlock, GltfCarriesTheBehaviourAndTheBakedShadingPerInstance) {
    const Windy windy = buildWindy();
    const fs::path dir = test::scratchDir("runtime_block_gltf");
    exportAs(windy, ExportFormat::Raw, dir / "raw");
    exportAs(windy, ExportFormat::Gltf, dir / "gltf");
    json raw = readJson(dir / "raw/manifest.json")["runtime"];
    const json gltf = readJson(dir / "gltf/grass.gltf");
    const json& extras = gltf["scenes"][0]["extras"]["grass_runtime"];
    // The same block without the mesh files (the terrain is the glTF's own node).
    EXPECT_TRUE(extras["meshes"].empty());
    EXPECT_FALSE(extras["colliders"][0].contains("mesh"));
    raw.erase("meshes");
    raw["colliders"][0].erase("mesh");
    json fromGltf = extras;
    fromGltf.erase("meshes");
    EXPECT_EQ(fromGltf, raw);

    // _AO, _WATER and _BLURRED_NORMAL of every instance are its blade's baked values.
    const LayerField& layer = windy.scene.layers[0];
    std::map<std::tuple<float, float, float>, std::size_t> slotByRoot;
    for (std::size_t slot = 0; slot < layer.patched.blades.size(); ++slot)
        if (layer.patched.blades[slot].h() > 0.0f) {
            const glm::vec3 root = layer.patched.blades[slot].v0();
            slotByRoot[{root.x, root.y, root.z}] = slot;
        }
    const std::string bin = gltf["buffers"][0]["uri"].get<std::string>();
    auto bytes = readFile(dir / "gltf" / bin);
    ASSERT_TRUE(bytes.ok());
    const auto floats = [&](int accessor, int components) {
        const json& a = gltf["accessors"][std::size_t(accessor)];
        const json& view = gltf["bufferViews"][a["bufferView"].get<std::size_t>()];
        const std::size_t offset = view.value("byteOffset", std::size_t(0)) +
                                   a.value("byteOffset", std::size_t(0));
        std::vector<float> out(a["count"].get<std::size_t>() * std::size_t(components));
        std::memcpy(out.data(), bytes->data() + offset, out.size() * sizeof(float));
        return out;
    };
    std::size_t checked = 0;
    for (const json& node : gltf["nodes"]) {
        if (!node.contains("extensions"))
            continue;
        const json& attributes = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
        const auto t = floats(attributes["TRANSLATION"], 3), ao = floats(attributes["_AO"], 1),
                   water = floats(attributes["_WATER"], 1),
                   normal = floats(attributes["_BLURRED_NORMAL"], 3);
        for (std::size_t i = 0; i < ao.size(); ++i) {
            const auto slot = slotByRoot.find({t[3 * i], t[3 * i + 1], t[3 * i + 2]});
            ASSERT_NE(slot, slotByRoot.end());
            const BladeShading& baked = layer.shading[slot->second];
            EXPECT_EQ(ao[i], baked.ao());
            EXPECT_EQ(water[i], baked.water());
            EXPECT_EQ(glm::vec3(normal[3 * i], normal[3 * i + 1], normal[3 * i + 2]),
                      baked.blurredNormal());
            ++checked;
        }
    }
    EXPECT_EQ(checked, layer.liveBlades);
}


// A ground far from its file's origin is moved next to grass's (docs/meshes.md); its export says
// by how much, with the unit and the up axis, so a host can put the field back on the map. A
// point of the export maps back to the file's point it was grown on. Before, only a note at
// load time said it.
TEST(RuntimeBlock, AMovedGroundsOriginTravelsWithTheExport) {
    const fs::path dir = test::scratchDir("runtime_block_far_ground");
    test::GltfAsset tile = test::singleMeshAsset(test::gridPrimitive(40.0f, 40.0f, 4));
    // +Z up in the file: the grid (in its x-z plane) stood up on its edge is a wall; turned to +Z
    // up by the node, it lies flat again, placed at UTM-like coordinates.
    tile.nodes[0].rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    tile.nodes[0].translation = {512345.0f, 5412345.0f, 120.0f};
    test::writeGltf(dir / "tile.gltf", tile);
    ASSERT_TRUE(writeFileAtomic(dir / "project.json", R"({"format": "grass-project", "version": 3, "name": "tile",
        "mesh": {"file": "tile.gltf", "unit": "cm", "up": "+Z"},
        "layers": [{"name": "grass", "density": 4.0}]})").ok());
    auto loaded = loadProject(dir / "project.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    const auto file = loadGltf(dir / "tile.gltf", GltfPlacement::GroundNearOrigin, 0.01);
    ASSERT_TRUE(file.ok());
    ASSERT_NE(file->origin, glm::dvec3(0.0)) << "the test's tile must be far enough to move";
    EXPECT_EQ(scene->groundOrigin, file->origin);

    const Windy moved{std::move(*loaded), std::move(*scene)};
    exportAs(moved, ExportFormat::Raw, dir / "raw");
    const json origin = readJson(dir / "raw/manifest.json")["runtime"]["ground_origin"];
    ASSERT_TRUE(origin.is_object());
    EXPECT_EQ(origin["file"], "tile.gltf");
    EXPECT_EQ(origin["metres_per_unit"].get<float>(), 0.01f);
    EXPECT_EQ(origin["up"], "+Z");
    const glm::dvec3 point{origin["point"][0].get<double>(), origin["point"][1].get<double>(),
                           origin["point"][2].get<double>()};
    EXPECT_EQ(point, file->origin);
    // The formula of docs/runtime.md takes the export's terrain back onto the file's: flat at
    // z = 120, its corners at the node's translation ± 20 file units.
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto vertex : moved.scene.mesh->vertices()) {
        const glm::vec3 p = toGlm(moved.scene.mesh->point(vertex));
        const glm::dvec3 back = point + glm::dvec3(p.x, -p.z, p.y) / 0.01;
        lo = glm::min(lo, back);
        hi = glm::max(hi, back);
    }
    EXPECT_LT(glm::length(lo - glm::dvec3(512325.0, 5412325.0, 120.0)), 0.01) << lo.x << " " << lo.y << " " << lo.z;
    EXPECT_LT(glm::length(hi - glm::dvec3(512365.0, 5412365.0, 120.0)), 0.01) << hi.x << " " << hi.y << " " << hi.z;

    // A ground that stays where its file puts it carries no origin.
    exportAs(buildWindy(), ExportFormat::Raw, dir / "near");
    EXPECT_FALSE(readJson(dir / "near/manifest.json")["runtime"].contains("ground_origin"));
}

}  // namespace
}  // namespace grass::core
