// The Editor's part of File › New from mesh…, Import mesh… and Import map image… (and of dropped
// files): what needs the live field and the camera. The choice of paths and the copying are
// mesh_import.h's, the map's pixels edit_actions.h's.
#include <cstdio>
#include <filesystem>
#include <utility>

#include "app/edit_actions.h"
#include "app/editor.h"
#include "app/mesh_import.h"

namespace grass::editor {

namespace fs = std::filesystem;

void Editor::applyImports() {
    EditorState& s = mState;
    // An export reads the scene on its worker, a load or a re-grow replaces it: imports wait
    // for them.
    if (s.busy() || s.regrowing())
        return;
    if (!s.newFromMeshRequested.empty()) {
        const fs::path file = std::exchange(s.newFromMeshRequested, {});
        startDocumentJob(DocumentAction::NewFromMesh, file,
                         [file](OptionalMesh& read, std::string&, std::stop_token stop) {
                             return newProjectFromMesh(file, NEW_MESH_PROJECT_BLADES,
                                                       &read.emplace(), stop);
                         });
        return;
    }
    if (!s.importMeshRequested.empty()) {
        const fs::path file = std::exchange(s.importMeshRequested, {});
        // The worker reads and grows from a copy of the project: the document waits meanwhile.
        startDocumentJob(DocumentAction::ImportMesh, file,
                         [file, loaded = s.doc.loaded](OptionalMesh& read, std::string& note,
                                                       std::stop_token stop) {
                             return projectWithImportedMesh(loaded, file, &note, &read.emplace(),
                                                            stop);
                         });
        return;
    }
    if (!s.importMapRequested.empty())
        importMapImage(s, std::exchange(s.importMapRequested, {}));
    if (!s.addColliderRequested.empty())
        startColliderImport();
}

void Editor::startColliderImport() {
    EditorState& s = mState;
    if (mColliderImport) {
        s.transient.message =
            "not taken: " + s.addColliderRequested +
            " (the last mesh chosen is still being read: add it once that one is in)";
        s.addColliderRequested.clear();
        return;
    }
    const fs::path file = std::exchange(s.addColliderRequested, {});
    auto request = colliderImportRequest(s, file);
    if (!request) {
        s.transient.message = "cannot add a collider: " + request.error().str();
        return;
    }
    mColliderImportFolder = request->folder;
    mColliderImport = std::make_unique<WorkerJob<Result<ImportedCollider>>>(
        [request = std::move(*request)] { return importColliderMesh(request); }, s.wakeFrame);
    s.transient.message = "reading " + file.filename().string() + " …";
    if (mReplay)  // scripts and screenshots: added in this frame, whatever the machine's speed
        collectColliderImport();
}

void Editor::collectColliderImport() {
    if (!mColliderImport || (!mColliderImport->done() && !mReplay))
        return;
    auto imported = std::exchange(mColliderImport, nullptr)->take();
    EditorState& s = mState;
    if (!imported) {
        s.transient.message = "cannot add a collider: " + imported.error().str();
        return;
    }
    // Another project opened meanwhile: the copy is in the folder it was meant for, unused.
    if (s.doc.loaded.folder != mColliderImportFolder) {
        s.transient.message = "not added: " + imported->collider.file + " belongs to " +
                              mColliderImportFolder.string();
        return;
    }
    core::MovableSurfaceMesh mesh = std::move(imported->mesh);
    const std::string file = addImportedCollider(s, std::move(*imported));
    mLive.motion.readAheadProps.insert_or_assign(file, std::move(mesh));
}

void Editor::adoptImportedMesh(GrownDocument imported, const fs::path& file) {
    EditorState& s = mState;
    const core::LoadedProject next = imported.field.loaded;
    // Brought up whole before anything changes: a mesh that cannot grow leaves the project as it
    // was. The maps painted on the old surface go on to the new one.
    auto live = bringUpLive(
        std::move(imported.field),
        [&](core::Scene& grown) { return carryPaintedMaps(s, *mLive.scene, grown); },
        mSettings.physicsDevice);
    if (!live) {
        s.transient.message = "cannot import " + file.string() + ": " + live.error().str();
        return;
    }
    s.doc.loaded.folder = next.folder;
    apply(s,
          EditProject{.after = next.project, .effect = EditEffect::Grown, .label = "import mesh"});
    adoptLive(std::move(*live));
    // Another surface, another place and size: the view moves to it.
    frameLiveSurface();
    // Blades tall for the new surface are said before what was copied, which the status line
    // would cut first, and on the terminal.
    const std::string size =
        bladeSizeNote(s.doc.project(), glm::length(mLive.scene->bounds.size()));
    if (!size.empty())
        std::fprintf(stderr, "grass-editor: %s: %s\n", file.filename().string().c_str(),
                     size.c_str());
    s.transient.message = "imported " + file.string() + (size.empty() ? "" : "; " + size) +
                          (imported.note.empty() ? "" : "; " + imported.note);
}

}  // namespace grass::editor
