#include "collider/packing_cache.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <system_error>

#include "util/atomic_file.h"
#include "util/content_digest.h"
#include "util/json_text.h"

namespace grass::core {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// 4096 spheres take about 300 KB; anything far larger is not ours.
constexpr std::uintmax_t MAX_CACHE_BYTES = 16u << 20u;

// FNV-1a (util/content_digest.h) over pieces of several kinds.
class Fnv1a {
public:
    void bytes(const void* data, std::size_t size) {
        mHash = contentDigest(std::string_view(static_cast<const char*>(data), size), mHash);
    }
    void u64(std::uint64_t value) { bytes(&value, sizeof value); }
    std::uint64_t value() const { return mHash; }

private:
    std::uint64_t mHash = FNV1A_OFFSET;
};

const Json* member(const Json& object, const char* name) {
    const auto it = object.find(name);
    return it == object.end() ? nullptr : &*it;
}

std::optional<double> finiteNumber(const Json* value) {
    if (value == nullptr || !value->is_number())
        return std::nullopt;
    const double number = value->get<double>();
    return std::isfinite(number) ? std::optional<double>(number) : std::nullopt;
}

std::optional<std::uint64_t> unsignedNumber(const Json* value) {
    if (value == nullptr || !value->is_number_unsigned())
        return std::nullopt;
    return value->get<std::uint64_t>();
}

// The packing in `text` when it is a well-formed cache for `key` and `params`; anything else
// (truncated, hand-edited, another version) is nullopt and gets repacked.
std::optional<SpherePacking> parseCache(const std::string& text, const std::string& key,
                                        const SpherePackingParams& params) {
    const auto parsed = parseJsonText(text, key);
    if (!parsed)
        return std::nullopt;
    const Json& doc = *parsed;
    if (!doc.is_object())
        return std::nullopt;
    const Json* format = member(doc, "format");
    const Json* cachedKey = member(doc, "key");
    const Json* cachedParams = member(doc, "params");
    if (format == nullptr || !format->is_string() ||
        format->get<std::string>() != PACKING_CACHE_FORMAT ||
        unsignedNumber(member(doc, "version")) != std::uint64_t{PACKING_CACHE_VERSION} ||
        cachedKey == nullptr || !cachedKey->is_string() || cachedKey->get<std::string>() != key ||
        cachedParams == nullptr || !cachedParams->is_object() ||
        unsignedNumber(member(*cachedParams, "sphereCount")) != params.sphereCount ||
        unsignedNumber(member(*cachedParams, "resolution")) != params.resolution)
        return std::nullopt;
    const auto voxelSize = finiteNumber(member(doc, "voxelSize"));
    const auto insideShare = finiteNumber(member(doc, "insideShare"));
    const auto coverage = finiteNumber(member(doc, "coverage"));
    const auto samples = unsignedNumber(member(doc, "samples"));
    const Json* spheres = member(doc, "spheres");
    if (!voxelSize || *voxelSize <= 0.0 || !insideShare || *insideShare < 0.0 ||
        *insideShare > 1.0 || !coverage || *coverage < 0.0 || *coverage > 1.0 || !samples ||
        *samples > UINT32_MAX || spheres == nullptr || !spheres->is_array() || spheres->empty() ||
        spheres->size() > params.sphereCount)
        return std::nullopt;
    SpherePacking packing;
    packing.voxelSize = static_cast<float>(*voxelSize);
    packing.insideShare = static_cast<float>(*insideShare);
    packing.coverage = static_cast<float>(*coverage);
    packing.samples = static_cast<std::uint32_t>(*samples);
    for (const Json& entry : *spheres) {
        if (!entry.is_array() || entry.size() != 4)
            return std::nullopt;
        float values[4];
        for (std::size_t i = 0; i < 4; ++i) {
            const auto number = finiteNumber(&entry[i]);
            if (!number)
                return std::nullopt;
            // The file holds each float's shortest round-trip decimal: this cast is exact.
            values[i] = static_cast<float>(*number);
        }
        if (!(values[3] > 0.0f))
            return std::nullopt;
        packing.spheres.push_back({{values[0], values[1], values[2]}, values[3]});
    }
    return packing;
}

// Written by hand around nlohmann's number formatting so each sphere takes one line.
std::string cacheText(const std::string& key, const SpherePackingParams& params,
                      const SpherePacking& packing) {
    const auto number = [](float value) { return Json(static_cast<double>(value)).dump(); };
    std::string text = "{\n";
    text += "  \"format\": " + Json(std::string(PACKING_CACHE_FORMAT)).dump() + ",\n";
    text += "  \"version\": " + std::to_string(PACKING_CACHE_VERSION) + ",\n";
    text += "  \"key\": " + Json(key).dump() + ",\n";
    text += "  \"params\": {\"sphereCount\": " + std::to_string(params.sphereCount) +
            ", \"resolution\": " + std::to_string(params.resolution) + "},\n";
    text += "  \"voxelSize\": " + number(packing.voxelSize) + ",\n";
    text += "  \"insideShare\": " + number(packing.insideShare) + ",\n";
    text += "  \"coverage\": " + number(packing.coverage) + ",\n";
    text += "  \"samples\": " + std::to_string(packing.samples) + ",\n";
    text += "  \"spheres\": [";
    for (std::size_t i = 0; i < packing.spheres.size(); ++i) {
        const PackedSphere& s = packing.spheres[i];
        text += (i == 0 ? "\n    [" : ",\n    [") + number(s.centre.x) + ", " + number(s.centre.y) +
                ", " + number(s.centre.z) + ", " + number(s.radiusM) + "]";
    }
    text += "\n  ]\n}\n";
    return text;
}

}  // namespace

std::string packingCacheKey(std::string_view meshFileBytes, const SurfaceMesh& mesh,
                            const SpherePackingParams& params) {
    Fnv1a hash;
    hash.bytes(PACKING_CACHE_FORMAT.data(), PACKING_CACHE_FORMAT.size());
    hash.u64(PACKING_CACHE_VERSION);
    hash.u64(meshFileBytes.size());
    hash.bytes(meshFileBytes.data(), meshFileBytes.size());
    hash.u64(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        for (const glm::vec3& p : facePositions(mesh, fh)) {
            std::uint32_t bits[3];
            std::memcpy(bits, &p.x, sizeof bits);
            hash.bytes(bits, sizeof bits);
        }
    }
    hash.u64(params.sphereCount);
    hash.u64(params.resolution);
    static constexpr char HEX[] = "0123456789abcdef";
    std::string key(16, '0');
    for (int i = 0; i < 16; ++i)
        key[static_cast<std::size_t>(i)] = HEX[(hash.value() >> (60 - 4 * i)) & 0xFu];
    return key;
}

Result<SpherePacking> loadOrPackSpheres(const fs::path& meshFile, const SurfaceMesh& mesh,
                                        const SpherePackingParams& params,
                                        const fs::path& cacheFile, bool* fromCache,
                                        std::string* cacheNote) {
    if (fromCache != nullptr)
        *fromCache = false;
    if (cacheNote != nullptr)
        cacheNote->clear();
    Result<std::string> meshBytes = readFile(meshFile);
    if (!meshBytes)
        return meshBytes.error();
    const std::string key = packingCacheKey(*meshBytes, mesh, params);

    std::error_code ec;
    const bool cacheExists = fs::is_regular_file(cacheFile, ec);
    const std::uintmax_t cacheSize = cacheExists ? fs::file_size(cacheFile, ec) : 0;
    if (cacheExists && !ec && cacheSize <= MAX_CACHE_BYTES) {
        if (const Result<std::string> text = readFile(cacheFile, MAX_JSON_FILE_BYTES); text) {
            if (std::optional<SpherePacking> cached = parseCache(*text, key, params)) {
                if (fromCache != nullptr)
                    *fromCache = true;
                return std::move(*cached);
            }
        }
    }

    Result<SpherePacking> packing = packSpheres(mesh, params);
    if (!packing) {
        Error error = packing.error();
        if (error.path.empty())
            error.path = meshFile.string();
        return error;
    }
    // The cache only saves the next load the packing: failing to write it costs time, not the
    // scene.
    std::string problem;
    if (cacheFile.has_parent_path()) {
        fs::create_directories(cacheFile.parent_path(), ec);
        if (ec)
            problem = "cannot create its folder: " + ec.message();
    }
    if (problem.empty()) {
        if (Result<void> written = writeFileAtomic(cacheFile, cacheText(key, params, *packing));
            !written)
            problem = written.error().message;
    }
    if (!problem.empty() && cacheNote != nullptr)
        *cacheNote = "sphere-packing cache " + cacheFile.string() + " not written (" + problem +
                     "): packed in memory, and packed again on the next load";
    return packing;
}

fs::path packingCachePath(const fs::path& projectFolder, const fs::path& meshFile,
                          const SpherePackingParams& params) {
    return projectFolder / ".grass-cache" /
           (meshFile.stem().string() + "." + std::to_string(params.sphereCount) + "-" +
            std::to_string(params.resolution) + ".spheres.json");
}

}  // namespace grass::core
