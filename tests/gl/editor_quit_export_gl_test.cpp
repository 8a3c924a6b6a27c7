// Quitting while an export runs (File › Export…, then the window closed): the export asked for
// is finished, whole, with the window off the screen and a line on the terminal saying so.
// Before, the window stood frozen on its last frame until the export's end, without a word.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "editor_runs.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

TEST(EditorQuit, AnExportUnderWayIsFinishedAndSaidBeforeTheEditorEnds) {
    const std::filesystem::path dir = scratchDir("editor_quit_export");
    writeTinyProject(dir, "tiny", 900, 560);
    // Each file the export writes is held 0.6 s before its rename, so the quit comes while
    // the export is under way (core/util/atomic_file.cpp's fault injection).
    ASSERT_EQ(setenv("GRASS_TEST_SAVE_DELAY_MS", "600", 1), 0);
    // A configuration home of its own: File's recent list holds this project alone, so the
    // menu's items stand where the clicks below expect them.
    ASSERT_EQ(setenv("XDG_CONFIG_HOME", (dir / "config").c_str(), 1), 0);
    // File › Export…, then the dialog's Export, and the script ends: the editor quits.
    const std::string log =
        runEditor(dir, "click 22 12\nwait 2\nclick 45 299\nwait 2\nclick 254 337\nwait 2\n", "");
    unsetenv("GRASS_TEST_SAVE_DELAY_MS");
    EXPECT_NE(log.find("finishing the export before quitting"), std::string::npos) << log;
    EXPECT_NE(log.find("exported "), std::string::npos) << log;
    // Whole: the layer's entry point and the buffer it names are in place.
    EXPECT_TRUE(std::filesystem::exists(dir / "export" / "grass.gltf")) << log;
    int buffers = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir / "export"))
        buffers += entry.path().extension() == ".bin" ? 1 : 0;
    EXPECT_EQ(buffers, 1) << log;
}

}  // namespace
}  // namespace grass::test
