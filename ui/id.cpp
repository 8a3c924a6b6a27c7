#include "ui/types.h"

namespace grass::ui {

namespace {

// FNV-1a over the bytes, then a 64-bit finaliser (splitmix64) so ids of similar strings and
// consecutive loop indices spread over the whole range: a parent id combined with salt "a" and
// "b" must not collide, and neither must index 1 and 2.
constexpr std::uint64_t FNV_OFFSET = 0xcbf29ce484222325ULL;
constexpr std::uint64_t FNV_PRIME = 0x100000001b3ULL;

std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::uint64_t hashBytes(std::uint64_t seed, std::string_view bytes) {
    std::uint64_t h = FNV_OFFSET ^ seed;
    for (unsigned char c : bytes) {
        h ^= c;
        h *= FNV_PRIME;
    }
    return mix(h);
}

}  // namespace

Id Id::fromString(std::string_view text) {
    return {hashBytes(0, text)};
}

Id Id::with(std::string_view salt) const {
    return {hashBytes(value, salt)};
}

Id Id::with(std::uint64_t salt) const {
    return {mix(value ^ mix(salt))};
}

}  // namespace grass::ui
