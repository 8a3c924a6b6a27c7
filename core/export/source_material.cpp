#include "export/source_material.h"

#include <cstdint>
#include <cstring>

#include "util/atomic_file.h"

namespace grass::core {

namespace {

using nlohmann::json;

constexpr std::uint32_t GLB_MAGIC = 0x46546C67u;  // "glTF"
constexpr std::uint32_t CHUNK_JSON = 0x4E4F534Au;

std::uint32_t u32At(const std::string& bytes, std::size_t offset) {
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

bool unitNumber(const json& value) {
    return value.is_number() && value.get<double>() >= 0.0 && value.get<double>() <= 1.0;
}

bool unitNumbers(const json& value, std::size_t count) {
    if (!value.is_array() || value.size() != count)
        return false;
    for (const json& v : value)
        if (!unitNumber(v))
            return false;
    return true;
}

// The document's JSON: a .glb's first chunk, or the whole .gltf.
json documentOf(const std::string& bytes) {
    if (bytes.size() >= 20 && u32At(bytes, 0) == GLB_MAGIC) {
        const std::uint32_t length = u32At(bytes, 12);
        if (u32At(bytes, 16) != CHUNK_JSON || std::size_t{length} > bytes.size() - 20)
            return nullptr;
        return json::parse(bytes.begin() + 20, bytes.begin() + 20 + length, nullptr, false);
    }
    return json::parse(bytes, nullptr, false);
}

}  // namespace

json sourceMeshMaterial(const std::filesystem::path& file) {
    auto bytes = readFile(file);
    if (!bytes)
        return nullptr;
    const json doc = documentOf(*bytes);
    if (!doc.is_object() || !doc.contains("meshes") || !doc["meshes"].is_array() ||
        !doc.contains("materials") || !doc["materials"].is_array())
        return nullptr;
    for (const json& mesh : doc["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
            continue;
        for (const json& primitive : mesh["primitives"]) {
            // Triangles (mode 4, the default) with a material.
            if (!primitive.is_object() || primitive.value("mode", 4) != 4 ||
                !primitive.contains("material") || !primitive["material"].is_number_unsigned())
                continue;
            const std::size_t index = primitive["material"].get<std::size_t>();
            if (index >= doc["materials"].size() || !doc["materials"][index].is_object())
                continue;
            const json& source = doc["materials"][index];
            json material = {{"name", "terrain: " + source.value("name", std::string("material ") +
                                                                           std::to_string(index))}};
            // Only values the spec allows travel: a broken factor in the source would make the
            // export invalid.
            json pbr = json::object();
            if (source.contains("pbrMetallicRoughness") && source["pbrMetallicRoughness"].is_object()) {
                const json& in = source["pbrMetallicRoughness"];
                if (in.contains("baseColorFactor") && unitNumbers(in["baseColorFactor"], 4))
                    pbr["baseColorFactor"] = in["baseColorFactor"];
                for (const char* key : {"metallicFactor", "roughnessFactor"})
                    if (in.contains(key) && unitNumber(in[key]))
                        pbr[key] = in[key];
            }
            if (!pbr.empty())
                material["pbrMetallicRoughness"] = pbr;
            if (source.contains("emissiveFactor") && unitNumbers(source["emissiveFactor"], 3))
                material["emissiveFactor"] = source["emissiveFactor"];
            const std::string alphaMode = source.value("alphaMode", std::string("OPAQUE"));
            if (alphaMode == "MASK" || alphaMode == "BLEND")
                material["alphaMode"] = alphaMode;
            if (alphaMode == "MASK" && source.contains("alphaCutoff") &&
                source["alphaCutoff"].is_number() && source["alphaCutoff"].get<double>() >= 0.0)
                material["alphaCutoff"] = source["alphaCutoff"];
            if (source.contains("doubleSided") && source["doubleSided"].is_boolean())
                material["doubleSided"] = source["doubleSided"];
            return material;
        }
    }
    return nullptr;
}

}  // namespace grass::core
