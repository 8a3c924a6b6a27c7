#include "support/test_paths.h"

#include <cstdlib>

namespace grass::test {

std::filesystem::path sourceDir() {
    return GRASS_SOURCE_DIR;
}

std::filesystem::path scratchDir(const std::string& name) {
    const char* root = std::getenv("GRASS_TEST_TMP");
    const std::filesystem::path base =
        root ? std::filesystem::path(root) : std::filesystem::temp_directory_path() / "grass-tests";
    const std::filesystem::path dir = base / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace grass::test
