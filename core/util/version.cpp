#include "util/version.h"

// Set for this file alone by core/CMakeLists.txt (a definition on the whole library would
// rebuild all of it at each version change); a build of core from another CMake project (the
// fuzz targets) does not say it.
#ifndef GRASS_VERSION
#define GRASS_VERSION "unknown"
#endif

namespace grass::core {

std::string_view versionText() {
    return GRASS_VERSION;
}

}  // namespace grass::core
