#include "util/content_digest.h"

#include "util/atomic_file.h"

namespace grass {

std::uint64_t contentDigest(std::string_view bytes) {
    std::uint64_t digest = 0xcbf29ce484222325ULL;  // FNV-1a 64's offset basis and prime
    for (const char byte : bytes) {
        digest ^= static_cast<unsigned char>(byte);
        digest *= 0x100000001b3ULL;
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
