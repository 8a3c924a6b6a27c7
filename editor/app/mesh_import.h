// Bringing the artist's own glTF mesh into the editor (issue 26): File › New from mesh… (a new
// project around the mesh, sized and framed for it as `grass render --mesh` does), File › Import
// mesh… and a dropped .gltf/.glb (the open project's surface replaced, one undo step). A project
// names its files relative to its folder, so a mesh from elsewhere is copied in, with the
// buffers and images a .gltf names, keeping their layout.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/gltf_loader.h"
#include "project/project.h"
#include "util/result.h"

namespace grass::editor {

struct EditorState;

// Blades a new project from a mesh grows (about the meadow's: interactive on llvmpipe).
inline constexpr std::size_t NEW_MESH_PROJECT_BLADES = 40000;

// `file` and, for a .gltf, the buffers and images it names: paths relative to the file's folder.
std::vector<std::filesystem::path> assetFileSet(const std::filesystem::path& file);

// Copies `from` to `to` with the files it names at the same places relative to it, each
// through a temporary (copyFileAtomic, util/atomic_file.h); files already at the destination are
// kept, and `keptAny` (when given) is set if one was. The error names the file that could not be
// copied.
Result<void> copyAssetFiles(const std::filesystem::path& from, const std::filesystem::path& to,
                            bool* keptAny = nullptr);

// A new, unsaved project around `meshFile` (its folder is the mesh's, so the mesh needs no copy
// until it is saved elsewhere). The error names the file and why it cannot be read. `read`, when
// given, receives the mesh as read, for growField to grow on instead of reading the file again.
// `stop` ends the read early (core::loadGltf's).
Result<core::LoadedProject> newProjectFromMesh(const std::filesystem::path& meshFile,
                                               std::size_t targetBlades = NEW_MESH_PROJECT_BLADES,
                                               core::GltfImport* read = nullptr,
                                               std::stop_token stop = {});
// Once the editor holds that project (File › New from mesh, or `grass-editor rock.glb`): it is
// unsaved, existing only in memory, and the status line says where it came from.
void markNewFromMesh(EditorState& state, const std::filesystem::path& meshFile);

// The open project with `meshFile` as its surface. A mesh inside the project's folder is named
// where it is; one from elsewhere is copied to meshes/<name>/ (a fresh folder each time); a
// project never saved and naming no file takes the mesh's folder as its own instead. The unit
// and up axis of a previous glTF surface are kept (a re-exported model keeps its units).
// `note` says what was copied. The mesh is read first: a broken file copies nothing. `read`,
// when given, receives the mesh as read, for growField to grow on instead of reading it again.
// `stop` ends the read early (core::loadGltf's); nothing is copied then.
Result<core::LoadedProject> projectWithImportedMesh(const core::LoadedProject& loaded,
                                                    const std::filesystem::path& meshFile,
                                                    std::string* note,
                                                    core::GltfImport* read = nullptr,
                                                    std::stop_token stop = {});

// The name the project gives the mesh at `absolute`: where it is, relative to `projectFolder`,
// when it lies inside it; else that of a copy in meshes/<name>/ (a fresh folder each time, the
// files a .gltf names copied along), `note` saying what was copied.
Result<std::string> meshInProject(const std::filesystem::path& projectFolder,
                                  const std::filesystem::path& absolute, std::string* note);

// Colliders › add mesh…: the glTF at `meshFile` becomes a mesh collider of the open project, one
// undo step that grows the field again (its spheres are packed then). Read first, as the
// project will read it: a broken file changes nothing, and the error names it. Copied into the
// project's folder when it lies elsewhere (meshInProject); sized to the scene when its own size
// is far from it; its box centred where a new ball would stand; selected; the status line says
// what was done. A project without a folder yet (never saved) is asked to be saved first.
// The editor runs it in two halves, the reading and copying on a worker (a prop of tens of
// megabytes takes seconds to read): colliderImportRequest and addImportedCollider on the
// window, importColliderMesh between them on the worker. addMeshCollider runs all three.
Result<void> addMeshCollider(EditorState& state, const std::filesystem::path& meshFile);

// What adding a mesh collider needs of the window's state, copied when the file is chosen.
struct ColliderImportRequest {
    std::filesystem::path folder;  // the project's
    core::Project project;         // whose ground's unit and frame the mesh is read in
    std::filesystem::path file;    // absolute
    glm::dvec3 groundOrigin{0.0};
    float sceneDiagonalM = 10.0f;
    glm::vec3 standAt{0.0f};  // where a new ball would stand (newObjectPosition)
};
// The collider ready to be added (named when it is, among the colliders of that moment), what
// was done to bring it in, and its mesh as read (the prop's, so the window reads it no more).
struct ImportedCollider {
    core::ColliderDesc collider;
    std::string note;
    core::MovableSurfaceMesh mesh;
};
// After Import mesh…, which keeps the layers as they were: a note when their tallest blades
// are tall for the new surface (over a tenth of its bounds' diagonal; New from mesh… makes them
// at most 7.8 %), saying how to size them; empty otherwise. The meadow's 0.6 m blades on a
// 3.7 m Suzanne stood out as spikes without a word.
std::string bladeSizeNote(const core::Project& project, float surfaceDiagonalM);

// An error (naming the file) for a project never saved.
Result<ColliderImportRequest> colliderImportRequest(const EditorState& state,
                                                    const std::filesystem::path& meshFile);
// Reads, checks, places and copies the mesh; touches no window state (a worker runs it).
Result<ImportedCollider> importColliderMesh(const ColliderImportRequest& request);
// Adds it to the open project as one undo step, selected; returns the collider's file.
std::string addImportedCollider(EditorState& state, ImportedCollider imported);

}  // namespace grass::editor
