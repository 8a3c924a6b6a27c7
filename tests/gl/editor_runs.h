// Runs of the real editor under Xvfb for the GL tests: a tiny project to open, and the editor
// driven by a script with its output returned.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "project/project.h"

namespace grass::test {

// A 2 m plane of sparse grass in `folder` (created), named `name`, the window `width` wide;
// `windy`: a breeze keeps its blades moving (without one they settle and stand still).
inline void writeTinyProject(const std::filesystem::path& folder, const std::string& name = "tiny",
                             int width = 480, int height = 320, bool windy = false) {
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "project.json")
        << R"({"format": "grass-project", "version": 2, "name": ")" << name << R"(",
  "mesh": {"procedural": "plane", "size": 2, "resolution": 2},
  "layers": [{"name": "grass", "density": 20}],)"
        << (windy
                ? R"( "wind": [{"name": "breeze", "kind": "directional", "direction": [1, 0, 0.35],
  "strength": 20, "gust": 0.5}],)"
                : "")
        << R"(
  "render": {"width": )"
        << width << ", \"height\": " << height << R"(, "geometry": "strips", "msaa": 0}})";
}

// A ball above a small field, seen from the front: 900 × 560, its marker at (615, 189) and its
// radius about 50 px on screen.
inline void writeBallProject(const std::filesystem::path& dir) {
    std::ofstream(dir / "project.json") << R"({"format": "grass-project", "version": 2,
  "name": "ball", "mesh": {"procedural": "plane", "size": 2, "resolution": 2},
  "layers": [{"name": "grass", "density": 20}],
  "colliders": [{"name": "ball", "shape": "sphere", "position": [0, 0.8, 0], "radius": 0.3}],
  "cameras": [{"name": "main", "position": [0.0, 1.6, 3.2], "target": [0, 0.4, 0]}],
  "render": {"width": 900, "height": 560, "geometry": "strips", "msaa": 0}})";
}

// The colliders of the project `dir` holds (saved by the script's Ctrl+S); none when it cannot
// be read, which fails the test.
inline std::vector<core::ColliderDesc> savedColliders(const std::filesystem::path& dir) {
    auto saved = core::loadProject(dir / "project.json");
    EXPECT_TRUE(saved.ok()) << saved.error().str();
    return saved.ok() ? saved->project.colliders : std::vector<core::ColliderDesc>{};
}

// Runs the editor on `dir` with `script` and `flags` under Xvfb; returns its output. With
// `wallClock` the script runs on wall-clock time (--wall-clock), else it replays frame by frame.
inline std::string runEditor(const std::filesystem::path& dir, const std::string& script,
                             const std::string& flags, bool wallClock = true) {
    std::ofstream(dir / "script.txt") << script;
    const std::string command =
        "xvfb-run -a -s '-screen 0 1024x768x24' " + std::string(GRASS_EDITOR_EXE) + " " +
        dir.string() + " --script " + (dir / "script.txt").string() +
        (wallClock ? " --wall-clock " : " ") + flags + " > " + (dir / "log.txt").string() + " 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command << " (see " << dir / "log.txt"
                                               << ")";
    std::ifstream log(dir / "log.txt");
    std::stringstream text;
    text << log.rdbuf();
    return text.str();
}

}  // namespace grass::test
