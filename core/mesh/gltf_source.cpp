#include "mesh/gltf_source.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdint>
#include <exception>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>

#include "mesh/gltf_draco.h"
#include "mesh/gltf_loader.h"
#include "mesh/gltf_meshopt.h"
#include "util/atomic_file.h"
#include "util/file_extension.h"
#include "util/json_text.h"
#include "util/path_inside.h"
#include "util/printable_text.h"

namespace grass::core::gltf {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// GLB container constants (glTF 2.0 §4.4).
constexpr std::uint32_t GLB_VERSION = 2;
constexpr std::uint32_t CHUNK_JSON = 0x4E4F534A;
constexpr std::uint32_t CHUNK_BIN = 0x004E4942;
constexpr std::size_t GLB_HEADER_BYTES = 12;
constexpr std::size_t CHUNK_HEADER_BYTES = 8;

// The only files tinygltf may open: virtual buffer names we hand it, mapped to files we have
// checked. Everything else (its "." fallback folder, any other path) does not exist for it.
struct FsContext {
    std::map<std::string, fs::path> files;
    // EXT_meshopt_compression fallback buffers without data: this many zero bytes each, which
    // the decoded bufferViews then fill (gltf_meshopt.h).
    std::map<std::string, std::uint64_t> zeros;
    // Buffers held in data: URIs that are not base64 (RFC 2397's percent-encoded octets, which
    // tinygltf does not read): their decoded bytes.
    std::map<std::string, std::string> decoded;
    // What fallback buffers may still claim in all: a compressed file cannot decode to more
    // than a bounded multiple of its size, so neither may its fallbacks.
    std::uint64_t fallbackBudget = 0;
};

// The bytes fallback buffers may claim: 64 times the file, and at least 64 MiB.
std::uint64_t fallbackBudgetFor(std::uint64_t fileBytes) {
    return std::max<std::uint64_t>(std::uint64_t{64} << 20, fileBytes * 64);
}

bool fileExists(const std::string& path, void* user) {
    const auto* context = static_cast<const FsContext*>(user);
    return context->files.count(path) != 0 || context->zeros.count(path) != 0 ||
           context->decoded.count(path) != 0;
}

std::string expandFilePath(const std::string& path, void*) {
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
    const auto* context = static_cast<const FsContext*>(user);
    if (const auto zeros = context->zeros.find(path); zeros != context->zeros.end()) {
        out->assign(static_cast<std::size_t>(zeros->second), 0);
        return true;
    }
    if (const auto decoded = context->decoded.find(path); decoded != context->decoded.end()) {
        out->assign(decoded->second.begin(), decoded->second.end());
        return true;
    }
    const auto& files = context->files;
    const auto it = files.find(path);
    if (it == files.end()) {
        if (err)
            *err += "refused to open " + path + "\n";
        return false;
    }
    std::ifstream in(it->second, std::ios::binary);
    std::error_code ec;
    const auto size = fs::file_size(it->second, ec);
    if (!in || ec) {
        if (err)
            *err += "cannot read " + it->second.string() + "\n";
        return false;
    }
    out->resize(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(out->size()));
    return static_cast<bool>(in);
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err)
        *err += "loading never writes files\n";
    return false;
}

// Geometry only: images are never decoded, so missing or broken textures cannot fail a load.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

std::uint32_t readU32(std::string_view bytes, std::size_t at) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at])) |
           static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 1])) << 8 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 2])) << 16 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 3])) << 24;
}

void appendU32(std::string& out, std::size_t value) {
    for (int shift = 0; shift < 32; shift += 8)
        out.push_back(static_cast<char>((value >> shift) & 0xFF));
}

struct GlbChunks {
    std::string_view json;
    std::string_view bin;
    bool hasBin = false;
};

// Splits a GLB into its JSON and BIN chunks; later chunks of other types are ignored (§4.4.3).
Result<GlbChunks> splitGlb(std::string_view bytes, const std::string& display) {
    if (bytes.size() < GLB_HEADER_BYTES + CHUNK_HEADER_BYTES)
        return makeError(display, "GLB is truncated: " + std::to_string(bytes.size()) +
                                      " bytes, less than its headers");
    if (const std::uint32_t version = readU32(bytes, 4); version != GLB_VERSION)
        return makeError(display, "GLB version " + std::to_string(version) +
                                      " is not supported (glTF 2.0 only)");
    const std::size_t length = readU32(bytes, 8);
    if (length > bytes.size())
        return makeError(display, "GLB is truncated: its header declares " +
                                      std::to_string(length) + " bytes, the file has " +
                                      std::to_string(bytes.size()));
    GlbChunks chunks;
    std::size_t offset = GLB_HEADER_BYTES;
    for (int index = 0; offset + CHUNK_HEADER_BYTES <= length; ++index) {
        const std::size_t chunkLength = readU32(bytes, offset);
        const std::uint32_t type = readU32(bytes, offset + 4);
        offset += CHUNK_HEADER_BYTES;
        if (chunkLength > length - offset)
            return makeError(display, "GLB is truncated or corrupt: chunk " +
                                          std::to_string(index) + " declares " +
                                          std::to_string(chunkLength) + " bytes, only " +
                                          std::to_string(length - offset) + " remain");
        const std::string_view payload = bytes.substr(offset, chunkLength);
        if (index == 0 && type != CHUNK_JSON)
            return makeError(display, "GLB is corrupt: its first chunk is not JSON");
        if (index == 0)
            chunks.json = payload;
        if (index == 1 && type == CHUNK_BIN) {
            chunks.bin = payload;
            chunks.hasBin = true;
        }
        offset += chunkLength;
    }
    if (chunks.json.empty())
        return makeError(display, "GLB is corrupt: its JSON chunk is empty");
    return chunks;
}

bool startsWithNoCase(std::string_view text, std::string_view prefix) {
    return text.size() >= prefix.size() &&
           std::equal(prefix.begin(), prefix.end(), text.begin(), [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) ==
                      std::tolower(static_cast<unsigned char>(b));
           });
}

int hexValue(char c) {
    return std::isdigit(static_cast<unsigned char>(c))
               ? c - '0'
               : std::tolower(static_cast<unsigned char>(c)) - 'a' + 10;
}

// RFC 3986 percent-decoding: "%20" is a space, a '+' stays a '+'.
std::string percentDecode(std::string_view uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out.push_back(static_cast<char>(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2])));
            i += 2;
        } else {
            out.push_back(uri[i]);
        }
    }
    return out;
}

// A relative file URI, decoded and checked to stay inside the glTF file's folder.
Result<fs::path> resolveFileUri(const std::string& uri, const std::string& what,
                                const std::string& display) {
    const auto refuse = [&](const std::string& why) {
        return makeError(display, what + " URI \"" + uri + "\" " + why +
                                      ": refused (buffer files must lie in the glTF file's "
                                      "folder)");
    };
    const std::size_t colon = uri.find(':');
    if (colon != std::string::npos && colon < uri.find('/') && colon > 0 &&
        std::isalpha(static_cast<unsigned char>(uri[0])))
        return refuse("is not a relative file path");
    // A query or fragment is not part of the file name.
    std::string decoded = percentDecode(uri.substr(0, uri.find_first_of("?#")));
    std::replace(decoded.begin(), decoded.end(), '\\', '/');
    if (decoded.find('\0') != std::string::npos)
        return refuse("contains a NUL byte");
    if (!decoded.empty() && decoded.front() == '/')
        return refuse("is an absolute path");
    const fs::path relative = fs::path(decoded).lexically_normal();
    if (relative.empty() || relative == ".")
        return refuse("names no file");
    if (*relative.begin() == "..")
        return refuse("leaves the glTF file's folder");
    return relative;
}

// The byte count tinygltf's base64 decoder yields: it stops at the first '=' or non-base64 char.
std::uint64_t base64DecodedSize(std::string_view payload) {
    std::uint64_t chars = 0;
    for (const char c : payload) {
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/'))
            break;
        ++chars;
    }
    const std::uint64_t rest = chars % 4;
    return chars / 4 * 3 + (rest > 1 ? rest - 1 : 0);
}

const Json* member(const Json& object, const char* key) {
    if (!object.is_object())
        return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

// glTF 2.0 §5.22: baseColorFactor is four numbers in 0..1, white by default.
std::vector<glm::vec4> baseColorFactors(const Json& doc) {
    std::vector<glm::vec4> colors;
    const Json* materials = member(doc, "materials");
    if (!materials || !materials->is_array())
        return colors;
    for (const Json& material : *materials) {
        glm::vec4 color(1.0f);
        const Json* pbr = material.is_object() ? member(material, "pbrMetallicRoughness") : nullptr;
        const Json* factor = pbr && pbr->is_object() ? member(*pbr, "baseColorFactor") : nullptr;
        if (factor && factor->is_array() && factor->size() == 4 &&
            std::all_of(factor->begin(), factor->end(), [](const Json& v) {
                return v.is_number() && v.get<double>() >= 0.0 && v.get<double>() <= 1.0;
            }))
            for (int c = 0; c < 4; ++c)
                color[c] = (*factor)[static_cast<std::size_t>(c)].get<float>();
        colors.push_back(color);
    }
    return colors;
}

std::vector<std::string> materialNamesOf(const Json& doc) {
    std::vector<std::string> names;
    const Json* materials = member(doc, "materials");
    if (!materials || !materials->is_array())
        return names;
    for (const Json& material : *materials) {
        const Json* name = material.is_object() ? member(material, "name") : nullptr;
        names.push_back(name && name->is_string() ? name->get<std::string>() : std::string());
    }
    return names;
}

// A Draco primitive's indices accessor has no bufferView (the indices are in the Draco stream),
// which tinygltf 2.7 refuses; the accessor moves into the extension object as DRACO_INDICES_KEY,
// where gltf_draco.cpp finds it to check the decoded count.
void moveDracoIndices(Json& doc) {
    Json* meshes = doc.is_object() && doc.contains("meshes") ? &doc["meshes"] : nullptr;
    if (!meshes || !meshes->is_array())
        return;
    for (Json& mesh : *meshes) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
            continue;
        for (Json& primitive : mesh["primitives"]) {
            if (!primitive.is_object() || !primitive.contains("indices") || !primitive.contains("extensions") ||
                !primitive["extensions"].is_object() ||
                !primitive["extensions"].contains("KHR_draco_mesh_compression") ||
                !primitive["extensions"]["KHR_draco_mesh_compression"].is_object())
                continue;
            primitive["extensions"]["KHR_draco_mesh_compression"][DRACO_INDICES_KEY] = primitive["indices"];
            primitive.erase("indices");
        }
    }
}

// Required extensions: we refuse those that change the geometry and that we cannot decode
// (glTF 2.0 §3.12: a loader MUST fail on a required extension it does not support), and
// ignore those that only concern appearance.
Result<void> checkRequiredExtensions(const Json& doc, const std::string& display,
                                     std::vector<std::string>& notes) {
    const Json* required = member(doc, "extensionsRequired");
    if (!required || !required->is_array())
        return {};
    static constexpr std::string_view APPEARANCE_PREFIXES[] = {
        "KHR_materials_", "KHR_texture_",          "EXT_texture_",        "MSFT_texture_",
        "KHR_lights_",    "EXT_lights_",           "ADOBE_materials_",    "EXT_materials_",
        "KHR_xmp",        "KHR_animation_pointer", "KHR_techniques_webgl"};
    for (const Json& entry : *required) {
        if (!entry.is_string())
            continue;
        const std::string name = entry.get<std::string>();
        // Decoded: quantized attributes, GPU instances, Draco (gltf_draco.h) and meshoptimizer
        // (gltf_meshopt.h) compression.
        if (name == "KHR_mesh_quantization" || name == "EXT_mesh_gpu_instancing" ||
            name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression" ||
            name == "KHR_meshopt_compression")
            continue;
        if (name == "CESIUM_RTC")
            continue;  // its centre only places the model on the globe (noteRtcCentre)
        const bool appearance =
            std::any_of(std::begin(APPEARANCE_PREFIXES), std::end(APPEARANCE_PREFIXES),
                        [&](std::string_view prefix) { return name.starts_with(prefix); });
        if (!appearance)
            return makeError(display, "requires extension " + name +
                                          ", which grass does not know (it may change the "
                                          "geometry)");
        notes.push_back("required extension " + name + " concerns appearance only: ignored");
    }
    return {};
}

// CESIUM_RTC (3D Tiles' glTF): positions are relative to a centre in the tileset's Earth-fixed,
// Z-up frame, meant to be added after the glTF's Y-up to Z-up turn. Adding it would put the
// ground thousands of kilometres out only for the import to move it back near the origin
// (docs/meshes.md), and would not change which way the vertices face: grass grows on the model
// in its local frame, and the note says so.
void noteRtcCentre(const Json& doc, std::vector<std::string>& notes) {
    const Json* extensions = member(doc, "extensions");
    const Json* rtc = extensions ? member(*extensions, "CESIUM_RTC") : nullptr;
    if (!rtc)
        return;
    std::string centre = "(none given)";
    if (const Json* c = member(*rtc, "center");
        c && c->is_array() && c->size() == 3 &&
        std::all_of(c->begin(), c->end(), [](const Json& v) { return v.is_number(); })) {
        char text[96];
        std::snprintf(text, sizeof text, "(%.1f, %.1f, %.1f)", (*c)[0].get<double>(),
                      (*c)[1].get<double>(), (*c)[2].get<double>());
        centre = text;
    }
    notes.push_back("CESIUM_RTC centre " + centre +
                    " not applied: the model is grown in its local frame (the centre only "
                    "places it on the globe)");
}

// The path tinygltf asks the file callbacks for a buffer's `name`: base dir and name joined as
// its JoinPath does.
std::string virtualBufferPath(const std::string& base, const std::string& name) {
    return base.empty() || base.back() == '/' ? base + name : base + "/" + name;
}

// The buffers some bufferView reads: its own `buffer`, and the `buffer` of its extensions (the
// compressed source of EXT_meshopt_compression and KHR_meshopt_compression).
std::vector<bool> buffersInUse(const Json& doc, std::size_t bufferCount) {
    std::vector<bool> used(bufferCount, false);
    const auto mark = [&](const Json* index) {
        if (index && index->is_number_unsigned() && index->get<std::uint64_t>() < bufferCount)
            used[index->get<std::size_t>()] = true;
    };
    const Json* views = member(doc, "bufferViews");
    if (!views || !views->is_array())
        return used;
    for (const Json& view : *views) {
        mark(member(view, "buffer"));
        if (const Json* extensions = member(view, "extensions");
            extensions && extensions->is_object())
            for (const Json& extension : *extensions)
                mark(member(extension, "buffer"));
    }
    return used;
}

// A buffer no bufferView reads holds nothing the geometry needs (glTF 2.0 allows one with no
// source at all; the validator's own valid files have them): its source is not checked or read,
// and tinygltf gets one byte of zeros in its place, so a missing file, a placeholder without a
// uri or an odd data: URI there does not refuse the whole model.
void replaceUnusedBuffer(Json& buffer, std::size_t index, const std::string& base,
                         FsContext& context) {
    const std::string name = "grass-unused-" + std::to_string(index) + ".bin";
    buffer = Json::object({{"byteLength", 1}, {"uri", name}});
    context.zeros[virtualBufferPath(base, name)] = 1;
}

// Checks one buffer's source and rewrites its JSON so tinygltf reads it without surprises:
// external files get a virtual name mapped in `context`; byteLength grows to the real size
// (tinygltf wants them equal; a longer file is harmless); data: URIs get a header it knows.
Result<void> prepareBuffer(Json& buffer, std::size_t index, const GlbChunks* glb,
                           const fs::path& folder, const std::string& base, FsContext& context,
                           const std::string& display) {
    const std::string what = "buffer " + std::to_string(index);
    const Json* lengthJson = member(buffer, "byteLength");
    if (!lengthJson || !lengthJson->is_number_unsigned())
        return {};  // tinygltf says what
    const std::uint64_t declared = lengthJson->get<std::uint64_t>();
    const auto truncated = [&](const std::string& source, std::uint64_t actual) {
        return makeError(display, what + " declares " + std::to_string(declared) + " bytes but " +
                                      source + " holds " + std::to_string(actual) +
                                      ": the file is truncated or corrupt");
    };
    const Json* uriJson = member(buffer, "uri");
    const Json* extensions = member(buffer, "extensions");
    const bool fallback = extensions && extensions->is_object() &&
                          std::any_of(extensions->begin(), extensions->end(), [](const Json& e) {
                              const Json* flag = member(e, "fallback");
                              return flag && flag->is_boolean() && flag->get<bool>();
                          });
    if ((!uriJson || !uriJson->is_string()) && fallback && !(glb && index == 0)) {
        // Its bytes come from decoding the compressed bufferViews that point into it.
        if (declared > context.fallbackBudget)
            return makeError(display, what + " is an EXT_meshopt_compression fallback of " +
                                          std::to_string(declared) +
                                          " bytes, more than a file of this size decodes to");
        context.fallbackBudget -= declared;
        const std::string name = "grass-fallback-" + std::to_string(index) + ".bin";
        buffer["uri"] = name;
        context.zeros[virtualBufferPath(base, name)] = declared;
        return {};
    }
    if (!uriJson || !uriJson->is_string()) {
        if (!glb)
            return makeError(display, what +
                                          " has no uri; a .gltf must name its buffer file "
                                          "or embed it as a data: URI");
        if (index != 0 || !glb->hasBin)
            return makeError(display, what + " has no uri and no GLB BIN chunk to read");
        if (declared > glb->bin.size())
            return truncated("the GLB BIN chunk", glb->bin.size());
        return {};
    }
    const std::string uri = uriJson->get<std::string>();
    if (startsWithNoCase(uri, "data:")) {
        const std::size_t comma = uri.find(',');
        const std::string_view header = std::string_view(uri).substr(0, comma);
        if (comma == std::string::npos)
            return makeError(display, what + " has a data: URI without the comma before its data");
        if (header.size() < 12 || !startsWithNoCase(header.substr(header.size() - 7), ";base64")) {
            // RFC 2397 (which glTF's data: URIs follow): without ";base64" the data are octets,
            // percent-encoded where not plain characters.
            std::string bytes = percentDecode(std::string_view(uri).substr(comma + 1));
            if (bytes.size() < declared)
                return truncated("its data: URI", bytes.size());
            buffer["byteLength"] = bytes.size();
            const std::string name = "grass-data-" + std::to_string(index) + ".bin";
            buffer["uri"] = name;
            context.decoded[virtualBufferPath(base, name)] = std::move(bytes);
            return {};
        }
        const std::uint64_t actual = base64DecodedSize(std::string_view(uri).substr(comma + 1));
        if (actual < declared)
            return truncated("its data: URI", actual);
        buffer["byteLength"] = actual;
        if (header != "data:application/octet-stream;base64" &&
            header != "data:application/gltf-buffer;base64")
            buffer["uri"] = "data:application/octet-stream;base64," + uri.substr(comma + 1);
        return {};
    }
    const auto relative = resolveFileUri(uri, what, display);
    if (!relative)
        return relative.error();
    const fs::path file = folder / *relative;
    std::error_code ec;
    if (!isInsideFolder(file, folder))
        return makeError(display, what + " file \"" + relative->generic_string() +
                                      "\" is a symbolic link leading outside the glTF file's "
                                      "folder; copy the file next to the glTF instead");
    if (!fs::is_regular_file(file, ec))
        return makeError(display, what + " file \"" + relative->generic_string() +
                                      "\" not found next to the glTF file");
    const std::uint64_t actual = fs::file_size(file, ec);
    if (ec)
        return makeError(display, what + " file \"" + relative->generic_string() +
                                      "\" cannot be read: " + ec.message());
    if (actual < declared)
        return truncated("file \"" + relative->generic_string() + "\"", actual);
    buffer["byteLength"] = actual;
    const std::string name = "grass-buffer-" + std::to_string(index) + ".bin";
    buffer["uri"] = name;
    context.files[virtualBufferPath(base, name)] = file;
    return {};
}

}  // namespace

Result<fs::path> fileNextToGltf(const fs::path& gltfFile, const std::string& uri,
                                const std::string& what) {
    const std::string display = gltfFile.string();
    const auto relative = resolveFileUri(uri, what, display);
    if (!relative)
        return relative.error();
    const fs::path folder = fs::absolute(gltfFile).parent_path().lexically_normal();
    const fs::path file = folder / *relative;
    std::error_code ec;
    if (!isInsideFolder(file, folder))
        return makeError(display, what + " file \"" + relative->generic_string() +
                                      "\" is a symbolic link leading outside the glTF file's folder");
    if (!fs::is_regular_file(file, ec))
        return makeError(display, what + " file \"" + relative->generic_string() +
                                      "\" not found next to the glTF file");
    return file;
}

namespace {

// tinygltf's multi-line messages as one line.
std::string oneLine(const std::string& text) {
    std::string out = joinedLines(text);
    constexpr std::size_t MAX_CHARS = 300;  // tinygltf may quote a whole data: URI
    if (out.size() > MAX_CHARS)
        out = out.substr(0, MAX_CHARS) + "...";
    return out;
}

std::string glbBytes(const std::string& json, const GlbChunks& chunks) {
    std::string out;
    const std::size_t jsonPadded = (json.size() + 3) / 4 * 4;
    const std::size_t binPadded = (chunks.bin.size() + 3) / 4 * 4;
    const bool bin = chunks.hasBin && !chunks.bin.empty();
    const std::size_t total = GLB_HEADER_BYTES + CHUNK_HEADER_BYTES + jsonPadded +
                              (bin ? CHUNK_HEADER_BYTES + binPadded : 0);
    out.reserve(total);
    out += "glTF";
    appendU32(out, GLB_VERSION);
    appendU32(out, total);
    appendU32(out, jsonPadded);
    appendU32(out, CHUNK_JSON);
    out += json;
    out.append(jsonPadded - json.size(), ' ');
    if (bin) {
        appendU32(out, binPadded);
        appendU32(out, CHUNK_BIN);
        out += chunks.bin;
        out.append(binPadded - chunks.bin.size(), '\0');
    }
    return out;
}

}  // namespace

std::string otherMeshFormat(const fs::path& file, std::string_view bytes) {
    const std::string ext = lowerExtension(file);
    std::string kind;
    if (bytes.starts_with("Kaydara FBX Binary") || ext == ".fbx")
        kind = "an FBX file";
    else if (bytes.starts_with("ply\n") || bytes.starts_with("ply\r") || ext == ".ply")
        kind = "a PLY file";
    else if (bytes.starts_with("solid ") || ext == ".stl")
        kind = "an STL file";
    else if (ext == ".obj")
        kind = "an OBJ file";
    else if (ext == ".dae")
        kind = "a COLLADA file";
    else if (ext == ".blend")
        kind = "a Blender file";
    else if (ext == ".usd" || ext == ".usda" || ext == ".usdc" || ext == ".usdz")
        kind = "a USD file";
    else if (ext == ".3ds" || ext == ".abc" || ext == ".x3d")
        kind = "a " + ext.substr(1) + " file";
    if (kind.empty())
        return {};
    return "; it looks like " + kind +
           ": grass reads glTF 2.0, so export the mesh as .glb or .gltf from the tool that made "
           "it (Blender: File > Export > glTF 2.0)";
}

Result<GltfSource> parseGltfFile(const fs::path& file) {
    const std::string display = file.string();
    auto bytes = readFile(file);
    if (!bytes)
        return bytes.error();
    if (bytes->empty())
        return makeError(display, "is empty, not a glTF file");
    const bool binary = bytes->starts_with("glTF");
    GlbChunks chunks;
    std::string_view jsonText = *bytes;
    if (binary) {
        auto split = splitGlb(*bytes, display);
        if (!split)
            return split.error();
        chunks = *split;
        jsonText = chunks.json;
    } else {
        const std::size_t first = jsonText.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
        if (first == std::string_view::npos || jsonText[first] != '{')
            return makeError(display,
                             "is not a glTF file: it is neither glTF JSON nor a GLB "
                             "(which starts with \"glTF\")" +
                                 otherMeshFormat(file, *bytes));
    }

    if (jsonDepth(jsonText) > MAX_JSON_DEPTH)
        return makeError(display, "invalid glTF JSON: nested more than " +
                                      std::to_string(MAX_JSON_DEPTH) + " levels deep");
    GltfSource source;
    Json doc;
    try {
        doc = Json::parse(jsonText.begin(), jsonText.end());
    } catch (const std::exception& e) {
        std::string what = e.what();
        what.erase(0, what.find("] ") == std::string::npos ? 0 : what.find("] ") + 2);
        return makeError(display, "invalid glTF JSON (truncated or corrupt): " + what);
    }
    const Json* asset = member(doc, "asset");
    const Json* version = asset ? member(*asset, "version") : nullptr;
    if (!version || !version->is_string())
        return makeError(display, "is not a glTF file: its JSON has no asset.version");
    if (!version->get<std::string>().starts_with("2."))
        return makeError(display,
                         "is glTF " + version->get<std::string>() + "; only glTF 2.0 is supported");
    noteRtcCentre(doc, source.notes);
    if (auto required = checkRequiredExtensions(doc, display, source.notes); !required)
        return required.error();

    const fs::path folder = fs::absolute(file).parent_path().lexically_normal();
    const std::string base = folder.string();
    FsContext context;
    context.fallbackBudget = fallbackBudgetFor(bytes->size());
    if (Json* buffers = doc.is_object() && doc.contains("buffers") ? &doc["buffers"] : nullptr;
        buffers && buffers->is_array()) {
        const std::vector<bool> used = buffersInUse(doc, buffers->size());
        for (std::size_t i = 0; i < buffers->size(); ++i) {
            if (!used[i]) {
                replaceUnusedBuffer((*buffers)[i], i, base, context);
                continue;
            }
            auto prepared = prepareBuffer((*buffers)[i], i, binary ? &chunks : nullptr, folder,
                                          base, context, display);
            if (!prepared)
                return prepared.error();
        }
    }
    source.baseColors = baseColorFactors(doc);
    source.materialNames = materialNamesOf(doc);
    moveDracoIndices(doc);
    // Geometry needs none of these; left in, a broken texture or animation could fail the load.
    // Skins stay: they pose their meshes (gltf_skin_pose.h).
    for (const char* key : {"images", "textures", "samplers", "materials", "animations", "cameras"})
        doc.erase(key);
    const std::string json = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
    const std::string input = binary ? glbBytes(json, chunks) : json;
    bytes = std::string();  // the GLB's BIN chunk now lives in `input`
    if (input.size() > std::numeric_limits<unsigned int>::max())
        return makeError(display, "is larger than 4 GiB, which tinygltf cannot read");

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, &context});
    std::string err, warn;
    bool ok = false;
    try {
        const auto size = static_cast<unsigned int>(input.size());
        ok = binary
                 ? loader.LoadBinaryFromMemory(&source.model, &err, &warn,
                                               reinterpret_cast<const unsigned char*>(input.data()),
                                               size, base)
                 : loader.LoadASCIIFromString(&source.model, &err, &warn, input.data(), size, base);
    } catch (const std::exception& e) {
        ok = false;
        err = e.what();
    }
    if (!ok)
        return makeError(display, "invalid glTF: " + (err.empty() ? std::string("tinygltf failed")
                                                                  : oneLine(err)));
    if (const std::string warnings = oneLine(warn + err); !warnings.empty())
        source.notes.push_back("tinygltf: " + warnings);
    if (auto decoded = decodeMeshoptBufferViews(source.model); !decoded)
        return makeError(display, decoded.error().message);
    return source;
}

}  // namespace grass::core::gltf

namespace grass::core {

namespace fs = std::filesystem;

std::vector<fs::path> gltfExternalFiles(const fs::path& file) {
    std::vector<fs::path> files;
    auto bytes = readFile(file, MAX_JSON_FILE_BYTES);
    if (!bytes || bytes->starts_with("glTF"))
        return files;
    const auto doc = parseJsonText(*bytes, file.string());
    if (!doc)
        return files;
    for (const char* key : {"buffers", "images"}) {
        const gltf::Json* list = gltf::member(*doc, key);
        if (list == nullptr || !list->is_array())
            continue;
        for (const gltf::Json& entry : *list) {
            const gltf::Json* uri = gltf::member(entry, "uri");
            if (uri == nullptr || !uri->is_string() ||
                gltf::startsWithNoCase(uri->get<std::string>(), "data:"))
                continue;
            if (auto relative = gltf::resolveFileUri(uri->get<std::string>(), key, file.string()))
                files.push_back(file.parent_path() / *relative);
        }
    }
    return files;
}

}  // namespace grass::core
