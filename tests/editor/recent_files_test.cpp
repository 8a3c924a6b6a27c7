// File › Open Recent's list (issue 26, app/recent_files.h): newest first, each project once, at
// most ten, kept across sessions; a broken file is an empty list, never a refusal to start.
#include "app/recent_files.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/scratch_folder.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;

TEST(RecentFiles, NewestFirstEachOnceAtMostTen) {
    editor::RecentFiles recent;
    for (int i = 0; i < 12; ++i)
        recent.add("/p/project" + std::to_string(i) + "/project.json");
    recent.add("/p/project5/project.json");
    ASSERT_EQ(recent.projects.size(), editor::MAX_RECENT_PROJECTS);
    EXPECT_EQ(recent.projects[0], fs::path("/p/project5/project.json"));
    EXPECT_EQ(recent.projects[1], fs::path("/p/project11/project.json"));
    EXPECT_EQ(std::count(recent.projects.begin(), recent.projects.end(),
                         fs::path("/p/project5/project.json")),
              1);
    EXPECT_EQ(recent.folders()[0], fs::path("/p/project5"));
}

TEST(RecentFiles, SurvivesASaveAndALoad) {
    const ScratchFolder folder("recent-roundtrip");
    editor::RecentFiles recent;
    recent.add("/a/project.json");
    recent.add("/b b/ünïcode/project.json");
    const fs::path file = folder.path() / "config/grass/recent.json";
    ASSERT_TRUE(editor::saveRecentFiles(recent, file).ok());
    EXPECT_EQ(editor::loadRecentFiles(file).projects, recent.projects);
}

TEST(RecentFiles, ABrokenOrMissingFileIsAnEmptyList) {
    const ScratchFolder folder("recent-broken");
    EXPECT_TRUE(editor::loadRecentFiles(folder.path() / "none.json").projects.empty());
    for (const char* text : {"", "{", "[1,2]", R"({"projects": 3})", R"({"projects": [7, "relative"]})"}) {
        std::ofstream(folder.path() / "recent.json", std::ios::trunc) << text;
        EXPECT_TRUE(editor::loadRecentFiles(folder.path() / "recent.json").projects.empty()) << text;
    }
}

TEST(RecentFiles, TheListLivesInTheUsersConfigFolder) {
    const char* saved = std::getenv("XDG_CONFIG_HOME");
    const std::string restore = saved ? saved : "";
    setenv("XDG_CONFIG_HOME", "/cfg", 1);
    EXPECT_EQ(editor::recentFilesPath(), fs::path("/cfg/grass/recent.json"));
    if (saved)
        setenv("XDG_CONFIG_HOME", restore.c_str(), 1);
    else
        unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace grass::test
