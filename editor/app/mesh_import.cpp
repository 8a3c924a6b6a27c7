#include "app/mesh_import.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "app/commands.h"
#include "app/editor_state.h"
#include "app/panels.h"
#include "mesh/gltf_loader.h"
#include "mesh/mesh_frame.h"
#include "scene/scene.h"
#include "scene/scene_props.h"
#include "util/atomic_file.h"
#include "util/free_name.h"
#include "util/path_inside.h"

namespace grass::editor {

namespace fs = std::filesystem;

namespace {

// Where the part `relative` of the asset `from` (assetFileSet) lies in its copy `to`: the main
// file under the copy's name, the files it names at the same places relative to it.
fs::path copiedPart(const fs::path& from, const fs::path& to, const fs::path& relative) {
    return to.parent_path() / (relative == from.filename() ? to.filename() : relative);
}

// Whether two files hold the same bytes (false when either cannot be read).
bool sameBytes(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::file_size(a, ec) != fs::file_size(b, ec) || ec)
        return false;
    const auto first = readFile(a);
    const auto second = readFile(b);
    return first && second && *first == *second;
}

// Whether `to` is a copy of `from` with every file it names, byte for byte.
bool copiedAlready(const fs::path& from, const fs::path& to) {
    for (const fs::path& relative : assetFileSet(from))
        if (!sameBytes(from.parent_path() / relative, copiedPart(from, to, relative)))
            return false;
    return true;
}

// The folder under meshes/ for a copy of `file` named `stem`: meshes/rock, meshes/rock-2, ...,
// the first that is free, or one that holds a copy of it already (`reused` then says so: the
// same mesh added twice is copied once).
std::string meshFolderFor(const fs::path& projectFolder, const fs::path& file, bool& reused) {
    const std::string base = "meshes/" + core::fileSafeName(file.stem().string());
    std::error_code ec;
    for (int n = 1;; ++n) {
        const std::string candidate = n == 1 ? base : base + "-" + std::to_string(n);
        if (!fs::exists(projectFolder / candidate, ec))
            return candidate;
        if (copiedAlready(file, projectFolder / candidate / file.filename())) {
            reused = true;
            return candidate;
        }
    }
}

// Farther than this from the scene's origin a mesh collider's float positions are coarser
// than a millimetre: one from a georeferenced file the ground does not share the frame of.
constexpr float FAR_COLLIDER_M = 1.0e4f;

std::string formatScale(float scale) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", double(scale));
    return text;
}

}  // namespace

Result<std::string> meshInProject(const fs::path& projectFolder, const fs::path& absolute,
                                  std::string* note) {
    if (!projectFolder.empty() && isInsideFolder(absolute, projectFolder))
        return realPath(absolute).lexically_relative(realPath(projectFolder)).generic_string();
    bool reused = false;
    const std::string folder = meshFolderFor(projectFolder, absolute, reused);
    std::string file = folder + "/" + absolute.filename().generic_string();
    if (!reused) {
        // The folder was free when chosen; a file found there now came in meanwhile, from
        // another import of the same name (the collider's worker and Import mesh… at once). The
        // same bytes serve both; others would make the project name a mesh it did not choose.
        bool keptAny = false;
        if (auto copied = copyAssetFiles(absolute, projectFolder / file, &keptAny); !copied)
            return copied.error();
        if (keptAny && !copiedAlready(absolute, projectFolder / file))
            return makeError(absolute.string(), "another mesh was copied into " +
                                                    (projectFolder / folder).string() +
                                                    " at the same moment: add this one again");
    }
    if (note)
        *note =
            (reused ? "uses its copy in " : "copied " + absolute.filename().string() + " into ") +
            (projectFolder / folder).string();
    return file;
}

Result<ColliderImportRequest> colliderImportRequest(const EditorState& s,
                                                    const fs::path& meshFile) {
    const core::LoadedProject& loaded = s.doc.loaded;
    if (loaded.folder.empty())
        return makeError(meshFile.string(),
                         "save the project first: a collider's mesh is kept "
                         "in the project's folder");
    ColliderImportRequest request;
    request.folder = loaded.folder;
    request.project = loaded.project;
    request.file = fs::absolute(meshFile).lexically_normal();
    request.groundOrigin = s.scene ? s.scene->groundOrigin : glm::dvec3(0.0);
    request.sceneDiagonalM = s.scene ? glm::length(s.scene->bounds.size()) : 10.0f;
    request.standAt = newObjectPosition(s);
    return request;
}

Result<ImportedCollider> importColliderMesh(const ColliderImportRequest& request) {
    const fs::path& absolute = request.file;
    // Read as the project will read it, before anything is copied: a broken file changes
    // nothing.
    auto imported = core::readColliderMesh(request.project, absolute, request.groundOrigin);
    if (!imported)
        return imported.error();
    const core::Bounds bounds = core::meshBounds(imported->mesh);
    const float side = std::max({bounds.size().x, bounds.size().y, bounds.size().z});
    if (!(side > 0.0f) || !std::isfinite(side))
        return makeError(absolute.string(), "the mesh has no extent to collide with");
    // A mesh far out in a georeferenced frame the ground does not share: its 32-bit positions
    // there are too coarse to draw or pack it (0.5 m apart at 5000 km).
    if (const float away = glm::length(bounds.centre()); away > FAR_COLLIDER_M) {
        char reason[200];
        std::snprintf(reason, sizeof reason,
                      "lies %.0f km from the scene's origin, where 32-bit positions are %.2g m "
                      "apart: move it near its file's origin and add it again",
                      double(away) / 1000.0, double(std::nextafter(away, 2.0f * away) - away));
        return makeError(absolute.string(), reason);
    }
    ImportedCollider result;
    core::ColliderDesc& collider = result.collider;
    collider.shape = core::ColliderShape::Mesh;
    // A prop of the scene's scale: its own size when that is between a hundredth and half of
    // the scene (a rock modelled in metres), else a tenth of the scene (a model in centimetres
    // or kilometres), said in the note.
    const float scene = request.sceneDiagonalM;
    std::string scaled;
    if (side > 0.5f * scene || side < 0.01f * scene) {
        collider.scale = 0.1f * scene / side;
        scaled = "scaled by " + formatScale(collider.scale) + " to a tenth of the scene";
    }
    // Its box's centre where a new ball would stand, above the scene's centre.
    collider.position = request.standAt - collider.scale * bounds.centre();
    std::string copied;
    auto file = meshInProject(request.folder, absolute, &copied);
    if (!file)
        return file.error();
    collider.file = std::move(*file);
    for (const std::string& part : {copied, scaled})
        if (!part.empty())
            result.note += (result.note.empty() ? "" : "; ") + part;
    result.mesh = std::move(imported->mesh);
    return result;
}

std::string addImportedCollider(EditorState& s, ImportedCollider imported) {
    core::ColliderDesc& collider = imported.collider;
    const std::string stem = fs::path(collider.file).stem().string();
    collider.name = core::freeName(s.doc.project().colliders, stem.empty() ? "collider" : stem);
    core::Project project = s.doc.project();
    project.colliders.push_back(collider);
    apply(s, EditProject{.after = std::move(project),
                         .effect = EditEffect::Regrow,
                         .label = "add collider " + collider.name});
    s.view.place.selected =
        PlacedObject{PlacedKind::Collider, s.doc.project().colliders.size() - 1};
    s.transient.message = "added collider " + collider.name +
                          (imported.note.empty() ? "" : " (" + imported.note + ")");
    return collider.file;
}

Result<void> addMeshCollider(EditorState& s, const fs::path& meshFile) {
    auto request = colliderImportRequest(s, meshFile);
    if (!request)
        return request.error();
    auto imported = importColliderMesh(*request);
    if (!imported)
        return imported.error();
    addImportedCollider(s, std::move(*imported));
    return {};
}

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

Result<void> copyAssetFiles(const fs::path& from, const fs::path& to, bool* keptAny) {
    for (const fs::path& relative : assetFileSet(from)) {
        const fs::path source = from.parent_path() / relative;
        const fs::path target = copiedPart(from, to, relative);
        std::error_code ec;
        if (!fs::exists(source, ec))
            continue;  // a missing part is the loader's to report
        fs::create_directories(target.parent_path(), ec);
        auto copied = copyFileAtomic(source, target);
        if (!copied)
            return copied.error();
        if (!*copied && keptAny)
            *keptAny = true;  // a file there is kept
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
    // Its notes go with the mesh's, said once the field has grown.
    auto loaded = core::projectForMesh(meshFile, imported->mesh, targetBlades, &imported->notes);
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
    } else {
        auto named = meshInProject(loaded.folder, absolute, note);
        if (!named)
            return named.error();
        mesh.file = std::move(*named);
    }
    if (read)
        *read = std::move(*imported);
    return next;
}

std::string bladeSizeNote(const core::Project& project, float surfaceDiagonalM) {
    float tallest = 0.0f;
    for (const core::GrassLayer& layer : project.layers)
        tallest = std::max(tallest, layer.scatter.blade.heightMax);
    if (!(surfaceDiagonalM > 0.0f) || !(tallest > 0.1f * surfaceDiagonalM))
        return {};
    char note[200];
    std::snprintf(note, sizeof note,
                  "the blades, up to %.3g m, are tall for a surface %.3g m across: lower the "
                  "layers' height, or File > New from mesh… sizes a field to it",
                  static_cast<double>(tallest), static_cast<double>(surfaceDiagonalM));
    return note;
}

}  // namespace grass::editor
