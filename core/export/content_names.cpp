#include "export/content_names.h"

#include <cstdio>
#include <set>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/atomic_file.h"
#include "util/json_text.h"

namespace grass::core {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr std::size_t HASH_DIGITS = 16;

bool isLowerHex(char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
}

void collectNames(const json& value, std::set<std::string>& names) {
    if (value.is_object()) {
        for (auto it = value.begin(); it != value.end(); ++it) {
            if ((it.key() == "uri" || it.key() == "file") && it.value().is_string())
                names.insert(it.value().get<std::string>());
            else
                collectNames(it.value(), names);
        }
    } else if (value.is_array()) {
        for (const json& element : value)
            collectNames(element, names);
    }
}

bool isEntryPoint(const fs::path& file) {
    return file.extension() == ".gltf" || file.filename() == "manifest.json";
}

}  // namespace

std::uint64_t contentHash(std::span<const std::byte> bytes, std::uint64_t seed) {
    return contentDigest(
        std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), seed);
}

std::uint64_t contentHash(std::string_view bytes, std::uint64_t seed) {
    return contentDigest(bytes, seed);
}

std::string contentAddressedName(std::string_view prefix, std::uint64_t hash,
                                 std::string_view suffix) {
    char digits[HASH_DIGITS + 1];
    std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash));
    return std::string(prefix) + "-" + digits + std::string(suffix);
}

bool isContentAddressedName(std::string_view fileName) {
    // The hash is the 16 hex digits after the last '-' that is followed by them and a '.'.
    for (std::size_t dash = fileName.rfind('-'); dash != std::string_view::npos && dash > 0;
         dash = fileName.rfind('-', dash - 1)) {
        const std::size_t dot = dash + 1 + HASH_DIGITS;
        if (dot + 1 >= fileName.size() || fileName[dot] != '.')
            continue;
        bool hex = true;
        for (std::size_t i = dash + 1; i < dot; ++i)
            hex = hex && isLowerHex(fileName[i]);
        if (hex)
            return true;
    }
    return false;
}

std::size_t removeUnreferencedExportFiles(const fs::path& folder) {
    std::error_code ec;
    std::vector<fs::path> candidates;
    std::set<std::string> named;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
        if (!entry.is_regular_file(ec))
            continue;
        const fs::path& file = entry.path();
        if (isEntryPoint(file)) {
            auto text = readFile(file, MAX_JSON_FILE_BYTES);
            if (!text)
                return 0;
            // Not ours, or nested deep enough to overflow a recursive walk: keep every file.
            const auto parsed = parseJsonText(*text, file.string());
            if (!parsed)
                return 0;
            collectNames(*parsed, named);
        } else if (isContentAddressedName(file.filename().string())) {
            candidates.push_back(file);
        }
    }
    if (ec)
        return 0;
    std::size_t removed = 0;
    for (const fs::path& file : candidates)
        if (!named.count(file.filename().string()) && fs::remove(file, ec))
            ++removed;
    return removed;
}

}  // namespace grass::core
