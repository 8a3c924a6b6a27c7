// Project files on disk: finding project.json, asset paths relative to its folder, atomic saves.
// The JSON schema itself (both directions) is in project_json.cpp.
#include "project/project.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>
#include <vector>

#include "mesh/gltf_loader.h"
#include "project/json_reader.h"
#include "util/atomic_file.h"
#include "util/content_digest.h"
#include "util/path_inside.h"

namespace grass::core {

namespace fs = std::filesystem;

namespace {

constexpr const char* PROJECT_FILE_NAME = "project.json";

}  // namespace

Result<fs::path> resolveAssetPath(const fs::path& folder, const std::string& relative,
                                  const std::string& fieldPath) {
    if (relative.empty())
        return makeError(fieldPath, "must name a file (got an empty path)");
    if (relative.find('\0') != std::string::npos)
        return makeError(fieldPath, "must not contain a NUL character");
    // A backslash is a file-name character on Linux but a separator on Windows: refuse it so a
    // project means the same file everywhere.
    if (relative.find('\\') != std::string::npos)
        return makeError(fieldPath, "must separate folders with '/', not '\\' (got " +
                                        json::quote(relative) + ")");
    const fs::path path(relative);
    if (path.has_root_path())
        return makeError(fieldPath, "must be relative to the project folder, not absolute (got " +
                                        json::quote(relative) + ")");
    // Lexical first: "a/../b" is "b", "a/../../b" leaves the folder.
    const fs::path normal = path.lexically_normal();
    if (!normal.empty() && *normal.begin() == "..")
        return makeError(fieldPath, "leaves the project folder (got " + json::quote(relative) +
                                        "); assets must sit inside it");
    if (normal.empty() || normal == "." || !normal.has_filename())
        return makeError(fieldPath,
                         "must name a file, not a folder (got " + json::quote(relative) + ")");
    if (folder.empty())
        return normal;
    // A symbolic link inside the project to a file outside it (a system file, another user's
    // data) is refused too: a project reads and writes only under its own folder.
    const fs::path joined = folder / normal;
    if (!isInsideFolder(joined, folder))
        return makeError(fieldPath, json::quote(relative) +
                                        " is a symbolic link (or lies in a linked folder) leading "
                                        "outside the project folder; copy the file into the "
                                        "project instead");
    return joined;
}

namespace {

// "; it holds the mesh ground.glb: …" for a folder without a project that holds a glTF file (the
// first by name, of the folder's first 4096 entries): a mesh given its folder as a project, the
// way to a project around it. Empty otherwise.
std::string meshInFolderHint(const fs::path& folder) {
    std::error_code ec;
    std::vector<fs::path> meshes;
    std::size_t looked = 0;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end && looked < 4096;
         it.increment(ec), ++looked)
        if (isGltfPath(it->path()) && it->is_regular_file(ec))
            meshes.push_back(it->path());
    if (meshes.empty())
        return {};
    const fs::path mesh = *std::min_element(meshes.begin(), meshes.end());
    return "; it holds the mesh " + mesh.filename().string() + ": `grass-editor " + mesh.string() +
           "` makes a project around it, `grass render " + mesh.string() + "` draws a field on it";
}

}  // namespace

Result<LoadedProject> loadProject(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    LoadedProject loaded;
    if (fs::is_directory(status)) {
        loaded.folder = path;
        loaded.file = path / PROJECT_FILE_NAME;
        if (!fs::exists(loaded.file, ec))
            return makeError(path.string(), std::string("this folder has no ") + PROJECT_FILE_NAME +
                                                " (a project folder holds one)" +
                                                meshInFolderHint(path));
    } else if (!fs::exists(status)) {
        return makeError(path.string(), "no such project file or folder");
    } else {
        if (path.extension() != ".json")
            return makeError(path.string(),
                             isGltfPath(path)
                                 ? "is a glTF mesh, not a project: `grass-editor " +
                                       path.filename().string() +
                                       "` makes a project around it (save it, then give its "
                                       "folder), `grass render " +
                                       path.filename().string() + "` draws a field on it"
                                 : std::string("not a project: give a project folder or its .json file"));
        loaded.file = path;
        loaded.folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    }
    auto text = readFile(loaded.file, MAX_JSON_FILE_BYTES);
    if (!text)
        return text.error();
    auto project = parseProject(*text, loaded.file.string());
    if (!project)
        return project.error();
    loaded.project = std::move(*project);
    loaded.fileDigest = contentDigest(*text);
    // A save of this project killed mid-write left its temporary next to the file it was
    // replacing: the next start clears them (the files themselves are whole, old or new).
    removeStaleTemporaries(loaded.folder);
    for (const std::string& asset : projectAssetPaths(loaded.project)) {
        const fs::path folder = (loaded.folder / asset).parent_path();
        if (folder != loaded.folder)
            removeStaleTemporaries(folder);
    }
    return loaded;
}

namespace {

// checkProjectSaves on the project's text, serialized once for the check and the write.
Result<void> checkTextSaves(const std::string& text, const fs::path& file) {
    std::error_code ec;
    if (fs::is_directory(file, ec))
        return makeError(file.string(), std::string("is a folder; save to ") +
                                            (file / PROJECT_FILE_NAME).string());
    if (file.extension() != ".json")
        return makeError(file.string(), "a project file name must end in .json");
    // Never write a file this build would refuse to load.
    if (auto check = parseProject(text, file.string()); !check)
        return makeError(check.error().path, "would not load again: " + check.error().message);
    return {};
}

}  // namespace

Result<void> checkProjectSaves(const Project& project, const fs::path& file) {
    return checkTextSaves(serializeProject(project), file);
}

Result<void> saveProject(const Project& project, const fs::path& file) {
    const std::string text = serializeProject(project);
    if (auto saves = checkTextSaves(text, file); !saves)
        return saves;
    std::error_code ec;
    if (file.has_parent_path()) {
        fs::create_directories(file.parent_path(), ec);
        if (ec)
            return makeError(file.parent_path().string(),
                             "cannot create the folder: " + ec.message());
    }
    return writeFileAtomic(file, text);
}

std::string fileSafeName(const std::string& name) {
    std::string safe;
    for (const char c : name)
        safe += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    return safe.empty() ? "layer" : safe;
}

std::string defaultMapFile(const std::string& layerName, std::string_view mapName) {
    return "maps/" + fileSafeName(layerName) + "-" + std::string(mapName) + ".png";
}

std::vector<std::string> projectAssetPaths(const Project& project) {
    std::vector<std::string> paths;
    const auto add = [&](const std::string& path) {
        if (!path.empty() && std::find(paths.begin(), paths.end(), path) == paths.end())
            paths.push_back(path);
    };
    if (project.mesh.isFile) {
        add(project.mesh.file);
        add(project.mesh.uvAtlas);
    }
    for (const GrassLayer& layer : project.layers) {
        add(layer.densityMap);
        add(layer.soilMap);
        add(layer.lightMap);
        add(layer.cutMap);
    }
    add(project.billboards.texture);
    for (const ColliderDesc& collider : project.colliders)
        if (collider.shape == ColliderShape::Mesh)
            add(collider.file);
    return paths;
}

}  // namespace grass::core
