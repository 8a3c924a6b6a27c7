#include "util/content_digest.h"

#include "util/atomic_file.h"

namespace grass {

std::uint64_t contentDigest(std::string_view bytes, std::uint64_t seed) {
    constexpr std::uint64_t FNV1A_PRIME = 1099511628211ull;
    std::uint64_t digest = seed;
    for (const char byte : bytes) {
        digest ^= static_cast<unsigned char>(byte);
        digest *= FNV1A_PRIME;
    }
    return digest;
}

std::optional<std::uint64_t> fileDigest(const std::filesystem::path& file) {
    auto text = readFile(file, MAX_JSON_FILE_BYTES);
    if (!text)
        return std::nullopt;
    return contentDigest(*text);
}

}  // namespace grass
