#include "export/source_material.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <map>

#include "mesh/gltf_source.h"
#include "util/atomic_file.h"
#include "util/result.h"

namespace grass::core {

namespace {

using nlohmann::json;

constexpr std::uint32_t GLB_MAGIC = 0x46546C67u;  // "glTF"
constexpr std::uint32_t CHUNK_JSON = 0x4E4F534Au;
constexpr std::uint32_t CHUNK_BIN = 0x004E4942u;

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


// An image's bytes are refused beyond this (a terrain's texture is a few MB).
constexpr std::size_t MAX_IMAGE_BYTES = std::size_t{256} << 20;

// A .glb's BIN chunk (empty when there is none).
std::string_view glbBin(const std::string& bytes) {
    if (bytes.size() < 20 || u32At(bytes, 0) != GLB_MAGIC)
        return {};
    const std::size_t jsonEnd = 20 + std::size_t{u32At(bytes, 12)};
    if (jsonEnd + 8 > bytes.size() || u32At(bytes, jsonEnd + 4) != CHUNK_BIN)
        return {};
    const std::size_t length = u32At(bytes, jsonEnd);
    if (length > bytes.size() - jsonEnd - 8)
        return {};
    return std::string_view(bytes).substr(jsonEnd + 8, length);
}

// PNG and JPEG, the core spec's image formats, told by their signatures.
std::string imageMimeType(std::string_view bytes) {
    if (bytes.size() >= 8 && bytes.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8))
        return "image/png";
    if (bytes.size() >= 3 && bytes.substr(0, 3) == std::string_view("\xFF\xD8\xFF", 3))
        return "image/jpeg";
    return {};
}

// Reads the images that a material's texture slots name, collecting them in `out.textures`.
class TextureReader {
public:
    TextureReader(const std::filesystem::path& file, const json& doc, const std::string& bytes,
                  bool primitiveHasUv, SourceMaterial& out)
        : mFile(file), mDoc(doc), mBytes(bytes), mHasUv(primitiveHasUv), mOut(out) {}

    // The slot of `parent[key]` rewritten to index `out.textures`, or null (with a note) when
    // its texture cannot travel.
    json slot(const json& parent, const char* key) {
        if (!parent.contains(key) || !parent[key].is_object())
            return nullptr;
        const json& in = parent[key];
        const auto skip = [&](const std::string& why) {
            mOut.notes.push_back(std::string(key) + " not carried: " + why);
            return json(nullptr);
        };
        if (!in.contains("index") || !in["index"].is_number_unsigned())
            return skip("no texture index");
        if (in.value("texCoord", 0) != 0)
            return skip("it reads TEXCOORD_" + std::to_string(in.value("texCoord", 0)) +
                        ", the terrain keeps TEXCOORD_0 only");
        if (!mHasUv)
            return skip("the primitive has no TEXCOORD_0 (the terrain's UVs are generated)");
        if (in.contains("extensions"))
            return skip("it uses texture extensions (e.g. KHR_texture_transform)");
        const std::size_t textureIndex = in["index"].get<std::size_t>();
        json slot = json::object();
        for (const char* number : {"scale", "strength"})
            if (in.contains(number) && in[number].is_number())
                slot[number] = in[number];
        if (slot.contains("strength") && !unitNumber(slot["strength"]))
            slot.erase("strength");
        // Slots that share a source texture share its copy.
        if (const auto known = mCarried.find(textureIndex); known != mCarried.end()) {
            slot["index"] = known->second;
            return slot;
        }
        const json* texture = element("textures", textureIndex);
        if (!texture || !texture->contains("source") || !(*texture)["source"].is_number_unsigned())
            return skip("texture " + std::to_string(textureIndex) + " names no PNG or JPEG image");
        const std::size_t imageIndex = (*texture)["source"].get<std::size_t>();
        const auto image = imageBytes(imageIndex);
        if (!image)
            return skip(image.error().message);
        const std::string mimeType = imageMimeType(*image);
        if (mimeType.empty())
            return skip("image " + std::to_string(imageIndex) + " is neither PNG nor JPEG");
        json sampler = nullptr;
        if (texture->contains("sampler") && (*texture)["sampler"].is_number_unsigned())
            if (const json* s = element("samplers", (*texture)["sampler"].get<std::size_t>()))
                sampler = samplerOf(*s);
        slot["index"] = mOut.textures.size();
        mCarried[textureIndex] = mOut.textures.size();
        mOut.textures.push_back({mimeType, std::move(*image), std::move(sampler)});
        return slot;
    }

private:
    const json* element(const char* array, std::size_t index) const {
        if (!mDoc.contains(array) || !mDoc[array].is_array() || index >= mDoc[array].size() ||
            !mDoc[array][index].is_object())
            return nullptr;
        return &mDoc[array][index];
    }

    // The filters and wrap modes the spec allows (§5.26).
    static json samplerOf(const json& in) {
        json out = json::object();
        const auto allowed = [&](const char* key, std::initializer_list<int> values) {
            if (in.contains(key) && in[key].is_number_integer() &&
                std::find(values.begin(), values.end(), in[key].get<int>()) != values.end())
                out[key] = in[key];
        };
        allowed("magFilter", {9728, 9729});
        allowed("minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
        allowed("wrapS", {33071, 33648, 10497});
        allowed("wrapT", {33071, 33648, 10497});
        return out.empty() ? json(nullptr) : out;
    }

    // The encoded bytes of image `index`: a data: URI, a file next to the glTF, or a bufferView
    // of the GLB's BIN chunk or of a buffer file.
    Result<std::string> imageBytes(std::size_t index) const {
        const std::string what = "image " + std::to_string(index);
        const json* image = element("images", index);
        if (!image)
            return makeError("", what + " does not exist");
        if (image->contains("uri") && (*image)["uri"].is_string())
            return uriBytes((*image)["uri"].get<std::string>(), what);
        if (!image->contains("bufferView") || !(*image)["bufferView"].is_number_unsigned())
            return makeError("", what + " has neither a uri nor a bufferView");
        const json* view = element("bufferViews", (*image)["bufferView"].get<std::size_t>());
        if (!view || !view->contains("buffer") || !(*view)["buffer"].is_number_unsigned() ||
            !view->contains("byteLength") || !(*view)["byteLength"].is_number_unsigned())
            return makeError("", what + " has a broken bufferView");
        const std::size_t bufferIndex = (*view)["buffer"].get<std::size_t>();
        const json* buffer = element("buffers", bufferIndex);
        if (!buffer)
            return makeError("", what + "'s buffer does not exist");
        std::string data;
        if (buffer->contains("uri") && (*buffer)["uri"].is_string()) {
            auto read = uriBytes((*buffer)["uri"].get<std::string>(), what + "'s buffer");
            if (!read)
                return read.error();
            data = std::move(*read);
        } else if (bufferIndex == 0) {
            data = std::string(glbBin(mBytes));
        }
        const std::size_t offset = view->value("byteOffset", std::size_t{0});
        const std::size_t length = (*view)["byteLength"].get<std::size_t>();
        if (offset > data.size() || length > data.size() - offset)
            return makeError("", what + "'s bufferView lies outside its buffer");
        if (length > MAX_IMAGE_BYTES)
            return makeError("", what + " is larger than 256 MB");
        return data.substr(offset, length);
    }

    Result<std::string> uriBytes(const std::string& uri, const std::string& what) const {
        if (tinygltf::IsDataURI(uri)) {
            std::vector<unsigned char> decoded;
            std::string mime;
            if (!tinygltf::DecodeDataURI(&decoded, mime, uri, 0, false))
                return makeError("", what + " has a data: URI that is not base64 PNG or JPEG");
            return std::string(decoded.begin(), decoded.end());
        }
        const auto path = gltf::fileNextToGltf(mFile, uri, what);
        if (!path)
            return makeError("", path.error().message);
        std::error_code ec;
        if (std::filesystem::file_size(*path, ec) > MAX_IMAGE_BYTES || ec)
            return makeError("", what + " file cannot be read or is larger than 256 MB");
        auto read = readFile(*path);
        if (!read)
            return makeError("", what + " file cannot be read");
        return std::move(*read);
    }

    const std::filesystem::path& mFile;
    const json& mDoc;
    const std::string& mBytes;
    bool mHasUv;
    SourceMaterial& mOut;
    std::map<std::size_t, std::size_t> mCarried;  // source texture → index into mOut.textures
};

}  // namespace

SourceMaterial sourceMeshMaterial(const std::filesystem::path& file) {
    SourceMaterial out;
    auto bytes = readFile(file);
    if (!bytes)
        return out;
    const json doc = documentOf(*bytes);
    if (!doc.is_object() || !doc.contains("meshes") || !doc["meshes"].is_array() ||
        !doc.contains("materials") || !doc["materials"].is_array())
        return out;
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
            json& material = out.material;
            material = {{"name", "terrain: " + source.value("name", std::string("material ") +
                                                                     std::to_string(index))}};
            // Only values the spec allows travel: a broken factor in the source would make the
            // export invalid.
            const bool hasUv = primitive.contains("attributes") && primitive["attributes"].is_object() &&
                               primitive["attributes"].contains("TEXCOORD_0");
            TextureReader textures(file, doc, *bytes, hasUv, out);
            json pbr = json::object();
            if (source.contains("pbrMetallicRoughness") && source["pbrMetallicRoughness"].is_object()) {
                const json& in = source["pbrMetallicRoughness"];
                if (in.contains("baseColorFactor") && unitNumbers(in["baseColorFactor"], 4))
                    pbr["baseColorFactor"] = in["baseColorFactor"];
                for (const char* key : {"metallicFactor", "roughnessFactor"})
                    if (in.contains(key) && unitNumber(in[key]))
                        pbr[key] = in[key];
                for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
                    if (auto slot = textures.slot(in, key); !slot.is_null())
                        pbr[key] = slot;
            }
            if (!pbr.empty())
                material["pbrMetallicRoughness"] = pbr;
            for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
                if (auto slot = textures.slot(source, key); !slot.is_null())
                    material[key] = slot;
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
            return out;
        }
    }
    return out;
}

}  // namespace grass::core
