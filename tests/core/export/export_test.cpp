// grass export (core/export/): the glTF re-imports (tinygltf) as one instance per live blade
// with the blade's root, up, width direction, height and width; the raw files read back bit for
// bit; LOD thins as documented; a bad output folder fails cleanly and leaves nothing behind.
#include "export/export.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <tuple>

#include "export/blade_instances.h"
#include "export/gltf_export.h"
#include "export/merged_blades.h"
#include "export/raw_export.h"
#include "export/source_material.h"
#include "maps/map_image.h"
#include "mesh/gltf_loader.h"
#include "support/gltf_writer.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/rng.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

struct Built {
    LoadedProject loaded;
    Scene scene;
};

Built buildProjectAt(const fs::path& path) {
    auto loaded = loadProject(path);
    EXPECT_TRUE(loaded.ok()) << (loaded ? "" : loaded.error().str());
    auto scene = buildScene(*loaded);
    EXPECT_TRUE(scene.ok()) << (scene ? "" : scene.error().str());
    return {std::move(*loaded), std::move(*scene)};
}

// growth_tiny: growth on, so blades lean (v2 off the up axis) and carry wilt.
Built buildProject(const std::string& name) {
    return buildProjectAt(test::sourceDir() / "tests/data/projects" / name);
}

// Blades on a sphere point every way: rotations far from the identity.
Built buildBall(const fs::path& dir) {
    std::ofstream(dir / "project.json") << R"({"format": "grass-project", "version": 1,
        "name": "ball", "mesh": {"procedural": "sphere", "size": 2.0, "resolution": 12},
        "layers": [{"name": "ball grass", "density": 30.0}]})";
    return buildProjectAt(dir / "project.json");
}

std::vector<Blade> liveBlades(const LayerField& layer) {
    std::vector<Blade> live;
    for (const Blade& blade : layer.patched.blades)
        if (isLiveBlade(blade))
            live.push_back(blade);
    return live;
}

// Decoding accepts images without looking at them: the test checks geometry only.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

// The float32 values of a tightly packed float accessor.
std::vector<float> readFloats(const tinygltf::Model& model, int accessorIndex, int components) {
    const tinygltf::Accessor& accessor =
        model.accessors.at(static_cast<std::size_t>(accessorIndex));
    EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& view =
        model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
    const tinygltf::Buffer& buffer = model.buffers.at(static_cast<std::size_t>(view.buffer));
    std::vector<float> values(accessor.count * static_cast<std::size_t>(components));
    EXPECT_LE(view.byteOffset + accessor.byteOffset + values.size() * 4, buffer.data.size());
    std::memcpy(values.data(), buffer.data.data() + view.byteOffset + accessor.byteOffset,
                values.size() * sizeof(float));
    return values;
}

// What a stock EXT_mesh_gpu_instancing loader sees: every instancing node's per-instance TRS and
// _COLOR_0, with the node's mesh (positions and COLOR_0) to draw.
struct StockInstance {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    float stiffness = 0.0f;
    glm::vec3 color{1.0f};  // _COLOR_0
    int mesh = -1;
    // instance matrix × a mesh point
    glm::vec3 place(glm::vec3 p) const { return translation + rotation * (scale * p); }
};

struct Reimported {
    tinygltf::Model model;
    std::vector<StockInstance> instances;
    std::size_t instancingNodes = 0;
};

Reimported reimport(const fs::path& file) {
    Reimported out;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    std::string error, warning;
    EXPECT_TRUE(loader.LoadASCIIFromFile(&out.model, &error, &warning, file.string())) << error;
    for (const tinygltf::Node& node : out.model.nodes) {
        const auto found = node.extensions.find("EXT_mesh_gpu_instancing");
        if (found == node.extensions.end())
            continue;
        ++out.instancingNodes;
        const tinygltf::Value& attributes = found->second.Get("attributes");
        const auto read = [&](const char* name, int components) {
            EXPECT_TRUE(attributes.Has(name)) << name;
            return attributes.Has(name)
                       ? readFloats(out.model, attributes.Get(name).GetNumberAsInt(), components)
                       : std::vector<float>{};
        };
        const std::vector<float> t = read("TRANSLATION", 3), r = read("ROTATION", 4),
                                 s = read("SCALE", 3), k = read("_STIFFNESS", 1),
                                 c = read("_COLOR_0", 3);
        for (std::size_t i = 0; i < k.size(); ++i) {
            StockInstance in;
            in.translation = {t[3 * i], t[3 * i + 1], t[3 * i + 2]};
            in.rotation = glm::quat(r[4 * i + 3], r[4 * i], r[4 * i + 1], r[4 * i + 2]);
            in.scale = {s[3 * i], s[3 * i + 1], s[3 * i + 2]};
            in.stiffness = k[i];
            if (c.size() == k.size() * 3)
                in.color = {c[3 * i], c[3 * i + 1], c[3 * i + 2]};
            in.mesh = node.mesh;
            out.instances.push_back(in);
        }
    }
    return out;
}

// A mesh's first primitive's attribute, as floats.
std::vector<float> meshAttribute(const tinygltf::Model& model, int mesh, const char* name,
                                 int components) {
    const auto& attributes = model.meshes.at(std::size_t(mesh)).primitives.at(0).attributes;
    const auto found = attributes.find(name);
    if (found == attributes.end())
        return {};
    return readFloats(model, found->second, components);
}

// The instance whose root is `root` (roots are unique in these fields).
const StockInstance* instanceAt(const Reimported& gltf, glm::vec3 root) {
    static const Reimported* indexed = nullptr;
    static std::map<std::tuple<float, float, float>, const StockInstance*> byRoot;
    if (indexed != &gltf || byRoot.size() != gltf.instances.size()) {
        byRoot.clear();
        for (const StockInstance& in : gltf.instances)
            byRoot[{in.translation.x, in.translation.y, in.translation.z}] = &in;
        indexed = &gltf;
    }
    const auto found = byRoot.find({root.x, root.y, root.z});
    return found == byRoot.end() ? nullptr : found->second;
}

ExportOptions options(ExportFormat format, int lod, const fs::path& outDir) {
    ExportOptions o;
    o.format = format;
    o.lod = lod;
    o.outDir = outDir;
    return o;
}

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance, const std::string& what) {
    EXPECT_LE(glm::length(a - b), tolerance) << what;
}

void expectReimportMatches(const Built& built, const fs::path& dir, const std::string& file) {
    auto report = exportProject(built.loaded, built.scene, options(ExportFormat::Gltf, 0, dir), {});
    ASSERT_TRUE(report.ok()) << report.error().str();
    const LayerField& layer = built.scene.layers[0];
    const std::vector<Blade> blades = liveBlades(layer);
    ASSERT_GT(blades.size(), 10u);
    ASSERT_EQ(report->layers.size(), 1u);
    EXPECT_EQ(report->layers[0].instances, blades.size());
    EXPECT_EQ(report->layers[0].liveBlades, layer.liveBlades);

    const Reimported gltf = reimport(dir / file);
    ASSERT_EQ(gltf.instances.size(), blades.size());
    for (std::size_t i = 0; i < blades.size(); ++i) {
        const Blade& b = blades[i];
        const std::string at = "blade " + std::to_string(i);
        const StockInstance* found = instanceAt(gltf, b.v0());
        ASSERT_NE(found, nullptr) << at;
        const glm::quat q = found->rotation;
        EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f) << at;
        expectNear(q * glm::vec3(0, 1, 0), glm::normalize(b.up()), 1e-5f, at + " up");
        expectNear(q * glm::vec3(1, 0, 0), widthDirection(glm::normalize(b.up()), b.theta()), 1e-5f,
                   at + " width direction");
        EXPECT_EQ(found->scale, glm::vec3(b.w(), b.h(), b.h())) << at;
        EXPECT_EQ(found->stiffness, b.s()) << at;
    }
    // The terrain comes along with every vertex of the surface.
    ASSERT_FALSE(gltf.model.meshes.empty());
    EXPECT_EQ(gltf.model.meshes[0].name, "terrain");
    const int positions = gltf.model.meshes[0].primitives[0].attributes.at("POSITION");
    EXPECT_EQ(gltf.model.accessors[static_cast<std::size_t>(positions)].count,
              built.scene.mesh->n_vertices());
}

TEST(Export, GltfReimportsEveryLiveBladeAsAnInstance) {
    expectReimportMatches(buildProject("growth_tiny"), test::scratchDir("export_gltf"),
                          "grass.gltf");
    const fs::path ball = test::scratchDir("export_gltf_ball");
    // The layer's name has a space: the file name gets '_' for it.
    expectReimportMatches(buildBall(ball), ball / "out", "ball_grass.gltf");
}

// Issue 25: what a stock loader draws — instance TRS × the node's mesh, coloured by the mesh's
// COLOR_0 times the instance's _COLOR_0 on the white material — is the resting field: the tips
// where the growth model leaned them and the root-to-tip colours. Before, every blade stood
// straight (tips a median 0.83 h away on the meadow) in one colour. The meadow: its painted soil
// and light vary the lean (0–60°) and the wilt blade by blade.
TEST(Export, StockLoadersDrawTheLeanAndTheColours) {
    const Built built = buildProjectAt(test::sourceDir() / "projects/meadow");
    const fs::path dir = test::scratchDir("export_stock");
    auto report = exportProject(built.loaded, built.scene, options(ExportFormat::Gltf, 0, dir), {});
    ASSERT_TRUE(report.ok()) << report.error().str();
    const Reimported gltf = reimport(dir / "grass.gltf");
    const LayerField& layer = built.scene.layers[0];
    std::vector<float> tipErrors, leans, rootErrors;
    float worstTipColour = 0.0f, worstRootColour = 0.0f;
    for (std::size_t slot = 0; slot < layer.patched.blades.size(); ++slot) {
        const Blade& b = layer.patched.blades[slot];
        if (!isLiveBlade(b))
            continue;
        const StockInstance* in = instanceAt(gltf, b.v0());
        ASSERT_NE(in, nullptr);
        const std::vector<float> positions = meshAttribute(gltf.model, in->mesh, "POSITION", 3);
        const std::vector<float> colours = meshAttribute(gltf.model, in->mesh, "COLOR_0", 3);
        ASSERT_EQ(colours.size(), positions.size()) << "the blade mesh has no COLOR_0";
        // Rows run root to tip: the first vertex is at the root, the last one in the top row.
        const std::size_t last = positions.size() - 3;
        const glm::vec3 tip = in->place({0.0f, positions[last + 1], positions[last + 2]});
        tipErrors.push_back(glm::length(tip - b.v2()) / b.h());
        leans.push_back(bladeLeanRad(b));
        const float wilt = layer.wilt[slot];
        const glm::vec3 tipColour = in->color * glm::vec3(colours[last], colours[last + 1], colours[last + 2]);
        const glm::vec3 rootColour = in->color * glm::vec3(colours[0], colours[1], colours[2]);
        const auto worst = [](glm::vec3 d) { return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}); };
        worstTipColour = std::max(worstTipColour, worst(tipColour - glm::mix(layer.tipColor, layer.poorTipColor, wilt)));
        rootErrors.push_back(worst(rootColour - glm::mix(layer.rootColor, layer.poorRootColor, wilt)));
        worstRootColour = std::max(worstRootColour, rootErrors.back());
    }
    ASSERT_GT(tipErrors.size(), 10u);
    std::sort(tipErrors.begin(), tipErrors.end());
    std::sort(leans.begin(), leans.end());
    const float median = tipErrors[tipErrors.size() / 2], worstTip = tipErrors.back();
    std::sort(rootErrors.begin(), rootErrors.end());
    std::printf("tip error / h: median %.4f, worst %.4f; lean %.1f..%.1f deg, median %.1f; colour "
                "error tip %.4f, root median %.4f, worst %.4f\n",
                median, worstTip, leans.front() * 57.2958f, leans.back() * 57.2958f,
                leans[leans.size() / 2] * 57.2958f, worstTipColour, rootErrors[rootErrors.size() / 2],
                worstRootColour);
    EXPECT_GT(leans[leans.size() / 2], 0.2f) << "the test field must lean for the check to mean anything";
    // The issue asks for a median within 10 % of h; bins of 5° bound every tip by 2·sin(1.25°).
    EXPECT_LE(median, 0.1f);
    EXPECT_LE(worstTip, 0.05f);
    // The tip colour is the instance's own; the root follows the root-to-tip ratio of the
    // blade's wilt bin (one mesh per bin of ¼), so it is off by at most an ⅛ step of wilt:
    // measured median 0.014, worst 0.023 of linear RGB on the meadow (0.072 with one mesh at
    // the layer's mean wilt).
    EXPECT_LE(worstTipColour, 1e-5f);
    EXPECT_LE(rootErrors[rootErrors.size() / 2], 0.03f);
    EXPECT_LE(worstRootColour, 0.04f);
    // Culling-friendly: more than one instancing node.
    EXPECT_GT(gltf.instancingNodes, 1u);
}

// --format glb (issue 25): one file, one terrain shared by every layer, each layer's blades
// under its own group, the maps embedded as PNG images named after their layer.
TEST(Export, GlbHoldsEveryLayerOverOneTerrain) {
    const fs::path dir = test::scratchDir("export_glb");
    std::ofstream(dir / "project.json") << R"({"format": "grass-project", "version": 1,
        "name": "two layers", "mesh": {"procedural": "plane", "size": 2.0, "resolution": 4},
        "layers": [{"name": "grass", "density": 40.0, "map_resolution": [16, 16],
                    "density_map": "maps/d.png", "growth": {"enabled": true}},
                   {"name": "flowers", "density": 10.0, "shape": "dandelion"}]})";
    fs::create_directories(dir / "maps");
    MapImage map;
    map.width = map.height = 16;
    map.texels.assign(256, 0.7f);
    ASSERT_TRUE(saveMapImage(map, dir / "maps/d.png", MapSampleFormat::UInt16).ok());
    const Built built = buildProjectAt(dir / "project.json");
    ASSERT_EQ(built.scene.layers.size(), 2u);
    auto report = exportProject(built.loaded, built.scene, options(ExportFormat::Glb, 0, dir / "out"), {});
    ASSERT_TRUE(report.ok()) << report.error().str();
    ASSERT_EQ(report->files.size(), 1u);
    EXPECT_EQ(report->files[0].path.filename(), "two_layers.glb");

    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, (dir / "out/two_layers.glb").string()))
        << error;
    EXPECT_EQ(std::count_if(model.meshes.begin(), model.meshes.end(),
                            [](const tinygltf::Mesh& m) { return m.name == "terrain"; }),
              1);
    std::map<std::string, std::size_t> instancesByLayer;
    for (const tinygltf::Node& node : model.nodes)
        for (const std::string layer : {"grass", "flowers"})
            if (node.name == layer + " blades") {
                EXPECT_TRUE(node.extras.Has("grass_blades") && node.extras.Get("grass_blades").Get<bool>())
                    << "the blade group is marked for importers";
                for (const int child : node.children) {
                    const tinygltf::Node& cell = model.nodes.at(std::size_t(child));
                    const int k = cell.extensions.at("EXT_mesh_gpu_instancing")
                                      .Get("attributes").Get("TRANSLATION").GetNumberAsInt();
                    instancesByLayer[layer] += model.accessors.at(std::size_t(k)).count;
                }
            }
    EXPECT_EQ(instancesByLayer["grass"], built.scene.layers[0].liveBlades);
    EXPECT_EQ(instancesByLayer["flowers"], built.scene.layers[1].liveBlades);
    // Imported as a ground (New from mesh), the export is its terrain: the blade groups are marked.
    std::size_t terrainTriangles = 0;
    for (const tinygltf::Mesh& mesh : model.meshes)
        if (mesh.name == "terrain")
            for (const tinygltf::Primitive& primitive : mesh.primitives)
                terrainTriangles += model.accessors.at(std::size_t(primitive.indices)).count / 3;
    const auto ground = loadGltf(dir / "out/two_layers.glb");
    ASSERT_TRUE(ground.ok()) << ground.error().str();
    EXPECT_EQ(ground->mesh->n_faces(), terrainTriangles);
    ASSERT_EQ(report->layers.size(), 2u);
    EXPECT_EQ(report->layers[1].instances, built.scene.layers[1].liveBlades);
    // The grass layer's density map, embedded (no file next to the .glb).
    ASSERT_EQ(model.images.size(), 1u);
    EXPECT_EQ(model.images[0].name, "grass density");
    EXPECT_EQ(model.images[0].mimeType, "image/png");
    EXPECT_GE(model.images[0].bufferView, 0);
    EXPECT_TRUE(model.images[0].uri.empty());
}

// --format mesh (issue 25): every blade baked into plain triangles, one mesh per cell, for viewers
// without the instancing extension; each blade keeps its lean (its lean bin's unit blade, placed)
// and its own root-to-tip colour. Over the triangle budget it is refused, naming the LOD that fits.
TEST(Export, MergedMeshBakesEveryBladeAndRespectsTheBudget) {
    const Built built = buildProject("growth_tiny");
    const LayerField& layer = built.scene.layers[0];
    const std::vector<MergedBladeMesh> meshes = mergedBlades(layer, 0, 8);
    ASSERT_GT(meshes.size(), 1u) << "one mesh per cell";
    std::size_t triangles = 0, vertices = 0;
    for (const MergedBladeMesh& m : meshes) {
        triangles += m.triangles();
        vertices += m.positions.size() / 3;
        ASSERT_EQ(m.colors.size(), m.positions.size());
        for (const std::uint32_t index : m.indices)
            ASSERT_LT(index, m.positions.size() / 3);
    }
    EXPECT_EQ(triangles, mergedBladeTriangles(layer, 0, 8));
    // Every blade's tip vertex (the top of its unit blade, placed) is in the mesh, where the
    // blade's tip is within the lean bins' bound, in its tip colour.
    const std::vector<BladeInstance> instances = bladeInstances(layer, 0);
    const UnitBladeMesh unit = unitBladeMesh(layer.shape, layer.tipStart, 8, leanBinRad(instances[0].leanBin));
    const std::size_t perBlade = unit.heights.size();
    EXPECT_EQ(vertices, instances.size() * perBlade);
    std::size_t tipsFound = 0;
    for (const MergedBladeMesh& m : meshes)
        for (std::size_t v = perBlade - 1; v < m.positions.size() / 3; v += perBlade) {
            const glm::vec3 tip(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
            const glm::vec3 colour(m.colors[3 * v], m.colors[3 * v + 1], m.colors[3 * v + 2]);
            for (const BladeInstance& b : instances)
                if (glm::length(tip - (b.translation + b.tipOffset)) <= 0.05f * b.scale.y &&
                    glm::length(colour - b.tipColor) < 1e-5f) {
                    ++tipsFound;
                    break;
                }
        }
    EXPECT_EQ(tipsFound, instances.size());

    const fs::path dir = test::scratchDir("export_mesh");
    ExportOptions o = options(ExportFormat::Mesh, 0, dir / "out");
    o.maxMergedTriangles = triangles / 3;  // LOD 2 keeps a quarter of the blades: it fits
    auto refused = exportProject(built.loaded, built.scene, o, {});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().str().find("--lod 2"), std::string::npos) << refused.error().str();
    EXPECT_FALSE(fs::exists(dir / "out")) << "a refused export leaves nothing";
    o.lod = 2;
    auto written = exportProject(built.loaded, built.scene, o, {});
    ASSERT_TRUE(written.ok()) << written.error().str();
    EXPECT_EQ(written->files.at(0).path.filename(), "growth_tiny-merged.glb");
}

// The material of the terrain node of an exported .gltf or .glb; none (and a failure) when the
// file does not read.
std::optional<tinygltf::Material> exportedTerrainMaterial(const fs::path& file) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    std::string error, warning;
    const bool read = file.extension() == ".glb"
                          ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                          : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
    EXPECT_TRUE(read) << file << ": " << error;
    const auto terrain = std::find_if(model.meshes.begin(), model.meshes.end(),
                                      [](const tinygltf::Mesh& m) { return m.name == "terrain"; });
    if (!read || terrain == model.meshes.end() || terrain->primitives.empty() ||
        terrain->primitives[0].material < 0)
        return std::nullopt;
    return model.materials.at(std::size_t(terrain->primitives[0].material));
}

// The artist's own mesh keeps its material in the export (issue 25): the terrain node of a
// project whose surface is a glTF file carries that file's material factors; a broken factor in
// the source is left out rather than copied into an invalid export; drawn in the
// ground colour instead, the export is too.
TEST(Export, TerrainKeepsTheSourceMeshsMaterial) {
    const fs::path dir = test::scratchDir("export_material");
    nlohmann::json quad;
    std::ifstream(test::sourceDir() / "tests/data/gltf/quad.gltf") >> quad;
    quad["materials"] = {{{"name", "mossy stone"},
                          {"pbrMetallicRoughness",
                           {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}, {"roughnessFactor", 0.3},
                            {"metallicFactor", 7.0}}},
                          {"doubleSided", true}}};
    quad["meshes"][0]["primitives"][0]["material"] = 0;
    std::ofstream(dir / "quad.gltf") << quad.dump();
    std::ofstream(dir / "project.json") << R"({"format": "grass-project", "version": 1,
        "name": "stone", "mesh": {"file": "quad.gltf"},
        "layers": [{"name": "grass", "density": 20.0}]})";
    const Built built = buildProjectAt(dir / "project.json");
    for (const ExportFormat format : {ExportFormat::Gltf, ExportFormat::Glb}) {
        auto report = exportProject(built.loaded, built.scene, options(format, 0, dir / "out"), {});
        ASSERT_TRUE(report.ok()) << report.error().str();
        const std::optional<tinygltf::Material> material = exportedTerrainMaterial(
            dir / (format == ExportFormat::Glb ? "out/stone.glb" : "out/grass.gltf"));
        ASSERT_TRUE(material);
        EXPECT_EQ(material->name, "terrain: mossy stone");
        EXPECT_EQ(material->pbrMetallicRoughness.baseColorFactor,
                  (std::vector<double>{0.2, 0.4, 0.6, 1.0}));
        EXPECT_DOUBLE_EQ(material->pbrMetallicRoughness.roughnessFactor, 0.3);
        EXPECT_DOUBLE_EQ(material->pbrMetallicRoughness.metallicFactor, 1.0)
            << "7 is not a factor: the default";
        EXPECT_TRUE(material->doubleSided);
    }
    // Drawn in the ground colour instead ("file_material": false): exported in it too.
    Built ground = buildProjectAt(dir / "project.json");
    ground.loaded.project.mesh.fileMaterial = false;
    ground.loaded.project.render.groundColor = {0.5f, 0.25f, 0.125f};
    auto report = exportProject(ground.loaded, ground.scene,
                                options(ExportFormat::Glb, 0, dir / "ground"), {});
    ASSERT_TRUE(report.ok()) << report.error().str();
    const std::optional<tinygltf::Material> material =
        exportedTerrainMaterial(dir / "ground/stone.glb");
    ASSERT_TRUE(material);
    EXPECT_EQ(material->name, "terrain");
    EXPECT_EQ(material->pbrMetallicRoughness.baseColorFactor,
              (std::vector<double>{0.5, 0.25, 0.125, 1.0}));
}

// The source material's PNG and JPEG textures travel embedded (issue 25 item 2): from a file next
// to the .gltf and from a .glb's own buffer; a texture on another UV set or in another format
// stays behind with a note.
TEST(Export, TerrainCarriesTheSourceMeshsTextures) {
    const fs::path dir = test::scratchDir("export_textures");
    MapImage stone;
    stone.width = stone.height = 4;
    stone.texels.assign(16, 0.5f);
    ASSERT_TRUE(saveMapImage(stone, dir / "stone.png", MapSampleFormat::UInt8).ok());
    const std::string png = *readFile(dir / "stone.png");
    for (const bool glb : {false, true}) {
        test::GltfDocument doc = test::buildGltf(test::singleMeshAsset(test::gridPrimitive(2, 2, 2)));
        nlohmann::json image = {{"uri", "stone.png"}};
        if (glb) {
            while (doc.bin.size() % 4 != 0)
                doc.bin.push_back(0);
            doc.json["bufferViews"].push_back(
                {{"buffer", 0}, {"byteOffset", doc.bin.size()}, {"byteLength", png.size()}});
            doc.bin.insert(doc.bin.end(), png.begin(), png.end());
            doc.json["buffers"][0]["byteLength"] = doc.bin.size();
            image = {{"bufferView", doc.json["bufferViews"].size() - 1}, {"mimeType", "image/png"}};
        }
        std::ofstream(dir / "fake.gif") << "GIF89a";
        doc.json["images"] = {image, {{"uri", "fake.gif"}}};
        doc.json["samplers"] = {{{"magFilter", 9728}, {"wrapS", 33071}, {"wrapT", 7}}};
        doc.json["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}};
        doc.json["materials"] = {{{"name", "stone"},
                                  {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                                  {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
                                  {"occlusionTexture", {{"index", 0}, {"texCoord", 1}}},
                                  {"emissiveTexture", {{"index", 1}}}}};
        doc.json["meshes"][0]["primitives"][0]["material"] = 0;
        const std::string source = glb ? "stone.glb" : "stone.gltf";
        test::writeGltf(dir / source, doc, glb ? test::BufferStorage::Glb : test::BufferStorage::ExternalFile);

        const SourceMaterial material = sourceMeshMaterial(dir / source);
        ASSERT_EQ(material.textures.size(), 1u) << source;
        EXPECT_EQ(material.textures[0].bytes, png);
        ASSERT_EQ(material.notes.size(), 2u) << "TEXCOORD_1 and the GIF are left behind";
        EXPECT_NE(material.notes[0].find("TEXCOORD_1"), std::string::npos) << material.notes[0];
        EXPECT_NE(material.notes[1].find("neither PNG nor JPEG"), std::string::npos) << material.notes[1];

        std::ofstream(dir / "project.json") << R"({"format": "grass-project", "version": 1,
            "name": "stone", "mesh": {"file": ")" + source + R"("},
            "layers": [{"name": "grass", "density": 20.0}]})";
        const Built built = buildProjectAt(dir / "project.json");
        auto report = exportProject(built.loaded, built.scene, options(ExportFormat::Glb, 0, dir / "out"), {});
        ASSERT_TRUE(report.ok()) << report.error().str();
        tinygltf::Model model;
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(skipImage, nullptr);
        std::string error, warning;
        ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, (dir / "out/stone.glb").string())) << error;
        const tinygltf::Material& out = model.materials.at(0);
        EXPECT_EQ(out.name, "terrain: stone");
        const int base = out.pbrMetallicRoughness.baseColorTexture.index;
        ASSERT_GE(base, 0);
        EXPECT_EQ(out.normalTexture.index, base);
        EXPECT_DOUBLE_EQ(out.normalTexture.scale, 0.5);
        EXPECT_EQ(out.occlusionTexture.index, -1);
        EXPECT_EQ(out.emissiveTexture.index, -1);
        const tinygltf::Texture& texture = model.textures.at(std::size_t(base));
        const tinygltf::Sampler& sampler = model.samplers.at(std::size_t(texture.sampler));
        EXPECT_EQ(sampler.magFilter, 9728);
        EXPECT_EQ(sampler.wrapS, 33071);
        EXPECT_EQ(sampler.wrapT, 10497) << "7 is no wrap mode: the default";
        const tinygltf::Image& embedded = model.images.at(std::size_t(texture.source));
        EXPECT_EQ(embedded.mimeType, "image/png");
        const tinygltf::BufferView& view = model.bufferViews.at(std::size_t(embedded.bufferView));
        const auto& bytes = model.buffers.at(std::size_t(view.buffer)).data;
        EXPECT_EQ(std::string(bytes.begin() + std::ptrdiff_t(view.byteOffset),
                              bytes.begin() + std::ptrdiff_t(view.byteOffset + view.byteLength)),
                  png);
        // The terrain keeps the source's UVs, which the texture reads, and has tangents for its
        // normal map.
        const auto& attributes = model.meshes.at(0).primitives.at(0).attributes;
        EXPECT_TRUE(attributes.count("TEXCOORD_0"));
        EXPECT_TRUE(attributes.count("TANGENT"));
    }
}

TEST(Export, LodKeepsEveryPowerOfTwoBladeWidened) {
    const Built built = buildProject("growth_tiny");
    const std::vector<Blade> blades = liveBlades(built.scene.layers[0]);
    for (int lod = 0; lod <= 3; ++lod) {
        const std::size_t stride = std::size_t{1} << lod;
        const std::vector<BladeInstance> instances = bladeInstances(built.scene.layers[0], lod);
        ASSERT_EQ(instances.size(), (blades.size() + stride - 1) / stride) << "lod " << lod;
        for (std::size_t k = 0; k < instances.size(); ++k) {
            const Blade& b = blades[k * stride];
            EXPECT_EQ(instances[k].translation, b.v0()) << "lod " << lod << ", instance " << k;
            EXPECT_FLOAT_EQ(instances[k].scale.x, b.w() * static_cast<float>(stride));
            EXPECT_EQ(instances[k].scale.y, b.h());
        }
    }
}

TEST(Export, RotationTakesYToUpAndXToWidthDirection) {
    for (std::uint64_t seed = 0; seed < 500; ++seed) {
        Rng rng(seed);
        const glm::vec3 up = glm::normalize(glm::vec3(
            rng.uniform(-1.0f, 1.0f), rng.uniform(0.05f, 1.0f), rng.uniform(-1.0f, 1.0f)));
        const float theta = rng.uniform(-6.3f, 6.3f);
        const glm::quat q = bladeRotation(up, theta);
        EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f) << "seed " << seed;
        expectNear(q * glm::vec3(0, 1, 0), up, 1e-5f, "up, seed " + std::to_string(seed));
        expectNear(q * glm::vec3(1, 0, 0), widthDirection(up, theta), 1e-5f,
                   "width, seed " + std::to_string(seed));
    }
}

TEST(Export, RawRoundTripsBitExactly) {
    const Built built = buildProject("growth_tiny");
    const fs::path dir = test::scratchDir("export_raw");
    auto report = exportProject(built.loaded, built.scene, options(ExportFormat::Raw, 0, dir), {});
    ASSERT_TRUE(report.ok()) << report.error().str();
    const LayerField& layer = built.scene.layers[0];
    auto manifestText = readFile(dir / "manifest.json");
    ASSERT_TRUE(manifestText.ok());
    const auto manifest = nlohmann::json::parse(*manifestText);
    const auto named = [&](const char* part) {
        return dir / manifest["layers"][0][part]["file"].get<std::string>();
    };
    auto blades = readRawBlades(named("blades"));
    ASSERT_TRUE(blades.ok()) << blades.error().str();
    ASSERT_EQ(blades->size(), layer.patched.blades.size());
    EXPECT_EQ(std::memcmp(blades->data(), layer.patched.blades.data(), blades->size() * 64), 0);
    auto patches = readRawPatches(named("patches"));
    ASSERT_TRUE(patches.ok()) << patches.error().str();
    ASSERT_EQ(patches->size(), layer.patched.patches.size());
    for (std::size_t p = 0; p < patches->size(); ++p) {
        EXPECT_EQ((*patches)[p].firstBlade, layer.patched.patches[p].firstBlade);
        EXPECT_EQ((*patches)[p].bladeCount, layer.patched.patches[p].bladeCount);
        EXPECT_EQ((*patches)[p].bounds, layer.patched.patches[p].bounds);
    }
    EXPECT_EQ(manifest["layout"]["blade_record"]["stride"], 64);
    EXPECT_EQ(manifest["layers"][0]["blades"]["count"], layer.patched.blades.size());
    EXPECT_EQ(manifest["layers"][0]["patch_size"], layer.patched.patchSize);
    EXPECT_EQ(manifest["layers"][0]["live_blades"], layer.liveBlades);
}

TEST(Export, RawRefusesLod) {
    const Built built = buildProject("tiny");
    const fs::path dir = test::scratchDir("export_raw_lod") / "out";
    auto report = exportProject(built.loaded, built.scene, options(ExportFormat::Raw, 1, dir), {});
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().path, "lod");
    EXPECT_FALSE(fs::exists(dir));
}

TEST(Export, FileInPlaceOfFolderFailsAndWritesNothing) {
    const Built built = buildProject("tiny");
    const fs::path dir = test::scratchDir("export_file_as_dir");
    { std::ofstream(dir / "out") << "not a folder"; }
    auto report =
        exportProject(built.loaded, built.scene, options(ExportFormat::Gltf, 0, dir / "out"), {});
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().path, (dir / "out").string());
    EXPECT_NE(report.error().message.find("not a folder"), std::string::npos);
    EXPECT_EQ(*readFile(dir / "out"), "not a folder");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(Export, FolderInPlaceOfAFileLeavesNoHalfExport) {
    const Built built = buildProject("tiny");
    const fs::path dir = test::scratchDir("export_blocked_file");
    // The .gltf is staged after the .bin: its failure must take the staged .bin back.
    fs::create_directories(dir / "grass.gltf");
    auto report = exportProject(built.loaded, built.scene, options(ExportFormat::Gltf, 0, dir), {});
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().path, (dir / "grass.gltf").string());
    std::vector<fs::path> left;
    for (const auto& entry : fs::directory_iterator(dir))
        left.push_back(entry.path().filename());
    ASSERT_EQ(left.size(), 1u) << left.back();
    EXPECT_EQ(left[0], "grass.gltf");
}

// An export is atomic as a set (content_names.h): the .gltf names its buffer by content, so a
// re-export of a changed field writes a new buffer beside the old one and only then replaces the
// .gltf; the old buffer goes once nothing names it. An unchanged field keeps its names.
TEST(Export, ReExportNamesFilesByContentAndRemovesWhatIsNoLongerNamed) {
    const Built built = buildProject("tiny");
    const fs::path dir = test::scratchDir("export_content_names");
    const auto exportedNames = [&](int lod) {
        auto report =
            exportProject(built.loaded, built.scene, options(ExportFormat::Gltf, lod, dir), {});
        EXPECT_TRUE(report.ok()) << report.error().str();
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir))
            names.insert(entry.path().filename().string());
        return names;
    };
    const std::set<std::string> first = exportedNames(0);
    EXPECT_EQ(first.size(), 2u);
    EXPECT_EQ(exportedNames(0), first);
    const std::set<std::string> coarser = exportedNames(2);
    EXPECT_EQ(coarser.size(), 2u);
    EXPECT_TRUE(coarser.count("grass.gltf"));
    EXPECT_NE(coarser, first) << "LOD 2 holds fewer instances: another buffer, another name";
    EXPECT_EQ(reimport(dir / "grass.gltf").instances.size(), bladeInstances(built.scene.layers[0], 2).size());
}

TEST(Export, ProgressRunsFromZeroToOne) {
    const Built built = buildProject("tiny");
    const fs::path dir = test::scratchDir("export_progress");
    std::vector<float> fractions;
    auto report =
        exportProject(built.loaded, built.scene, options(ExportFormat::Gltf, 1, dir),
                      [&](float fraction, std::string_view) { fractions.push_back(fraction); });
    ASSERT_TRUE(report.ok()) << report.error().str();
    ASSERT_GE(fractions.size(), 2u);
    EXPECT_EQ(fractions.front(), 0.0f);
    EXPECT_EQ(fractions.back(), 1.0f);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(report->files.size(), 2u);  // grass-<hash>.bin, grass.gltf: tiny has no maps
    EXPECT_GT(report->totalBytes(), 0u);
}

// A stop (the editor's Stop while it exports) ends the export at its next stage, before anything
// is renamed into place: a re-export stopped once it reports a stage leaves the folder holding
// the previous export byte for byte, in every format, and a stop requested before the start
// creates no folder. Without the stop the same re-export replaces the files.
TEST(Export, AStoppedExportLeavesTheFolderAsItWas) {
    const Built built = buildProject("tiny");
    const auto contents = [](const fs::path& dir) {
        std::map<std::string, std::string> files;
        for (const auto& entry : fs::directory_iterator(dir))
            files[entry.path().filename().string()] = *readFile(entry.path());
        return files;
    };
    for (const ExportFormat format :
         {ExportFormat::Gltf, ExportFormat::Raw, ExportFormat::Glb, ExportFormat::Mesh}) {
        const std::string name(exportFormatName(format));
        const fs::path dir = test::scratchDir("export_stopped_" + name);
        ASSERT_TRUE(exportProject(built.loaded, built.scene, options(format, 0, dir), {}));
        const auto before = contents(dir);
        int stops = 0;
        for (const std::string& stage : {std::string("layer"), std::string("terrain"),
                                         std::string("writing"), std::string("blades")}) {
            ExportOptions again = options(format, format == ExportFormat::Raw ? 0 : 2, dir);
            std::stop_source source;
            again.stop = source.get_token();
            bool asked = false;
            auto report =
                exportProject(built.loaded, built.scene, again, [&](float, std::string_view now) {
                    if (now.find(stage) != std::string_view::npos) {
                        asked = true;
                        source.request_stop();
                    }
                });
            if (!asked)
                continue;  // this format reports no such stage
            ASSERT_FALSE(report) << name << ", stopped at " << stage;
            EXPECT_EQ(report.error().path, dir.string());
            EXPECT_NE(report.error().message.find("stopped"), std::string::npos);
            EXPECT_EQ(contents(dir), before) << name << ", stopped at " << stage;
            ++stops;
        }
        EXPECT_GE(stops, 2) << name << ": stopped at two stages at least";
        if (format != ExportFormat::Raw) {
            ASSERT_TRUE(exportProject(built.loaded, built.scene, options(format, 2, dir), {}));
            EXPECT_NE(contents(dir), before) << name << ": unstopped, LOD 2 replaces the files";
        }
    }
    const fs::path never = test::scratchDir("export_stopped_early") / "out";
    ExportOptions early = options(ExportFormat::Gltf, 0, never);
    std::stop_source source;
    source.request_stop();
    early.stop = source.get_token();
    EXPECT_FALSE(exportProject(built.loaded, built.scene, early, {}));
    EXPECT_FALSE(fs::exists(never));
}

TEST(Export, UnitBladeIsOneTallTwoWideWithoutDegenerateTriangles) {
    for (const BladeShape shape : {BladeShape::Quad, BladeShape::Triangle, BladeShape::Quadratic,
                                   BladeShape::TriangleTip, BladeShape::Dandelion})
        for (int segments : {1, 4, 8}) {
            const UnitBladeMesh mesh = unitBladeMesh(shape, 0.5f, segments);
            const std::string at =
                std::string(bladeShapeName(shape)) + " x" + std::to_string(segments);
            float top = 0.0f, left = 0.0f;
            for (std::size_t v = 0; v < mesh.positions.size(); v += 3) {
                top = std::max(top, mesh.positions[v + 1]);
                left = std::min(left, mesh.positions[v]);
            }
            EXPECT_FLOAT_EQ(top, 1.0f) << at;
            EXPECT_GE(left, -1.0f) << at;
            ASSERT_EQ(mesh.indices.size() % 3, 0u) << at;
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
                const auto p = [&](std::size_t k) {
                    const std::size_t i = mesh.indices[t + k] * 3u;
                    return glm::vec3(mesh.positions[i], mesh.positions[i + 1],
                                     mesh.positions[i + 2]);
                };
                const glm::vec3 n = glm::cross(p(1) - p(0), p(2) - p(0));
                // Counter-clockwise seen from −Z, the normal's side.
                EXPECT_LT(n.z, 0.0f) << at << ", triangle " << t / 3;
            }
        }
}

// The pre-bent blades (issue 25): every lean bin's mesh is the renderer's resting curve — its
// tip at the bin's angle from up towards −Z, its length 1 as the validation keeps it — with unit
// normals that face the front (−Z-ish) and triangles that still wind towards them.
TEST(Export, LeanedUnitBladesBendTowardsTheFront) {
    for (int bin = 0; bin < LEAN_BIN_COUNT; ++bin) {
        const float lean = leanBinRad(bin);
        const UnitBladeMesh mesh = unitBladeMesh(BladeShape::Quad, 0.5f, 8, lean);
        const std::string at = "bin " + std::to_string(bin);
        ASSERT_EQ(mesh.heights.size() * 3, mesh.positions.size()) << at;
        const std::size_t last = mesh.positions.size() - 3;
        const glm::vec3 tip(0.0f, mesh.positions[last + 1], mesh.positions[last + 2]);
        EXPECT_NEAR(std::atan2(-tip.z, tip.y), lean, 1e-4f) << at;
        EXPECT_FLOAT_EQ(mesh.heights.front(), 0.0f);
        EXPECT_FLOAT_EQ(mesh.heights.back(), 1.0f);
        for (std::size_t v = 0; v < mesh.normals.size(); v += 3) {
            const glm::vec3 n(mesh.normals[v], mesh.normals[v + 1], mesh.normals[v + 2]);
            ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << at << ", vertex " << v / 3;
            EXPECT_LT(n.z, 0.0f) << at << ", vertex " << v / 3;
        }
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            const auto p = [&](std::size_t k) {
                const std::size_t i = mesh.indices[t + k] * 3u;
                return glm::vec3(mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]);
            };
            const std::size_t n0 = mesh.indices[t] * 3u;
            const glm::vec3 normal(mesh.normals[n0], mesh.normals[n0 + 1], mesh.normals[n0 + 2]);
            EXPECT_GT(glm::dot(glm::cross(p(1) - p(0), p(2) - p(0)), normal), 0.0f)
                << at << ", triangle " << t / 3;
        }
    }
    EXPECT_EQ(leanBinOf(0.0f), 0);
    EXPECT_EQ(leanBinOf(0.05f), 1);  // 2.9° rounds to 5°
    EXPECT_EQ(leanBinOf(2.0f), LEAN_BIN_COUNT - 1);
}

}  // namespace
}  // namespace grass::core
