// Content-addressed export files (issue 11: an export is atomic as a set): the naming rule and
// the clean-up of files no entry point names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "export/content_names.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
    std::ofstream(file) << text;
}

std::set<std::string> filesIn(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.insert(entry.path().filename().string());
    return names;
}

TEST(ContentNames, NameCarriesSixteenHexDigitsOfTheHash) {
    EXPECT_EQ(contentAddressedName("grass", 0xabcull, ".bin"), "grass-0000000000000abc.bin");
    EXPECT_EQ(contentAddressedName("grass.blades", contentHash("x"), ".bin").size(),
              std::string("grass.blades-").size() + 16 + 4);
    // One changed byte changes the name; equal bytes keep it.
    EXPECT_NE(contentHash("blade data 1"), contentHash("blade data 2"));
    EXPECT_EQ(contentHash("blade data 1"), contentHash("blade data 1"));
    // Chaining is hashing the concatenation.
    EXPECT_EQ(contentHash("world", contentHash("hello ")), contentHash("hello world"));
}

TEST(ContentNames, RecognisesOnlyItsOwnForm) {
    for (const char* ours : {"grass-0123456789abcdef.bin", "grass-density-0123456789abcdef.png",
                             "grass.blades-0123456789abcdef.bin", "a-b-0000000000000000.x.y"})
        EXPECT_TRUE(isContentAddressedName(ours)) << ours;
    for (const char* theirs :
         {"grass.bin", "grass.gltf", "manifest.json", "grass-0123456789ABCDEF.bin",
          "grass-0123456789abcde.bin", "grass-0123456789abcdef0.bin",
          "grass-0123456789abcdef.", "-0123456789abcdef.bin", "notes-0123456789abcdefg.txt"})
        EXPECT_FALSE(isContentAddressedName(theirs)) << theirs;
}

TEST(ContentNames, CleanUpRemovesWhatNoEntryPointNamesAndNothingElse) {
    const fs::path dir = test::scratchDir("content-names-cleanup");
    const std::string named = "grass-1111111111111111.bin";
    const std::string namedMap = "grass-density-2222222222222222.png";
    const std::string rawNamed = "meadow.blades-3333333333333333.bin";
    const std::string stale = "grass-4444444444444444.bin";
    const std::string staleMap = "grass-density-5555555555555555.png";
    write(dir / "grass.gltf", R"({"buffers": [{"uri": ")" + named +
                                  R"(", "byteLength": 4}], "images": [{"uri": ")" + namedMap +
                                  R"("}]})");
    write(dir / "manifest.json", R"({"layers": [{"blades": {"file": ")" + rawNamed + R"("}}]})");
    for (const std::string& file : {named, namedMap, rawNamed, stale, staleMap})
        write(dir / file, "data");
    write(dir / "readme.txt", "the user's own file");
    write(dir / "grass.bin", "an export of an older version, not content-addressed");

    EXPECT_EQ(removeUnreferencedExportFiles(dir), 2u);
    EXPECT_EQ(filesIn(dir), (std::set<std::string>{"grass.gltf", "manifest.json", named, namedMap,
                                                   rawNamed, "readme.txt", "grass.bin"}));
}

TEST(ContentNames, AnEntryPointThatDoesNotParseStopsTheCleanUp) {
    const fs::path dir = test::scratchDir("content-names-broken");
    write(dir / "grass.gltf", R"({"buffers": [{"uri": "grass-1111)");
    write(dir / "grass-1111111111111111.bin", "data");
    EXPECT_EQ(removeUnreferencedExportFiles(dir), 0u);
    EXPECT_TRUE(fs::exists(dir / "grass-1111111111111111.bin"));
}

// Issue 22: a .gltf nested 50,000 levels deep in the export folder overflowed the stack of the
// clean-up's recursive walk (SIGSEGV). Now it is refused before it is parsed, and, unreadable,
// stops the clean-up like any entry point that does not parse.
TEST(ContentNames, DeeplyNestedGltfStopsTheCleanUp) {
    const fs::path dir = test::scratchDir("content-names-deep");
    write(dir / "deep.gltf", "{\"uri\":" + std::string(50000, '[') + "1" + std::string(50000, ']') +
                                 "}");
    write(dir / "grass-1111111111111111.bin", "data");
    EXPECT_EQ(removeUnreferencedExportFiles(dir), 0u);
    EXPECT_TRUE(fs::exists(dir / "grass-1111111111111111.bin"));
}

}  // namespace
}  // namespace grass::core
