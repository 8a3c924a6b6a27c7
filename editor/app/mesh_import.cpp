#include "app/mesh_import.h"

#include <algorithm>
#include <system_error>

#include "app/editor_state.h"
#include "mesh/gltf_loader.h"
#include "mesh/mesh_frame.h"
#include "scene/scene.h"
#include "util/path_inside.h"

namespace grass::editor {

namespace fs = std::filesystem;

namespace {

// A free folder name under meshes/ for `stem`: meshes/rock, meshes/rock-2, ...
std::string freshMeshFolder(const fs::path& projectFolder, const std::string& stem) {
    const std::string base = "meshes/" + core::fileSafeName(stem);
    std::error_code ec;
    for (int n = 1;; ++n) {
        const std::string candidate = n == 1 ? base : base + "-" + std::to_string(n);
        if (!fs::exists(projectFolder / candidate, ec))
            return candidate;
    }
}

}  // namespace

std::vector<fs::path> assetFileSet(const fs::path& file) {
    std::vector<fs::path> files{file.filename()};
    // Empty for a .glb or an unreadable file: nothing else to take along.
    for (const fs::path& part : core::gltfExternalFiles(file)) {
        fs::path relative = part.lexically_relative(file.parent_path());
        if (!relative.empty() && std::find(files.begin(), files.end(), relative) == files.end())
            files.push_back(std::move(relative));
    }
    return files;
}

Result<void> copyAssetFiles(const fs::path& from, const fs::path& to) {
    for (const fs::path& relative : assetFileSet(from)) {
        const fs::path source = from.parent_path() / relative;
        const fs::path target = to.parent_path() / (relative == from.filename() ? to.filename() : relative);
        std::error_code ec;
        if (!fs::exists(source, ec) || fs::exists(target, ec))
            continue;  // a missing part is the loader's to report; a file there is kept
        fs::create_directories(target.parent_path(), ec);
        if (!fs::copy_file(source, target, ec))
            return makeError(target.string(), "cannot copy " + source.string() + " (" + ec.message() + ")");
    }
    return {};
}

Result<core::LoadedProject> newProjectFromMesh(const fs::path& meshFile, std::size_t targetBlades,
                                               core::GltfImport* read, std::stop_token stop) {
    // A new project's mesh is in metres (projectForMesh), the unit its placement is judged in.
    auto imported =
        core::loadGltf(meshFile, core::GltfPlacement::GroundNearOrigin, 1.0, glm::dvec3(0.0), stop);
    if (!imported)
        return imported.error();
    auto loaded = core::projectForMesh(meshFile, imported->mesh, targetBlades);
    if (!loaded)
        return loaded.error();
    loaded->file.clear();  // not saved yet: Save asks where
    if (read)
        *read = std::move(*imported);
    return loaded;
}

void markNewFromMesh(EditorState& state, const fs::path& meshFile) {
    state.doc.dirty = true;
    state.transient.message = "new project from " + meshFile.string() + " (not saved)";
}

Result<core::LoadedProject> projectWithImportedMesh(const core::LoadedProject& loaded,
                                                    const fs::path& meshFile, std::string* note,
                                                    core::GltfImport* read, std::stop_token stop) {
    core::LoadedProject next = loaded;
    core::MeshSource& mesh = next.project.mesh;
    if (!mesh.isFile) {
        mesh.metresPerUnit = 1.0f;
        mesh.up = core::UpAxis::Y;
    }
    // Read as the project will read it (its placement and unit), so the field grows on this
    // reading instead of the file's second one.
    auto imported = core::loadGltf(meshFile, core::GltfPlacement::GroundNearOrigin,
                                   mesh.metresPerUnit, glm::dvec3(0.0), stop);
    if (!imported)
        return imported.error();
    mesh.isFile = true;
    const fs::path absolute = fs::absolute(meshFile).lexically_normal();
    core::Project withoutMesh = loaded.project;
    withoutMesh.mesh = {};
    std::error_code ec;
    if (loaded.file.empty() && core::projectAssetPaths(withoutMesh).empty()) {
        // Nothing of the project lives anywhere yet: it moves to the mesh.
        next.folder = absolute.parent_path();
        mesh.file = absolute.filename().generic_string();
    } else if (!loaded.folder.empty() && isInsideFolder(absolute, loaded.folder)) {
        mesh.file = realPath(absolute).lexically_relative(realPath(loaded.folder)).generic_string();
    } else {
        const std::string folder = freshMeshFolder(loaded.folder, absolute.stem().string());
        mesh.file = folder + "/" + absolute.filename().generic_string();
        if (auto copied = copyAssetFiles(absolute, loaded.folder / mesh.file); !copied)
            return copied.error();
        if (note)
            *note = "copied " + absolute.filename().string() + " into " + (loaded.folder / folder).string();
    }
    if (read)
        *read = std::move(*imported);
    return next;
}

}  // namespace grass::editor
