#include "support/test_paths.h"

#include <cstdlib>

namespace grass::test {

namespace {

// <build>/test-tmp (CTest sets GRASS_TEST_TMP), else a folder in the system's temporary folder.
std::filesystem::path scratchRoot() {
    const char* root = std::getenv("GRASS_TEST_TMP");
    return root ? std::filesystem::path(root)
                : std::filesystem::temp_directory_path() / "grass-tests";
}

// No test writes into the configuration or state of the user who runs the suite. The editor
// keeps its recent projects in $XDG_CONFIG_HOME/grass/recent.json, and the tests that run the
// real editor on a project (screenshots, scripts, time) added their folders under
// build/test-tmp to the developer's own File > Open Recent; never-saved projects autosave under
// $XDG_STATE_HOME. Every test process, and every editor it starts, gets folders of its own
// beside the scratch folders (tests/CMakeLists.txt does the same for the command-line tests).
// A test that sets the variables itself still may.
[[maybe_unused]] const bool HOMES_IN_SCRATCH =
    ::setenv("XDG_CONFIG_HOME", (scratchRoot() / "config").c_str(), 1) == 0 &&
    ::setenv("XDG_STATE_HOME", (scratchRoot() / "state").c_str(), 1) == 0;

}  // namespace

std::filesystem::path sourceDir() {
    return GRASS_SOURCE_DIR;
}

std::filesystem::path scratchDir(const std::string& name) {
    const std::filesystem::path dir = scratchRoot() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::filesystem::path sharedDir(const std::string& name) {
    const std::filesystem::path dir = scratchRoot() / name;
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace grass::test
