#include "export/gltf_export.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "export/blade_instances.h"
#include "export/vertex_tangents.h"
#include "export/content_names.h"
#include "export/gltf_builder.h"
#include "export/merged_blades.h"
#include "mesh/gltf_blade_nodes.h"
#include "physics/physics.h"
#include "util/assert.h"

namespace grass::core {

namespace {

using nlohmann::json;

// How deep the dandelion's notches cut (shaders/include/shapes.glsl, DANDELION_NOTCH).
constexpr float DANDELION_NOTCH = 0.6f;
// Below this the two edges of a row meet: the row becomes one tip vertex, so no triangle of
// the blade is degenerate (glTF validators flag those).
constexpr float MIN_ROW_WIDTH = 1e-6f;

// t(u, v) of shaders/include/shapes.glsl: where between the edges a point of the unit quad lies.
float shapeT(BladeShape shape, float u, float v, float tau, float level) {
    switch (shape) {
        case BladeShape::Quad:
            return u;
        case BladeShape::Quadratic:
            return u - u * v * v;
        case BladeShape::TriangleTip:
            return 0.5f + (u - 0.5f) * (1.0f - std::max(v - tau, 0.0f) / (1.0f - tau));
        case BladeShape::Dandelion: {
            const float pi = std::numbers::pi_v<float>;
            const float envelope =
                std::clamp(0.25f * (1.0f - v) + 0.85f * std::sin(pi * v), 0.0f, 1.0f);
            const float notch = 0.5f - 0.5f * std::cos(pi * std::max(level, 1.0f) * v);
            return 0.5f + (u - 0.5f) * envelope * (1.0f - DANDELION_NOTCH * notch);
        }
        case BladeShape::Triangle:
            break;
    }
    return u + 0.5f * v - u * v;
}

void push(std::vector<float>& out, std::initializer_list<float> values) {
    out.insert(out.end(), values);
}

json meshPrimitive(const json& attributes, int indices, int material) {
    return {{"attributes", attributes}, {"indices", indices}, {"material", material}};
}

json colorFactor(glm::vec3 color) {
    return json::array({color.r, color.g, color.b, 1.0f});
}

// The terrain: every vertex of the surface mesh with its normal and UV0, and its triangles;
// `withTangents` (a normal-mapped material) adds TANGENT (vertex_tangents.h).
json terrainMesh(GltfBuilder& builder, const SurfaceMesh& mesh, int material, bool withTangents) {
    std::vector<float> positions, normals, uvs;
    positions.reserve(mesh.n_vertices() * 3);
    for (const auto vertex : mesh.vertices()) {
        const auto& p = mesh.point(vertex);
        const auto& n = mesh.normal(vertex);
        const auto& t = mesh.texcoord2D(vertex);
        push(positions, {p[0], p[1], p[2]});
        push(normals, {n[0], n[1], n[2]});
        push(uvs, {t[0], t[1]});
    }
    std::vector<std::uint32_t> indices;
    for (const auto& triangle : triangleIndices(mesh))
        indices.insert(indices.end(), triangle.begin(), triangle.end());
    json attributes = {{"POSITION", builder.addFloats(positions, 3, GltfTarget::ArrayBuffer)},
                       {"NORMAL", builder.addFloats(normals, 3, GltfTarget::ArrayBuffer)},
                       {"TEXCOORD_0", builder.addFloats(uvs, 2, GltfTarget::ArrayBuffer)}};
    if (withTangents) {
        const auto vec3s = [](const std::vector<float>& v) {
            std::vector<glm::vec3> out(v.size() / 3);
            for (std::size_t i = 0; i < out.size(); ++i)
                out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
            return out;
        };
        std::vector<glm::vec2> uv2(uvs.size() / 2);
        for (std::size_t i = 0; i < uv2.size(); ++i)
            uv2[i] = {uvs[2 * i], uvs[2 * i + 1]};
        std::vector<float> tangents;
        for (const glm::vec4& t : vertexTangents(vec3s(positions), vec3s(normals), uv2, triangleIndices(mesh)))
            push(tangents, {t.x, t.y, t.z, t.w});
        attributes["TANGENT"] = builder.addFloats(tangents, 4, GltfTarget::ArrayBuffer);
    }
    return {{"name", "terrain"},
            {"primitives", {meshPrimitive(attributes, builder.addIndices(indices), material)}}};
}

// The per-instance attributes of EXT_mesh_gpu_instancing, one accessor each, for the instances
// `which` of `instances`.
json instanceAttributes(GltfBuilder& builder, const std::vector<BladeInstance>& instances,
                        const std::vector<std::uint32_t>& which) {
    std::vector<float> translation, rotation, scale, stiffness, tipColor, rootColor, tipOffset,
        blurredNormal, ao, water;
    for (const std::uint32_t i : which) {
        const BladeInstance& b = instances[i];
        push(translation, {b.translation.x, b.translation.y, b.translation.z});
        // glTF quaternions are (x, y, z, w).
        push(rotation, {b.rotation.x, b.rotation.y, b.rotation.z, b.rotation.w});
        push(scale, {b.scale.x, b.scale.y, b.scale.z});
        stiffness.push_back(b.stiffness);
        push(tipColor, {b.tipColor.r, b.tipColor.g, b.tipColor.b});
        push(rootColor, {b.rootColor.r, b.rootColor.g, b.rootColor.b});
        push(tipOffset, {b.tipOffset.x, b.tipOffset.y, b.tipOffset.z});
        push(blurredNormal, {b.blurredNormal.x, b.blurredNormal.y, b.blurredNormal.z});
        ao.push_back(b.ao);
        water.push_back(b.water);
    }
    const auto add = [&](const std::vector<float>& values, int components) {
        return builder.addFloats(values, components, GltfTarget::None);
    };
    const int tip = add(tipColor, 3);
    // _COLOR_0 is the convention stock loaders read per-instance colour from (three.js'
    // GLTFLoader, for one); _COLOR, the same accessor, stays for runtimes that read it.
    return {{"TRANSLATION", add(translation, 3)},
            {"ROTATION", add(rotation, 4)},
            {"SCALE", add(scale, 3)},
            {"_STIFFNESS", add(stiffness, 1)},
            {"_COLOR", tip},
            {"_COLOR_0", tip},
            {"_ROOT_COLOR", add(rootColor, 3)},
            {"_TIP_OFFSET", add(tipOffset, 3)},
            {"_BLURRED_NORMAL", add(blurredNormal, 3)},
            {"_AO", add(ao, 1)},
            {"_WATER", add(water, 1)}};
}

// The root-to-tip shading of the blade meshes' COLOR_0, which loaders multiply with the
// instance colour (_COLOR_0, the tip colour): the root's share of the tip colour per channel at
// `wilt` (a wilt bin's value: each bin has its own mesh).
glm::vec3 rootShareAt(const LayerField& layer, float wilt) {
    const glm::vec3 root = glm::mix(layer.rootColor, layer.poorRootColor, wilt);
    const glm::vec3 tip = glm::mix(layer.tipColor, layer.poorTipColor, wilt);
    glm::vec3 share(1.0f);
    for (int c = 0; c < 3; ++c)
        if (tip[c] > 0.0f)
            share[c] = std::clamp(root[c] / tip[c], 0.0f, 1.0f);
    return share;
}

}  // namespace

UnitBladeMesh unitBladeMesh(BladeShape shape, float tipStart, int segments, float leanRad) {
    GRASS_ASSERT(segments >= 1);
    // The resting blade of height 1 in the instance frame (x = t1, y = up), leaned by leanRad
    // towards its front −Z and validated as the growth model does (layer_growth.cpp): the
    // same curve the renderer bends, v0 at the origin.
    Blade rest = makeRestBlade(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 1.0f, 1.0f,
                               widthAngle(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)));
    if (leanRad > 0.0f) {
        rest.v2W = glm::vec4(0.0f, std::cos(leanRad), -std::sin(leanRad), 1.0f);
        validateBlade(rest);
    }
    const glm::vec3 v1 = rest.v1(), v2 = rest.v2();
    UnitBladeMesh mesh;
    const auto level = static_cast<float>(segments);
    std::uint32_t previousLeft = 0, previousRight = 0;
    for (int i = 0; i <= segments; ++i) {
        const float v = static_cast<float>(i) / level;
        // Quadratic Bézier from v0 = 0 (for a straight blade, y = 2v − v²).
        const glm::vec3 c = 2.0f * (1.0f - v) * v * v1 + v * v * v2;
        glm::vec3 tangent = 2.0f * (1.0f - 2.0f * v) * v1 + 2.0f * v * v2;
        // At a straight blade's tip (v1 = v2) the derivative vanishes: the chord has its direction.
        if (glm::dot(tangent, tangent) < 1e-12f)
            tangent = v2;
        // The renderer's front normal is tangent × t1 (+Y × +X = −Z when straight, shaders/
        // include/blade_geometry.glsl); triangles wind counter-clockwise seen from there.
        const glm::vec3 n = glm::normalize(glm::cross(tangent, glm::vec3(1.0f, 0.0f, 0.0f)));
        const float left = 2.0f * shapeT(shape, 0.0f, v, tipStart, level) - 1.0f;
        const float right = 2.0f * shapeT(shape, 1.0f, v, tipStart, level) - 1.0f;
        const auto first = static_cast<std::uint32_t>(mesh.positions.size() / 3);
        const bool pointed = i > 0 && std::abs(right - left) < MIN_ROW_WIDTH;
        push(mesh.positions, {pointed ? 0.5f * (left + right) : left, c.y, c.z});
        push(mesh.normals, {n.x, n.y, n.z});
        mesh.heights.push_back(v);
        if (!pointed) {
            push(mesh.positions, {right, c.y, c.z});
            push(mesh.normals, {n.x, n.y, n.z});
            mesh.heights.push_back(v);
        }
        if (i > 0) {
            mesh.indices.insert(mesh.indices.end(), {previousLeft, first, previousRight});
            if (!pointed)
                mesh.indices.insert(mesh.indices.end(), {previousRight, first, first + 1});
        }
        previousLeft = first;
        previousRight = pointed ? first : first + 1;
        if (pointed)
            break;
    }
    return mesh;
}

namespace {

// A document under construction: the builder, and the top-level nodes of its one scene.
struct DocumentParts {
    GltfBuilder builder;
    std::vector<int> topNodes;

    DocumentParts() {
        json& doc = builder.document();
        doc["asset"] = {{"version", "2.0"}, {"generator", "grass export"}};
        doc["materials"] = json::array();
        doc["meshes"] = json::array();
        doc["nodes"] = json::array();
    }
    json& doc() { return builder.document(); }
    int addNode(json node) {
        doc()["nodes"].push_back(std::move(node));
        return static_cast<int>(doc()["nodes"].size()) - 1;
    }
    int addMaterial(json material) {
        doc()["materials"].push_back(std::move(material));
        return static_cast<int>(doc()["materials"].size()) - 1;
    }
    int addMesh(json mesh) {
        doc()["meshes"].push_back(std::move(mesh));
        return static_cast<int>(doc()["meshes"].size()) - 1;
    }
    // The node grouping a layer's blades, marked so that an import of the export as a ground
    // leaves them out (mesh/gltf_blade_nodes.h).
    int addBladeGroup(const std::string& layerName, json children) {
        return addNode({{"name", layerName + " blades"},
                        {"children", std::move(children)},
                        {"extras", {{std::string(gltf::BLADE_GROUP_EXTRAS_KEY), true}}}});
    }
    void finishScene(const std::string& name, const json& runtime) {
        json sceneJson = {{"name", name}};
        if (!runtime.is_null())
            sceneJson["extras"] = {{"grass_runtime", runtime}};
        if (!topNodes.empty())
            sceneJson["nodes"] = topNodes;
        doc()["scenes"] = json::array({sceneJson});
        doc()["scene"] = 0;
    }
};

// The source material's textures embedded in the buffer (PNG or JPEG as the source held them),
// its slots' indices moved to the document's textures.
json withEmbeddedTextures(DocumentParts& parts, const SourceMaterial& source) {
    json material = source.material;
    if (source.textures.empty())
        return material;
    json& doc = parts.doc();
    for (const char* array : {"images", "textures"})
        if (!doc.contains(array))
            doc[array] = json::array();
    const std::size_t first = doc["textures"].size();
    for (std::size_t i = 0; i < source.textures.size(); ++i) {
        const SourceTexture& texture = source.textures[i];
        const std::string name = "terrain texture " + std::to_string(i);
        doc["images"].push_back({{"name", name},
                                 {"bufferView", parts.builder.addBytes(texture.bytes)},
                                 {"mimeType", texture.mimeType}});
        json entry = {{"name", name}, {"source", doc["images"].size() - 1}};
        if (texture.sampler.is_object()) {
            if (!doc.contains("samplers"))
                doc["samplers"] = json::array();
            doc["samplers"].push_back(texture.sampler);
            entry["sampler"] = doc["samplers"].size() - 1;
        }
        doc["textures"].push_back(entry);
    }
    const auto move = [&](json& slot) {
        if (slot.is_object() && slot.contains("index"))
            slot["index"] = first + slot["index"].get<std::size_t>();
    };
    if (material.contains("pbrMetallicRoughness"))
        for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
            if (material["pbrMetallicRoughness"].contains(key))
                move(material["pbrMetallicRoughness"][key]);
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
        if (material.contains(key))
            move(material[key]);
    return material;
}

// The terrain node, with the project's ground colour or the source mesh's material
// (source_material.h) when it has one.
void addTerrain(DocumentParts& parts, const SurfaceMesh& mesh, glm::vec3 groundColor,
                const SourceMaterial& sourceMaterial) {
    const int material =
        sourceMaterial.material.is_object()
            ? parts.addMaterial(withEmbeddedTextures(parts, sourceMaterial))
            : parts.addMaterial({{"name", "terrain"},
                                 {"pbrMetallicRoughness",
                                  {{"baseColorFactor", colorFactor(groundColor)},
                                   {"metallicFactor", 0.0},
                                   {"roughnessFactor", 1.0}}}});
    if (mesh.n_faces() == 0)
        return;
    const bool normalMapped = sourceMaterial.material.is_object() &&
                              sourceMaterial.material.contains("normalTexture");
    const int meshIndex = parts.addMesh(terrainMesh(parts.builder, mesh, material, normalMapped));
    parts.topNodes.push_back(parts.addNode({{"name", "terrain"}, {"mesh", meshIndex}}));
}

// The maps as images and textures named `prefix` + the map: by file name, or embedded.
void addMaps(DocumentParts& parts, const std::vector<GltfMapImage>& maps, const std::string& prefix) {
    if (maps.empty())
        return;
    json& doc = parts.doc();
    if (!doc.contains("images")) {
        doc["images"] = json::array();
        doc["textures"] = json::array();
    }
    for (const GltfMapImage& map : maps) {
        json image = {{"name", prefix + map.map}};
        if (map.png.empty())
            image["uri"] = map.uri;
        else
            image.update({{"bufferView", parts.builder.addBytes(map.png)}, {"mimeType", "image/png"}});
        doc["images"].push_back(image);
        doc["textures"].push_back({{"name", prefix + map.map}, {"source", doc["images"].size() - 1}});
    }
}

// The blades' material: double-sided and white, the colour coming from the vertices (and, when
// instanced, times the instance's _COLOR_0).
int addBladeMaterial(DocumentParts& parts, const LayerField& layer) {
    return parts.addMaterial({{"name", layer.name + " blade"},
                              {"doubleSided", true},
                              {"pbrMetallicRoughness",
                               {{"baseColorFactor", colorFactor(glm::vec3(1.0f))},
                                {"metallicFactor", 0.0},
                                {"roughnessFactor", 0.7}}}});
}

// The layer's blades (header comment): a group node "<layer> blades" with one instancing child
// per cell, lean bin and wilt bin. Returns the instances written.
std::size_t addLayerBlades(DocumentParts& parts, const LayerField& layer, int lod, int segments) {
    const std::vector<BladeInstance> instances = bladeInstances(layer, lod);
    if (instances.empty())
        return 0;
    GltfBuilder& builder = parts.builder;
    const int material = addBladeMaterial(parts, layer);
    // One pre-bent unit blade per lean bin and wilt bin in use (blade_instances.h).
    std::map<std::pair<int, int>, int> meshOfBin;
    for (const BladeInstance& b : instances)
        meshOfBin.emplace(std::pair{b.leanBin, b.wiltBin}, -1);
    for (auto& [bins, meshIndex] : meshOfBin) {
        const auto [bin, wiltBin] = bins;
        const UnitBladeMesh blade = unitBladeMesh(layer.shape, layer.tipStart, segments, leanBinRad(bin));
        const glm::vec3 share = rootShareAt(layer, wiltBinValue(wiltBin));
        std::vector<float> colors;
        for (const float v : blade.heights) {
            const glm::vec3 c = glm::mix(share, glm::vec3(1.0f), v);
            push(colors, {c.r, c.g, c.b});
        }
        const json attributes = {
            {"POSITION", builder.addFloats(blade.positions, 3, GltfTarget::ArrayBuffer)},
            {"NORMAL", builder.addFloats(blade.normals, 3, GltfTarget::ArrayBuffer)},
            {"COLOR_0", builder.addFloats(colors, 3, GltfTarget::ArrayBuffer)}};
        const int indices = builder.addIndices(blade.indices);
        const int degrees =
            static_cast<int>(std::lround(leanBinRad(bin) * 180.0f / std::numbers::pi_v<float>));
        meshIndex = parts.addMesh(
            {{"name", layer.name + " unit blade, lean " + std::to_string(degrees) + " deg, wilt " +
                          std::to_string(wiltBin) + "/" + std::to_string(WILT_BIN_COUNT - 1)},
             {"primitives", {meshPrimitive(attributes, indices, material)}}});
    }
    json children = json::array();
    for (const InstanceGroup& group : groupInstances(instances))
        children.push_back(parts.addNode(
            {{"name", layer.name + " blades cell " + std::to_string(group.cell) + " lean " +
                          std::to_string(group.bin) + " wilt " + std::to_string(group.wiltBin)},
             {"mesh", meshOfBin.at({group.bin, group.wiltBin})},
             {"extensions",
              {{"EXT_mesh_gpu_instancing",
                {{"attributes", instanceAttributes(builder, instances, group.members)}}}}}}));
    parts.topNodes.push_back(parts.addBladeGroup(layer.name, std::move(children)));
    parts.doc()["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    return instances.size();
}

// The layer's blades baked into plain meshes (merged_blades.h): a group node "<layer> blades"
// with one mesh node per cell, coloured by vertex. Returns the blades written.
std::size_t addLayerMergedBlades(DocumentParts& parts, const LayerField& layer, int lod,
                                 int segments) {
    const std::vector<MergedBladeMesh> meshes = mergedBlades(layer, lod, segments);
    if (meshes.empty())
        return 0;
    GltfBuilder& builder = parts.builder;
    const int material = addBladeMaterial(parts, layer);
    json children = json::array();
    std::size_t blades = 0;
    for (const MergedBladeMesh& cell : meshes) {
        blades += cell.blades;
        const json attributes = {
            {"POSITION", builder.addFloats(cell.positions, 3, GltfTarget::ArrayBuffer)},
            {"NORMAL", builder.addFloats(cell.normals, 3, GltfTarget::ArrayBuffer)},
            {"COLOR_0", builder.addFloats(cell.colors, 3, GltfTarget::ArrayBuffer)}};
        const int indices = builder.addIndices(cell.indices);
        const std::string name = layer.name + " blades cell " + std::to_string(cell.cell);
        const int mesh = parts.addMesh(
            {{"name", name}, {"primitives", {meshPrimitive(attributes, indices, material)}}});
        children.push_back(parts.addNode({{"name", name}, {"mesh", mesh}}));
    }
    parts.topNodes.push_back(parts.addBladeGroup(layer.name, std::move(children)));
    return blades;
}

}  // namespace

GltfLayerDocument buildLayerGltf(const GltfLayerInput& input) {
    GRASS_ASSERT(input.scene && input.layer < input.scene->layers.size());
    const Scene& scene = *input.scene;
    const LayerField& layer = scene.layers[input.layer];
    DocumentParts parts;
    addMaps(parts, input.maps, "");
    addTerrain(parts, scene.mesh, input.groundColor, input.terrainMaterial);
    GltfLayerDocument out;
    out.instances = addLayerBlades(parts, layer, input.lod, input.segments);
    parts.finishScene(layer.name, input.runtime);
    out.binary = parts.builder.finishBinary();
    out.binUri = contentAddressedName(input.binStem, contentHash(out.binary), ".bin");
    out.json = parts.builder.finishJson(out.binUri);
    return out;
}

GltfSceneDocument buildSceneGlb(const GltfSceneInput& input) {
    GRASS_ASSERT(input.scene && input.layerMaps.size() == input.scene->layers.size());
    const Scene& scene = *input.scene;
    DocumentParts parts;
    addTerrain(parts, scene.mesh, input.groundColor, input.terrainMaterial);
    GltfSceneDocument out;
    for (std::size_t i = 0; i < scene.layers.size(); ++i) {
        // Map names carry the layer's: every layer's maps live in the one file.
        addMaps(parts, input.layerMaps[i], scene.layers[i].name + " ");
        out.instances.push_back(
            input.merged ? addLayerMergedBlades(parts, scene.layers[i], input.lod, input.segments)
                         : addLayerBlades(parts, scene.layers[i], input.lod, input.segments));
    }
    parts.finishScene(input.name, input.runtime);
    out.glb = parts.builder.finishGlb();
    return out;
}

}  // namespace grass::core
