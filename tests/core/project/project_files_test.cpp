// Saved projects keep opening (issue 23 item 9): every project.json committed in projects/ and
// tests/data/projects/ opens with this build, except the fixtures that exist to be refused, each
// listed with the part of the refusal that is its point. A change of the format (a narrowed
// range, a renamed key) that would refuse a saved project fails here first; such a change raises
// PROJECT_FORMAT_VERSION and brings a migration. Each file that opens saves and reopens equal.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "project/project.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

TEST(ProjectFiles, EveryCommittedProjectOpensOrIsARefusalFixture) {
    // Fixtures refused on purpose: folder → what the refusal must say.
    const std::map<std::string, std::string> refused = {
        {"bad_wind", "/wind/0"},
        {"inf_density", "/layers/0/density"},
        {"negative_density", "/layers/0/density"},
        {"unknown_format", "/format"},
        {"unknown_version", "version"},
    };
    std::size_t opened = 0, fixtures = 0;
    for (const char* root : {"projects", "tests/data/projects"})
        for (const auto& entry : fs::directory_iterator(test::sourceDir() / root)) {
            const fs::path file = entry.path() / "project.json";
            if (!fs::exists(file))
                continue;
            const std::string name = entry.path().filename().string();
            std::ifstream in(file);
            std::ostringstream text;
            text << in.rdbuf();
            const auto project = parseProject(text.str(), file.string());
            if (const auto fixture = refused.find(name); fixture != refused.end()) {
                ASSERT_FALSE(project) << name << " is a refusal fixture";
                EXPECT_NE(project.error().str().find(fixture->second), std::string::npos)
                    << name << ": " << project.error().str();
                ++fixtures;
                continue;
            }
            ASSERT_TRUE(project) << "a committed project no longer opens: "
                                 << project.error().str();
            const auto reopened = parseProject(serializeProject(*project), "saved");
            ASSERT_TRUE(reopened) << name << ": " << reopened.error().str();
            EXPECT_EQ(*reopened, *project) << name;
            ++opened;
        }
    EXPECT_EQ(fixtures, refused.size());
    EXPECT_GE(opened, 12u);
}

}  // namespace
}  // namespace grass::core
