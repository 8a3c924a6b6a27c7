#include "app/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "util/atomic_file.h"

namespace grass::editor {

namespace fs = std::filesystem;

void RecentFiles::add(const fs::path& projectFile) {
    std::error_code ec;
    fs::path file = fs::absolute(projectFile, ec).lexically_normal();
    if (ec)
        file = projectFile;
    std::erase(projects, file);
    projects.insert(projects.begin(), file);
    if (projects.size() > MAX_RECENT_PROJECTS)
        projects.resize(MAX_RECENT_PROJECTS);
}

std::vector<fs::path> RecentFiles::folders() const {
    std::vector<fs::path> out;
    for (const fs::path& project : projects) {
        const fs::path folder = project.parent_path();
        if (std::find(out.begin(), out.end(), folder) == out.end())
            out.push_back(folder);
    }
    return out;
}

std::string shownFileName(const fs::path& file) {
    return file.filename() == "project.json" ? file.parent_path().filename().string()
                                             : file.filename().string();
}

fs::path recentFilesPath() {
    if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config == '/')
        return fs::path(config) / "grass" / "recent.json";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".config" / "grass" / "recent.json";
    return {};
}

RecentFiles loadRecentFiles(const fs::path& file) {
    RecentFiles recent;
    std::ifstream in(file, std::ios::binary);
    if (file.empty() || !in)
        return recent;
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
    if (!json.is_object() || !json.contains("projects") || !json["projects"].is_array())
        return recent;
    for (const nlohmann::json& entry : json["projects"]) {
        if (!entry.is_string() || recent.projects.size() >= MAX_RECENT_PROJECTS)
            continue;
        const fs::path path(entry.get<std::string>());
        if (path.is_absolute() &&
            std::find(recent.projects.begin(), recent.projects.end(), path) == recent.projects.end())
            recent.projects.push_back(path);
    }
    return recent;
}

Result<void> saveRecentFiles(const RecentFiles& recent, const fs::path& file) {
    if (file.empty())
        return {};
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec)
        return makeError(file.parent_path().string(), "cannot create the folder: " + ec.message());
    nlohmann::json json{{"projects", nlohmann::json::array()}};
    for (const fs::path& project : recent.projects) {
        // JSON text is UTF-8: a path that is not (Linux allows any bytes) is left out rather
        // than written mangled.
        try {
            nlohmann::json entry = project.string();
            (void)entry.dump();
            json["projects"].push_back(std::move(entry));
        } catch (const nlohmann::json::exception&) {
        }
    }
    return writeFileAtomic(file, json.dump(2) + "\n");
}

}  // namespace grass::editor
