#include "support/gltf_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "util/assert.h"

namespace grass::test {
namespace {

using Json = nlohmann::json;

constexpr int FLOAT = 5126;
constexpr int UNSIGNED_INT = 5125;

int componentType(ComponentEncoding encoding) {
    switch (encoding) {
        case ComponentEncoding::Float:
            return FLOAT;
        case ComponentEncoding::Byte:
            return 5120;
        case ComponentEncoding::UnsignedByte:
            return 5121;
        case ComponentEncoding::Short:
            return 5122;
        case ComponentEncoding::UnsignedShort:
            return 5123;
    }
    return FLOAT;
}

std::size_t componentBytes(ComponentEncoding encoding) {
    switch (encoding) {
        case ComponentEncoding::Byte:
        case ComponentEncoding::UnsignedByte:
            return 1;
        case ComponentEncoding::Short:
        case ComponentEncoding::UnsignedShort:
            return 2;
        case ComponentEncoding::Float:
            return 4;
    }
    return 4;
}

template <class T>
void appendRaw(std::vector<std::uint8_t>& out, T value) {
    std::uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // little-endian hosts only, as glTF is
    out.insert(out.end(), bytes, bytes + sizeof(T));
}

// Normalized: the value times the type's maximum (spec §3.11); otherwise rounded as is.
template <class T>
T quantize(float value, bool normalized) {
    const double scaled = normalized ? double(value) * std::numeric_limits<T>::max() : value;
    const double clamped = std::clamp(scaled, double(std::numeric_limits<T>::lowest()),
                                      double(std::numeric_limits<T>::max()));
    return static_cast<T>(std::lround(clamped));
}

void appendComponent(std::vector<std::uint8_t>& out, float value, AttributeEncoding encoding) {
    switch (encoding.type) {
        case ComponentEncoding::Float:
            return appendRaw(out, value);
        case ComponentEncoding::Byte:
            return appendRaw(out, quantize<std::int8_t>(value, encoding.normalized));
        case ComponentEncoding::UnsignedByte:
            return appendRaw(out, quantize<std::uint8_t>(value, encoding.normalized));
        case ComponentEncoding::Short:
            return appendRaw(out, quantize<std::int16_t>(value, encoding.normalized));
        case ComponentEncoding::UnsignedShort:
            return appendRaw(out, quantize<std::uint16_t>(value, encoding.normalized));
    }
}

void padTo4(std::vector<std::uint8_t>& out) {
    while (out.size() % 4 != 0)
        out.push_back(0);
}

// One vertex attribute as flat floats, ready to encode.
struct Attribute {
    std::string semantic;
    std::string type;  // "VEC2", "VEC3"
    int components = 0;
    std::vector<float> values;
    AttributeEncoding encoding;
    std::size_t count() const { return values.size() / static_cast<std::size_t>(components); }
    std::size_t elementBytes() const {
        return componentBytes(encoding.type) * static_cast<std::size_t>(components);
    }
};

template <int N>
std::vector<float> flatten(const std::vector<glm::vec<N, float>>& vectors) {
    std::vector<float> out;
    for (const auto& v : vectors)
        for (int i = 0; i < N; ++i)
            out.push_back(v[i]);
    return out;
}

class Builder {
public:
    explicit Builder(GltfDocument& document) : mDoc(document) {}

    int addView(const std::vector<std::uint8_t>& bytes, std::size_t stride = 0) {
        padTo4(mDoc.bin);
        Json view = {{"buffer", 0}, {"byteOffset", mDoc.bin.size()}, {"byteLength", bytes.size()}};
        if (stride != 0)
            view["byteStride"] = stride;
        mDoc.bin.insert(mDoc.bin.end(), bytes.begin(), bytes.end());
        mDoc.json["bufferViews"].push_back(view);
        return static_cast<int>(mDoc.json["bufferViews"].size()) - 1;
    }

    int addAccessor(Json accessor) {
        mDoc.json["accessors"].push_back(std::move(accessor));
        return static_cast<int>(mDoc.json["accessors"].size()) - 1;
    }

    Json primitive(const GltfPrimitive& p) {
        std::vector<Attribute> attributes;
        attributes.push_back({"POSITION", "VEC3", 3, flatten(p.positions), p.positionEncoding});
        if (!p.normals.empty())
            attributes.push_back({"NORMAL", "VEC3", 3, flatten(p.normals), p.normalEncoding});
        if (!p.uvs.empty())
            attributes.push_back({"TEXCOORD_0", "VEC2", 2, flatten(p.uvs), p.uvEncoding});
        Json out = {{"mode", static_cast<int>(p.mode)}, {"attributes", Json::object()}};
        if (p.material >= 0)
            out["material"] = p.material;
        const bool viewlessPosition = !p.sparsePositions.empty() && p.sparseWithoutBufferView;
        std::vector<Json> accessors;
        for (const auto& a : attributes) {
            Json accessor = {{"componentType", componentType(a.encoding.type)},
                             {"count", a.count()},
                             {"type", a.type}};
            if (a.encoding.normalized)
                accessor["normalized"] = true;
            if (a.semantic == "POSITION")
                addBounds(accessor, finalPositions(p));
            accessors.push_back(accessor);
        }
        if (p.interleaved) {
            std::size_t stride = 0;
            std::vector<std::size_t> offsets;
            for (const auto& a : attributes) {
                offsets.push_back(stride);
                stride += (a.elementBytes() + 3) / 4 * 4;
            }
            std::vector<std::uint8_t> bytes;
            for (std::size_t v = 0; v < p.positions.size(); ++v) {
                for (const auto& a : attributes) {
                    for (int c = 0; c < a.components; ++c)
                        appendComponent(bytes,
                                        a.values[v * static_cast<std::size_t>(a.components) +
                                                 static_cast<std::size_t>(c)],
                                        a.encoding);
                    padTo4(bytes);
                }
            }
            const int view = addView(bytes, stride);
            for (std::size_t i = 0; i < attributes.size(); ++i) {
                accessors[i]["bufferView"] = view;
                accessors[i]["byteOffset"] = offsets[i];
            }
        } else {
            for (std::size_t i = 0; i < attributes.size(); ++i) {
                if (i == 0 && viewlessPosition)
                    continue;
                std::vector<std::uint8_t> bytes;
                // Vertex attribute elements must start on 4-byte boundaries (spec §3.6.2.4):
                // pad small quantized elements and say so with a byteStride.
                const Attribute& a = attributes[i];
                const std::size_t stride = (a.elementBytes() + 3) / 4 * 4;
                for (std::size_t v = 0; v < a.count(); ++v) {
                    for (int c = 0; c < a.components; ++c)
                        appendComponent(bytes,
                                        a.values[v * static_cast<std::size_t>(a.components) +
                                                 static_cast<std::size_t>(c)],
                                        a.encoding);
                    padTo4(bytes);
                }
                accessors[i]["bufferView"] =
                    addView(bytes, stride == a.elementBytes() ? 0 : stride);
            }
        }
        if (viewlessPosition)
            accessors[0].erase("bufferView");
        if (!p.sparsePositions.empty())
            accessors[0]["sparse"] = sparse(p);
        for (std::size_t i = 0; i < attributes.size(); ++i)
            out["attributes"][attributes[i].semantic] = addAccessor(accessors[i]);
        if (!p.indices.empty())
            out["indices"] = indices(p);
        return out;
    }

    // EXT_mesh_gpu_instancing: TRANSLATION, ROTATION and SCALE accessors of FLOAT.
    Json instanceAttributes(const std::vector<GltfInstance>& instances) {
        std::vector<std::uint8_t> t, r, s;
        for (const auto& instance : instances) {
            for (int c = 0; c < 3; ++c) {
                appendRaw(t, instance.translation[c]);
                appendRaw(s, instance.scale[c]);
            }
            for (const float value : {instance.rotation.x, instance.rotation.y, instance.rotation.z,
                                      instance.rotation.w})
                appendRaw(r, value);
        }
        const auto accessor = [&](const std::vector<std::uint8_t>& bytes, const char* type) {
            return addAccessor({{"bufferView", addView(bytes)},
                                {"componentType", FLOAT},
                                {"count", instances.size()},
                                {"type", type}});
        };
        return {{"TRANSLATION", accessor(t, "VEC3")},
                {"ROTATION", accessor(r, "VEC4")},
                {"SCALE", accessor(s, "VEC3")}};
    }

private:
    // What a reader gets: the base (zeros without a bufferView) with sparse overrides.
    static std::vector<glm::vec3> finalPositions(const GltfPrimitive& p) {
        std::vector<glm::vec3> out = p.positions;
        if (!p.sparsePositions.empty() && p.sparseWithoutBufferView)
            std::fill(out.begin(), out.end(), glm::vec3(0.0f));
        for (const auto& [index, value] : p.sparsePositions)
            if (index < out.size())
                out[index] = value;
        return out;
    }

    static void addBounds(Json& accessor, const std::vector<glm::vec3>& positions) {
        if (positions.empty())
            return;
        glm::vec3 lo = positions[0], hi = positions[0];
        for (const auto& v : positions) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        accessor["min"] = {lo.x, lo.y, lo.z};
        accessor["max"] = {hi.x, hi.y, hi.z};
    }

    Json sparse(const GltfPrimitive& p) {
        std::vector<std::uint8_t> indexBytes, valueBytes;
        for (const auto& [index, value] : p.sparsePositions) {
            appendRaw(indexBytes, index);
            for (int c = 0; c < 3; ++c)
                appendComponent(valueBytes, value[c], p.positionEncoding);
        }
        return {{"count", p.sparsePositions.size()},
                {"indices", {{"bufferView", addView(indexBytes)}, {"componentType", UNSIGNED_INT}}},
                {"values", {{"bufferView", addView(valueBytes)}}}};
    }

    int indices(const GltfPrimitive& p) {
        std::vector<std::uint8_t> bytes;
        int type = UNSIGNED_INT;
        for (const std::uint32_t index : p.indices) {
            switch (p.indexType) {
                case IndexType::UnsignedByte:
                    appendRaw(bytes, static_cast<std::uint8_t>(index));
                    type = 5121;
                    break;
                case IndexType::UnsignedShort:
                    appendRaw(bytes, static_cast<std::uint16_t>(index));
                    type = 5123;
                    break;
                case IndexType::UnsignedInt:
                    appendRaw(bytes, index);
                    break;
            }
        }
        return addAccessor({{"bufferView", addView(bytes)},
                            {"componentType", type},
                            {"count", p.indices.size()},
                            {"type", "SCALAR"}});
    }

    GltfDocument& mDoc;
};

Json nodeJson(const GltfNode& node) {
    Json out = Json::object();
    if (!node.name.empty())
        out["name"] = node.name;
    if (node.mesh >= 0)
        out["mesh"] = node.mesh;
    if (!node.children.empty())
        out["children"] = node.children;
    if (node.matrix) {
        Json matrix = Json::array();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                matrix.push_back((*node.matrix)[c][r]);
        out["matrix"] = matrix;
    } else {
        const auto& t = node.translation;
        const auto& q = node.rotation;
        const auto& s = node.scale;
        out["translation"] = {t.x, t.y, t.z};
        out["rotation"] = {q.x, q.y, q.z, q.w};  // glTF order: x, y, z, w
        out["scale"] = {s.x, s.y, s.z};
    }
    return out;
}

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static constexpr char ALPHABET[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t group = 0;
        for (std::size_t k = 0; k < 3; ++k)
            group = group << 8 | (k < n ? bytes[i + k] : 0u);
        for (std::size_t k = 0; k < 4; ++k)
            out.push_back(k <= n ? ALPHABET[(group >> (18 - 6 * k)) & 63u] : '=');
    }
    return out;
}

void writeBytes(const std::filesystem::path& file, const void* data, std::size_t size) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    GRASS_ASSERT(out);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    GRASS_ASSERT(out);
}

void appendU32(std::string& out, std::size_t value) {
    for (int shift = 0; shift < 32; shift += 8)
        out.push_back(static_cast<char>((value >> shift) & 0xFFu));
}

std::string glb(std::string json, std::vector<std::uint8_t> bin) {
    while (json.size() % 4 != 0)
        json.push_back(' ');
    padTo4(bin);
    std::string out = "glTF";
    appendU32(out, 2);
    appendU32(out, 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
    appendU32(out, json.size());
    appendU32(out, 0x4E4F534A);  // "JSON"
    out += json;
    if (!bin.empty()) {
        appendU32(out, bin.size());
        appendU32(out, 0x004E4942);  // "BIN\0"
        out.append(reinterpret_cast<const char*>(bin.data()), bin.size());
    }
    return out;
}

}  // namespace

GltfDocument buildGltf(const GltfAsset& asset) {
    GltfDocument doc;
    doc.json["asset"] = {{"version", "2.0"}, {"generator", "grass tests"}};
    Builder builder(doc);
    std::vector<std::string> extensionsUsed = asset.extensionsUsed;
    for (const auto& mesh : asset.meshes) {
        Json primitives = Json::array();
        for (const auto& primitive : mesh.primitives)
            primitives.push_back(builder.primitive(primitive));
        Json meshJson = {{"primitives", primitives}};
        if (!mesh.name.empty())
            meshJson["name"] = mesh.name;
        doc.json["meshes"].push_back(meshJson);
    }
    for (const auto& material : asset.materials)
        doc.json["materials"].push_back(Json::object(
            {{"name", material.name},
             {"pbrMetallicRoughness",
              {{"baseColorFactor", {material.baseColor.r, material.baseColor.g,
                                    material.baseColor.b, material.baseColor.a}}}}}));
    std::vector<bool> isChild(asset.nodes.size(), false);
    for (const auto& node : asset.nodes) {
        Json json = nodeJson(node);
        if (!node.instances.empty()) {
            json["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] =
                builder.instanceAttributes(node.instances);
            if (std::find(extensionsUsed.begin(), extensionsUsed.end(),
                          "EXT_mesh_gpu_instancing") == extensionsUsed.end())
                extensionsUsed.push_back("EXT_mesh_gpu_instancing");
        }
        doc.json["nodes"].push_back(json);
        for (const int child : node.children)
            if (child >= 0 && static_cast<std::size_t>(child) < isChild.size())
                isChild[static_cast<std::size_t>(child)] = true;
    }
    if (asset.withScene) {
        std::vector<int> roots = asset.sceneNodes;
        if (roots.empty())
            for (std::size_t i = 0; i < asset.nodes.size(); ++i)
                if (!isChild[i])
                    roots.push_back(static_cast<int>(i));
        doc.json["scenes"] = Json::array({{{"nodes", roots}}});
        doc.json["scene"] = 0;
    }
    if (!doc.bin.empty())
        doc.json["buffers"] = Json::array({{{"byteLength", doc.bin.size()}}});
    if (!extensionsUsed.empty())
        doc.json["extensionsUsed"] = extensionsUsed;
    if (!asset.extensionsRequired.empty())
        doc.json["extensionsRequired"] = asset.extensionsRequired;
    return doc;
}

void writeGltf(const std::filesystem::path& file, const GltfDocument& document,
               BufferStorage storage, const std::string& binFileName) {
    Json json = document.json;
    const bool hasBuffer = json.contains("buffers") && !json["buffers"].empty();
    const bool uriSet = hasBuffer && json["buffers"][0].contains("uri");
    switch (storage) {
        case BufferStorage::ExternalFile: {
            const std::string name =
                binFileName.empty() ? file.stem().string() + ".bin" : binFileName;
            if (!document.bin.empty())
                writeBytes(file.parent_path() / name, document.bin.data(), document.bin.size());
            if (hasBuffer && !uriSet)
                json["buffers"][0]["uri"] = percentEncodeUri(name);
            break;
        }
        case BufferStorage::DataUri:
            if (hasBuffer && !uriSet)
                json["buffers"][0]["uri"] =
                    "data:application/octet-stream;base64," + base64(document.bin);
            break;
        case BufferStorage::Glb: {
            const std::string bytes = glb(json.dump(), document.bin);
            writeBytes(file, bytes.data(), bytes.size());
            return;
        }
    }
    const std::string text = json.dump(2);
    writeBytes(file, text.data(), text.size());
}

void writeGltf(const std::filesystem::path& file, const GltfAsset& asset, BufferStorage storage,
               const std::string& binFileName) {
    writeGltf(file, buildGltf(asset), storage, binFileName);
}

std::string percentEncodeUri(const std::string& path) {
    static constexpr char HEX[] = "0123456789ABCDEF";
    std::string out;
    for (const char c : path) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
            out.push_back(c);
        } else {
            out.push_back('%');
            out.push_back(HEX[u >> 4]);
            out.push_back(HEX[u & 15u]);
        }
    }
    return out;
}

GltfAsset singleMeshAsset(GltfPrimitive primitive, const std::string& name) {
    GltfAsset asset;
    asset.meshes.push_back({name, {std::move(primitive)}});
    GltfNode node;
    node.name = name;
    node.mesh = 0;
    asset.nodes.push_back(node);
    return asset;
}

GltfPrimitive gridPrimitive(float sizeX, float sizeZ, int cells) {
    GRASS_ASSERT(cells > 0);
    GltfPrimitive p;
    const auto n = static_cast<std::uint32_t>(cells);
    for (std::uint32_t j = 0; j <= n; ++j) {
        for (std::uint32_t i = 0; i <= n; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(n);
            const float v = static_cast<float>(j) / static_cast<float>(n);
            p.positions.push_back({(u - 0.5f) * sizeX, 0.0f, (v - 0.5f) * sizeZ});
            p.normals.push_back({0.0f, 1.0f, 0.0f});
            p.uvs.push_back({u, v});
        }
    }
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, b = a + 1, d = a + n + 1, c = d + 1;
            // x grows with i and z with j: (a, d, c) turns counter-clockwise seen from +Y.
            p.indices.insert(p.indices.end(), {a, d, c, a, c, b});
        }
    }
    return p;
}

GltfPrimitive boxPrimitive(glm::vec3 min, glm::vec3 max) {
    GltfPrimitive p;
    for (int axis = 0; axis < 3; ++axis) {
        for (const float sign : {-1.0f, 1.0f}) {
            glm::vec3 normal(0.0f);
            normal[axis] = sign;
            // (uAxis, vAxis, axis) is right-handed for +, swapped for -: u × v = normal.
            int uAxis = (axis + 1) % 3, vAxis = (axis + 2) % 3;
            if (sign < 0.0f)
                std::swap(uAxis, vAxis);
            const auto first = static_cast<std::uint32_t>(p.positions.size());
            for (const glm::vec2 corner :
                 {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
                glm::vec3 position;
                position[axis] = sign > 0.0f ? max[axis] : min[axis];
                position[uAxis] = corner.x > 0.0f ? max[uAxis] : min[uAxis];
                position[vAxis] = corner.y > 0.0f ? max[vAxis] : min[vAxis];
                p.positions.push_back(position);
                p.normals.push_back(normal);
                p.uvs.push_back(corner);
            }
            p.indices.insert(p.indices.end(),
                             {first, first + 1, first + 2, first, first + 2, first + 3});
        }
    }
    return p;
}

}  // namespace grass::test
