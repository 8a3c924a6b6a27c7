#include "export/gltf_export.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "export/blade_instances.h"
#include "export/content_names.h"
#include "export/gltf_builder.h"
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

// The terrain: every vertex of the surface mesh with its normal and UV0, and its triangles.
json terrainMesh(GltfBuilder& builder, const SurfaceMesh& mesh, int material) {
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
    const json attributes = {{"POSITION", builder.addFloats(positions, 3, GltfTarget::ArrayBuffer)},
                             {"NORMAL", builder.addFloats(normals, 3, GltfTarget::ArrayBuffer)},
                             {"TEXCOORD_0", builder.addFloats(uvs, 2, GltfTarget::ArrayBuffer)}};
    return {{"name", "terrain"},
            {"primitives", {meshPrimitive(attributes, builder.addIndices(indices), material)}}};
}

// The per-instance attributes of EXT_mesh_gpu_instancing, one accessor each.
json instanceAttributes(GltfBuilder& builder, const std::vector<BladeInstance>& instances) {
    std::vector<float> translation, rotation, scale, stiffness, tipColor, rootColor, tipOffset;
    for (const BladeInstance& b : instances) {
        push(translation, {b.translation.x, b.translation.y, b.translation.z});
        // glTF quaternions are (x, y, z, w).
        push(rotation, {b.rotation.x, b.rotation.y, b.rotation.z, b.rotation.w});
        push(scale, {b.scale.x, b.scale.y, b.scale.z});
        stiffness.push_back(b.stiffness);
        push(tipColor, {b.tipColor.r, b.tipColor.g, b.tipColor.b});
        push(rootColor, {b.rootColor.r, b.rootColor.g, b.rootColor.b});
        push(tipOffset, {b.tipOffset.x, b.tipOffset.y, b.tipOffset.z});
    }
    const auto add = [&](const std::vector<float>& values, int components) {
        return builder.addFloats(values, components, GltfTarget::None);
    };
    return {{"TRANSLATION", add(translation, 3)},
            {"ROTATION", add(rotation, 4)},
            {"SCALE", add(scale, 3)},
            {"_STIFFNESS", add(stiffness, 1)},
            {"_COLOR", add(tipColor, 3)},
            {"_ROOT_COLOR", add(rootColor, 3)},
            {"_TIP_OFFSET", add(tipOffset, 3)}};
}

}  // namespace

UnitBladeMesh unitBladeMesh(BladeShape shape, float tipStart, int segments) {
    GRASS_ASSERT(segments >= 1);
    UnitBladeMesh mesh;
    const auto level = static_cast<float>(segments);
    std::uint32_t previousLeft = 0, previousRight = 0;
    for (int i = 0; i <= segments; ++i) {
        const float v = static_cast<float>(i) / level;
        const float y = 2.0f * v - v * v;
        const float left = 2.0f * shapeT(shape, 0.0f, v, tipStart, level) - 1.0f;
        const float right = 2.0f * shapeT(shape, 1.0f, v, tipStart, level) - 1.0f;
        const auto first = static_cast<std::uint32_t>(mesh.positions.size() / 3);
        // The renderer's front normal is up × t1 = +Y × +X = −Z (shaders/include/
        // blade_geometry.glsl); triangles wind counter-clockwise seen from there.
        const bool pointed = i > 0 && std::abs(right - left) < MIN_ROW_WIDTH;
        push(mesh.positions, {pointed ? 0.5f * (left + right) : left, y, 0.0f});
        push(mesh.normals, {0.0f, 0.0f, -1.0f});
        if (!pointed) {
            push(mesh.positions, {right, y, 0.0f});
            push(mesh.normals, {0.0f, 0.0f, -1.0f});
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

GltfLayerDocument buildLayerGltf(const GltfLayerInput& input) {
    GRASS_ASSERT(input.scene && input.layer < input.scene->layers.size());
    const Scene& scene = *input.scene;
    const LayerField& layer = scene.layers[input.layer];
    GltfBuilder builder;
    json& doc = builder.document();
    doc["asset"] = {{"version", "2.0"}, {"generator", "grass export"}};
    doc["materials"] = json::array();
    doc["meshes"] = json::array();
    doc["nodes"] = json::array();

    json terrainMaterial = {{"name", "terrain"},
                            {"pbrMetallicRoughness",
                             {{"baseColorFactor", colorFactor(input.groundColor)},
                              {"metallicFactor", 0.0},
                              {"roughnessFactor", 1.0}}}};
    if (!input.maps.empty()) {
        doc["images"] = json::array();
        doc["textures"] = json::array();
        for (const GltfMapImage& map : input.maps) {
            doc["images"].push_back({{"name", map.map}, {"uri", map.uri}});
            doc["textures"].push_back({{"name", map.map}, {"source", doc["images"].size() - 1}});
        }
    }
    doc["materials"].push_back(terrainMaterial);
    if (scene.mesh.n_faces() > 0) {
        doc["meshes"].push_back(terrainMesh(builder, scene.mesh, 0));
        doc["nodes"].push_back({{"name", "terrain"}, {"mesh", doc["meshes"].size() - 1}});
    }

    const std::vector<BladeInstance> instances = bladeInstances(layer, input.lod);
    if (!instances.empty()) {
        const UnitBladeMesh blade = unitBladeMesh(layer.shape, layer.tipStart, input.segments);
        doc["materials"].push_back({{"name", layer.name + " blade"},
                                    {"doubleSided", true},
                                    {"pbrMetallicRoughness",
                                     {{"baseColorFactor", colorFactor(layer.tipColor)},
                                      {"metallicFactor", 0.0},
                                      {"roughnessFactor", 0.7}}}});
        const json attributes = {
            {"POSITION", builder.addFloats(blade.positions, 3, GltfTarget::ArrayBuffer)},
            {"NORMAL", builder.addFloats(blade.normals, 3, GltfTarget::ArrayBuffer)}};
        const int indices = builder.addIndices(blade.indices);
        doc["meshes"].push_back({{"name", layer.name + " unit blade"},
                                 {"primitives",
                                  {meshPrimitive(attributes, indices,
                                                 static_cast<int>(doc["materials"].size()) - 1)}}});
        doc["nodes"].push_back({{"name", layer.name + " blades"},
                                {"mesh", doc["meshes"].size() - 1},
                                {"extensions",
                                 {{"EXT_mesh_gpu_instancing",
                                   {{"attributes", instanceAttributes(builder, instances)}}}}}});
        doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    }
    json sceneNodes = json::array();
    for (std::size_t n = 0; n < doc["nodes"].size(); ++n)
        sceneNodes.push_back(n);
    json sceneJson = {{"name", layer.name}};
    if (!sceneNodes.empty())
        sceneJson["nodes"] = sceneNodes;
    doc["scenes"] = json::array({sceneJson});
    doc["scene"] = 0;

    GltfLayerDocument out;
    out.instances = instances.size();
    out.binary = builder.finishBinary();
    out.binUri = contentAddressedName(input.binStem, contentHash(out.binary), ".bin");
    out.json = builder.finishJson(out.binUri);
    return out;
}

}  // namespace grass::core
