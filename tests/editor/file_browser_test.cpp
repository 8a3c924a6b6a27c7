// The file browser's model (issue 26, app/file_browser.h): what a folder lists through each
// purpose's filter, where a double-click or a typed path leads, and why a choice is refused.
#include "app/file_browser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include "support/scratch_folder.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;
using editor::BrowsePurpose;
using editor::FileBrowser;

// A folder as an artist's might be: meshes of both kinds in any case, pictures, a project
// folder, a plain folder, a hidden file.
void makeFolder(const fs::path& root) {
    for (const char* name : {"Terrain.GLB", "rock.gltf", "rock.bin", "notes.txt", "moss.png",
                             "soil.TGA", "icon.ico", ".hidden.glb"})
        std::ofstream(root / name) << "x";
    fs::create_directories(root / "meadow");
    std::ofstream(root / "meadow/project.json") << "{}";
    fs::create_directories(root / "Assets");
}

std::vector<std::string> names(const editor::FolderListing& listing) {
    std::vector<std::string> out;
    for (const auto& entry : listing.entries)
        out.push_back(entry.name);
    return out;
}

TEST(FileBrowser, ListsFoldersFirstThenTheFilesThePurposeTakesInAnyCase) {
    const ScratchFolder folder("browser-list");
    makeFolder(folder.path());
    const auto meshes = editor::listFolder(folder.path(), editor::browseExtensions(BrowsePurpose::ImportMesh));
    EXPECT_EQ(names(meshes), (std::vector<std::string>{"Assets", "meadow", "rock.gltf", "Terrain.GLB"}));
    EXPECT_TRUE(meshes.entries[1].isProject);
    EXPECT_FALSE(meshes.entries[0].isProject);
    EXPECT_EQ(meshes.entries[2].bytes, 1u);
    const auto images = editor::listFolder(folder.path(), editor::browseExtensions(BrowsePurpose::ImportMap));
    EXPECT_EQ(names(images), (std::vector<std::string>{"Assets", "meadow", "moss.png", "soil.TGA"}));
}

TEST(FileBrowser, AnUnreadableFolderSaysSoInsteadOfThrowing) {
    const auto listing = editor::listFolder("/no/such/folder", {".glb"});
    EXPECT_TRUE(listing.entries.empty());
    EXPECT_NE(listing.error.find("/no/such/folder"), std::string::npos) << listing.error;
}

TEST(FileBrowser, DoubleClickEntersAFolderAndChoosesAFile) {
    const ScratchFolder folder("browser-activate");
    makeFolder(folder.path());
    FileBrowser browser(BrowsePurpose::ImportMesh, folder.path());
    // "meadow" is a project, but importing a mesh browses into it.
    ASSERT_FALSE(browser.activate(1).has_value());
    EXPECT_EQ(browser.folder(), folder.path() / "meadow");
    browser.up();
    EXPECT_EQ(browser.folder(), folder.path());
    browser.select(3);
    EXPECT_EQ(browser.typed(), "Terrain.GLB");  // a click puts the file's name in the path field
    const auto chosen = browser.activate(3);
    ASSERT_TRUE(chosen.has_value());
    EXPECT_EQ(*chosen, folder.path() / "Terrain.GLB");
}

TEST(FileBrowser, OpeningAProjectFolderChoosesItRatherThanBrowsingIt) {
    const ScratchFolder folder("browser-open");
    makeFolder(folder.path());
    FileBrowser browser(BrowsePurpose::OpenProject, folder.path());
    ASSERT_EQ(browser.listing().entries[1].name, "meadow");
    const auto chosen = browser.activate(1);
    ASSERT_TRUE(chosen.has_value());
    EXPECT_EQ(*chosen, folder.path() / "meadow");
    // A plain folder is entered; with nothing typed, Open there is refused with the reason.
    EXPECT_FALSE(browser.activate(0).has_value());
    EXPECT_FALSE(browser.activateTyped().has_value());
    EXPECT_NE(browser.message().find("project.json"), std::string::npos) << browser.message();
}

TEST(FileBrowser, ATypedPathIsRelativeToTheFolderOrAbsoluteOrFromHome) {
    const ScratchFolder folder("browser-typed");
    makeFolder(folder.path());
    FileBrowser browser(BrowsePurpose::ImportMesh, folder.path() / "Assets");
    browser.typed() = "../rock.gltf";
    EXPECT_EQ(browser.activateTyped(), std::optional<fs::path>(folder.path() / "rock.gltf"));
    browser.typed() = (folder.path() / "meadow").string();  // a folder: the browser goes there
    EXPECT_FALSE(browser.activateTyped().has_value());
    EXPECT_EQ(browser.folder(), folder.path() / "meadow");
    EXPECT_TRUE(browser.typed().empty());
    const char* home = std::getenv("HOME");
    ASSERT_NE(home, nullptr);
    EXPECT_EQ(editor::resolveTypedPath("/x", "~/a.glb"), (fs::path(home) / "a.glb").lexically_normal());
    EXPECT_EQ(editor::resolveTypedPath("/x/y", "a.glb"), fs::path("/x/y/a.glb"));
}

TEST(FileBrowser, AWrongKindOrAMissingFileIsRefusedWithTheReason) {
    const ScratchFolder folder("browser-refuse");
    makeFolder(folder.path());
    FileBrowser browser(BrowsePurpose::ImportMesh, folder.path());
    browser.typed() = "notes.txt";
    EXPECT_FALSE(browser.activateTyped().has_value());
    EXPECT_NE(browser.message().find("glTF (.gltf .glb)"), std::string::npos) << browser.message();
    browser.typed() = "gone.glb";
    EXPECT_FALSE(browser.activateTyped().has_value());
    EXPECT_NE(browser.message().find("does not exist"), std::string::npos) << browser.message();
    // Saving takes a new name: a project folder that does not exist yet.
    FileBrowser save(BrowsePurpose::SaveProject, folder.path());
    save.typed() = "new-field";
    EXPECT_EQ(save.activateTyped(), std::optional<fs::path>(folder.path() / "new-field"));
}

// Save As onto another project would overwrite its project.json (and leave this project naming
// that folder's files where names collide): the first choice says so, the same choice again
// confirms. The open project's own file is saved over without asking (Save As where it is).
TEST(FileBrowser, SavingOverAnotherProjectAsksFirst) {
    const ScratchFolder folder("browser-replace");
    makeFolder(folder.path());  // meadow/ holds a project.json
    FileBrowser save(BrowsePurpose::SaveProject, folder.path());
    save.typed() = "meadow";
    EXPECT_FALSE(save.activateTyped().has_value());
    EXPECT_NE(save.message().find("meadow/project.json is another project"), std::string::npos)
        << save.message();
    EXPECT_EQ(save.activateTyped(), std::optional<fs::path>(folder.path() / "meadow"))
        << "chosen again: replace it";
    // Browsed into (a double-click enters a folder) and saved with nothing typed: the same.
    FileBrowser entered(BrowsePurpose::SaveProject, folder.path());
    const auto& entries = entered.listing().entries;
    const auto meadow = std::find_if(entries.begin(), entries.end(),
                                     [](const auto& entry) { return entry.name == "meadow"; });
    ASSERT_NE(meadow, entries.end());
    EXPECT_FALSE(entered.activate(static_cast<std::size_t>(meadow - entries.begin())));
    ASSERT_EQ(entered.folder(), folder.path() / "meadow");
    EXPECT_FALSE(entered.activateTyped().has_value());
    EXPECT_NE(entered.message().find("is another project"), std::string::npos);
    EXPECT_EQ(entered.activateTyped(), std::optional<fs::path>(folder.path() / "meadow"));
    // The open project's own folder: no question.
    FileBrowser own(BrowsePurpose::SaveProject, folder.path());
    own.setOwnProject(folder.path() / "meadow/project.json");
    own.typed() = "meadow";
    EXPECT_EQ(own.activateTyped(), std::optional<fs::path>(folder.path() / "meadow"));
    EXPECT_TRUE(own.message().empty()) << own.message();
}

// A painted map exported onto a picture already there (the artist's own texture, perhaps):
// asked first, like Save As onto another project; a new name is taken at once.
TEST(FileBrowser, ExportingAMapOverAnExistingPictureAsksFirst) {
    const ScratchFolder folder("browser-export-map");
    makeFolder(folder.path());  // moss.png exists
    FileBrowser exporting(BrowsePurpose::ExportMap, folder.path());
    exporting.typed() = "moss.png";
    EXPECT_FALSE(exporting.activateTyped().has_value());
    EXPECT_NE(exporting.message().find("moss.png already exists"), std::string::npos)
        << exporting.message();
    EXPECT_EQ(exporting.activateTyped(), std::optional<fs::path>(folder.path() / "moss.png"));
    exporting.typed() = "grass-density.png";
    EXPECT_EQ(exporting.activateTyped(),
              std::optional<fs::path>(folder.path() / "grass-density.png"));
}

TEST(FileBrowser, StartsAtTheNearestFolderThatExists) {
    const ScratchFolder folder("browser-start");
    const FileBrowser browser(BrowsePurpose::OpenProject, folder.path() / "moved/away/project");
    EXPECT_EQ(browser.folder(), folder.path());
}

}  // namespace
}  // namespace grass::test
