// Autosave side-file names (editor/app/autosave.h): every map name maps to one side name and
// back, and names that are not side files are recognised as such. (In grass_gl_tests with the
// editor library; no GL context is used.)
#include <gtest/gtest.h>

#include "app/autosave.h"

namespace grass::test {
namespace {

TEST(Autosave, SideNamesRoundTripAndOnlySideNamesAreRecognised) {
    for (const std::string name :
         {"maps/grass-soil.png", "density.exr", "a/b/c.tif", "maps/x.y.png"}) {
        const std::string side = editor::autosaveMapName(name);
        EXPECT_NE(side, name);
        ASSERT_TRUE(editor::mapNameOfAutosave(side).has_value()) << side;
        EXPECT_EQ(*editor::mapNameOfAutosave(side), name);
        EXPECT_FALSE(editor::mapNameOfAutosave(name).has_value()) << name;
    }
    EXPECT_EQ(editor::autosaveMapName("maps/grass-soil.png"), "maps/grass-soil.autosave.png");
    EXPECT_FALSE(editor::mapNameOfAutosave(".autosave.png").has_value());
}

TEST(Autosave, TheSideProjectSitsNextToTheProjectAndANewProjectHasNone) {
    core::LoadedProject loaded;
    EXPECT_TRUE(editor::autosavePath(loaded).empty());
    loaded.folder = "/p";
    loaded.file = "/p/project.json";
    EXPECT_EQ(editor::autosavePath(loaded), std::filesystem::path("/p/project.autosave.json"));
    EXPECT_FALSE(editor::findAutosave(loaded).has_value());
}

}  // namespace
}  // namespace grass::test
