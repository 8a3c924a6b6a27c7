#include "util/blade_pass_group.h"

#include <charconv>
#include <cstdlib>
#include <cstring>

#include "util/assert.h"

namespace grass::core {

bool isBladePassGroupSize(std::uint32_t size) {
    return size >= BLADE_PASS_GROUP_STEP && size <= MAX_BLADE_PASS_GROUP &&
           size % BLADE_PASS_GROUP_STEP == 0;
}

Result<std::uint32_t> bladePassGroupSize(const char* text) {
    if (text == nullptr || *text == '\0')
        return DEFAULT_BLADE_PASS_GROUP;
    const char* end = text + std::strlen(text);
    std::uint32_t size = 0;
    const auto [last, error] = std::from_chars(text, end, size);
    if (error != std::errc() || last != end || !isBladePassGroupSize(size))
        return makeError("GRASS_COMPUTE_GROUP",
                         "'" + std::string(text) +
                             "' is not a work-group size: use 32, 64, 96, ... or 256 (a multiple "
                             "of 32), or unset it for the default (32)");
    return size;
}

Result<std::uint32_t> bladePassGroupSizeFromEnvironment() {
    return bladePassGroupSize(std::getenv("GRASS_COMPUTE_GROUP"));
}

std::string physicsGroupDefine(std::uint32_t groupSize) {
    GRASS_ASSERT(isBladePassGroupSize(groupSize));
    return "GROUP_SIZE " + std::to_string(groupSize);
}

std::string cullGroupDefine(std::uint32_t groupSize) {
    GRASS_ASSERT(isBladePassGroupSize(groupSize));
    return "GROUP_RUNS " + std::to_string(groupSize / BLADE_PASS_GROUP_STEP);
}

}  // namespace grass::core
