// File › Open Recent and the browser's recent places (issue 26): the projects the user opened or
// saved last, newest first, kept across sessions in the user's configuration folder
// ($XDG_CONFIG_HOME/grass/recent.json, else ~/.config/grass/recent.json). A missing or broken
// file is an empty list (it is a convenience, never a reason to refuse to start); writes are
// atomic.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::editor {

inline constexpr std::size_t MAX_RECENT_PROJECTS = 10;

struct RecentFiles {
    std::vector<std::filesystem::path> projects;  // project files, newest first

    // Puts `projectFile` first (absolute), once, keeping at most MAX_RECENT_PROJECTS.
    void add(const std::filesystem::path& projectFile);
    // The folders of the projects, each once, for the browser's places.
    std::vector<std::filesystem::path> folders() const;
};

// How a project or mesh file the user picked is named to them: "meadow" for
// projects/meadow/project.json, "rock.glb" for a mesh (Open Recent, the loading box).
std::string shownFileName(const std::filesystem::path& file);

// Where the list lives; empty when neither XDG_CONFIG_HOME nor HOME is set.
std::filesystem::path recentFilesPath();

RecentFiles loadRecentFiles(const std::filesystem::path& file);
Result<void> saveRecentFiles(const RecentFiles& recent, const std::filesystem::path& file);

}  // namespace grass::editor
