// docs/project-format.md says what the reader accepts (issue 23 item 3): each section's table in
// the doc is the one written from the section's table of settings, and the tables themselves
// drive the reader and the writer (each key read, written, refused when out of range).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "project/project.h"
#include "project/setting_docs.h"
#include "project/settings.h"
#include "support/test_paths.h"

namespace grass::core::settings {
namespace {

std::string readDoc() {
    std::ifstream in(test::sourceDir() / "docs" / "project-format.md");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(SettingDocs, EveryTableOfTheDocMatchesItsSettings) {
    const std::string doc = readDoc();
    ASSERT_FALSE(doc.empty());
    for (const DocTable& table : projectFormatTables())
        EXPECT_NE(doc.find(table.markdown), std::string::npos)
            << "docs/project-format.md: the table of \"" << table.section
            << "\" differs from its settings; it should read:\n"
            << table.markdown;
}

TEST(SettingDocs, TheDocListsNoKeyTheSettingsLack) {
    // A row the tables do not write (a removed or renamed key) would survive the test above.
    const std::string doc = readDoc();
    std::size_t rows = 0, documented = 0;
    for (const DocTable& table : projectFormatTables())
        for (std::size_t at = table.markdown.find("\n| `"); at != std::string::npos;
             at = table.markdown.find("\n| `", at + 1))
            ++rows;
    for (std::size_t at = doc.find("## The document"); at != std::string::npos &&
                                                        at < doc.find("## Limits");
         at = doc.find("\n| `", at + 1))
        ++documented;
    EXPECT_EQ(documented - 1, rows);  // the first hit is the heading itself
}

TEST(SettingDocs, KeysAreUniqueWithinEverySection) {
    const auto unique = [](auto table) {
        for (std::size_t i = 0; i < table.size(); ++i)
            for (std::size_t j = i + 1; j < table.size(); ++j)
                if (table[i].key == table[j].key)
                    return false;
        return true;
    };
    EXPECT_TRUE(unique(project()));
    EXPECT_TRUE(unique(layer()));
    EXPECT_TRUE(unique(lighting()));
    EXPECT_TRUE(unique(render()));
    EXPECT_TRUE(unique(snow()));
    EXPECT_TRUE(unique(collider()));
    EXPECT_TRUE(unique(wind()));
}

// A key refused out of range, a value written back: through the table alone.
TEST(SettingDocs, ARowDrivesTheReaderAndTheWriter) {
    Project project;
    project.snow.noiseOctaves = 7;
    const std::string text = serializeProject(project);
    EXPECT_NE(text.find("\"noise_octaves\": 7"), std::string::npos);
    const auto reread = parseProject(text, "p.json");
    ASSERT_TRUE(reread) << reread.error().message;
    EXPECT_EQ(reread->snow.noiseOctaves, 7);

    std::string bad = text;
    bad.replace(bad.find("\"noise_octaves\": 7"), 18, "\"noise_octaves\": 9");
    const auto refused = parseProject(bad, "p.json");
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("/snow/noise_octaves"), std::string::npos);
    EXPECT_NE(refused.error().message.find("1..8"), std::string::npos) << refused.error().message;
}

}  // namespace
}  // namespace grass::core::settings
