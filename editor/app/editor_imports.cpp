// The Editor's part of File › New from mesh…, Import mesh… and Import map image… (and of dropped
// files): what needs the live field and the camera. The choice of paths and the copying are
// mesh_import.h's, the map's pixels edit_actions.h's.
#include <filesystem>
#include <utility>

#include "app/edit_actions.h"
#include "app/editor.h"
#include "app/mesh_import.h"

namespace grass::editor {

namespace fs = std::filesystem;

void Editor::applyImports() {
    EditorState& s = mState;
    // An export reads the scene on its worker: replacing it waits.
    if (s.busy())
        return;
    if (!s.newFromMeshRequested.empty()) {
        const fs::path file = std::exchange(s.newFromMeshRequested, {});
        const std::string what = "cannot make a project from " + file.filename().string();
        core::GltfImport read;
        if (auto next = newProjectFromMesh(file, NEW_MESH_PROJECT_BLADES, &read); !next) {
            s.transient.message = what + ": " + next.error().str();
        } else if (adoptDocument(std::move(*next), what, &read)) {
            markNewFromMesh(s, file);
        }
    }
    if (!s.importMeshRequested.empty()) {
        const fs::path file = std::exchange(s.importMeshRequested, {});
        std::string note;
        auto next = projectWithImportedMesh(s.doc.loaded, file, &note);
        // Grown whole before anything changes: a mesh that cannot grow leaves the project as it was.
        auto live = next ? buildLive(
                               *next, !mSettings.noPhysics,
                               [&](core::Scene& grown) {
                                   return carryPaintedMaps(s, *mLive.scene, grown);
                               },
                               mSettings.physicsDevice)
                         : Result<Live>(next.error());
        if (!live) {
            s.transient.message = "cannot import " + file.string() + ": " + live.error().str();
        } else {
            s.doc.loaded.folder = next->folder;
            apply(s, EditProject{.after = std::move(next->project), .label = "import mesh"});
            adoptLive(std::move(*live));
            // Another surface, another place and size: the view moves to it.
            frameLiveSurface();
            s.transient.message = "imported " + file.string() + (note.empty() ? "" : "; " + note);
        }
    }
    if (!s.importMapRequested.empty())
        importMapImage(s, std::exchange(s.importMapRequested, {}));
}

}  // namespace grass::editor
