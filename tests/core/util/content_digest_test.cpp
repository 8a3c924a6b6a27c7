// The digest the editor's Save compares to tell a project file another program changed
// (util/content_digest.h): one byte more, less or different changes it; the same bytes keep it;
// a file that cannot be read has none; loadProject records the digest of the bytes it read.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "project/project.h"
#include "support/scratch_folder.h"
#include "support/test_paths.h"
#include "util/content_digest.h"

namespace grass::test {
namespace {

TEST(ContentDigest, AnyChangedByteChangesItAndTheSameBytesKeepIt) {
    const std::string text = "{\"name\": \"meadow\"}\n";
    EXPECT_EQ(contentDigest(text), contentDigest(std::string(text)));
    std::string other = text;
    for (std::size_t i = 0; i < text.size(); ++i) {
        other[i] = static_cast<char>(other[i] ^ 1);
        EXPECT_NE(contentDigest(other), contentDigest(text)) << i;
        other[i] = text[i];
    }
    EXPECT_NE(contentDigest(text + " "), contentDigest(text));
    EXPECT_NE(contentDigest(text.substr(1)), contentDigest(text));
    EXPECT_NE(contentDigest(""), contentDigest(std::string(1, '\0')));
}

// FNV-1a 64's published test vectors: the export's content-addressed names and the packing
// cache's keys, which use this digest, stay those already on users' disks.
TEST(ContentDigest, IsFnv1a64AndChainsPieces) {
    EXPECT_EQ(contentDigest(""), 0xcbf29ce484222325ULL);
    EXPECT_EQ(contentDigest("a"), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(contentDigest("foobar"), 0x85944171f73967e8ULL);
    EXPECT_EQ(contentDigest("bar", contentDigest("foo")), contentDigest("foobar"));
}

TEST(ContentDigest, ALoadedProjectRemembersTheBytesItWasReadFrom) {
    const ScratchFolder folder("content-digest");
    const auto file = folder.path() / "project.json";
    auto loaded = core::loadProject(sourceDir() / "tests/data/projects/growth_tiny/project.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    ASSERT_TRUE(core::saveProject(loaded->project, file).ok());
    auto reloaded = core::loadProject(file);
    ASSERT_TRUE(reloaded.ok());
    ASSERT_TRUE(reloaded->fileDigest.has_value());
    EXPECT_EQ(reloaded->fileDigest, fileDigest(file));
    std::ofstream(file, std::ios::app) << "\n";  // a text editor's trailing newline
    EXPECT_NE(reloaded->fileDigest, fileDigest(file));
    EXPECT_FALSE(fileDigest(folder.path() / "gone.json").has_value());
    EXPECT_FALSE(fileDigest(folder.path()).has_value()) << "a folder";
}

}  // namespace
}  // namespace grass::test
