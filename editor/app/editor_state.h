// What the editor knows, in three parts with different lives (issue 23):
//   Document  — the project, its painted maps, its undo history, whether it is saved and where.
//               Saved, undone, autosaved; changed only by commands (app/commands.h).
//   ViewState — how the user looks at it and works on it: cull-test overrides, the active tool
//               and its settings, the timeline. Never saved, never undone.
//   Transient — the UI's own: dialogs, the status bar's message and figures.
// EditorState holds the three, plus the links to the live field it is drawn from and the
// requests the Editor (editor.h) carries out because it owns the window and the scene.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>
#include <utility>

#include "app/document_job.h"
#include "app/export_job.h"
#include "app/file_browser.h"
#include "app/file_watch_state.h"
#include "app/recent_files.h"
#include "app/viewport_tools.h"
#include "edit/gizmo_drag.h"
#include "edit/history.h"
#include "edit/timeline.h"
#include "project/project.h"
#include "quality/interaction_quality.h"
#include "render/scene_renderer.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace grass::editor {

struct Document {
    core::LoadedProject loaded;  // file empty: a new project not saved yet
    // Set by every command that changes the document; cleared by a save or a load.
    bool dirty = false;
    core::EditHistory history;
    // The project as of the last history step: an edit under way (a drag, a text entry) differs
    // from it until the edit ends and becomes one step.
    core::Project committed;
    // The edit since `committed`: whether it changed the project at all (a drag may end where it
    // began) and whether any part of it re-grows the field (its step's ProjectEdit::regrows).
    bool editChanged = false;
    bool editRegrows = false;
    // Maps painted since the last save, by layer; saving writes them (edit_actions.h).
    std::set<std::pair<std::size_t, core::LayerMap>> paintedMaps;
    // Painted maps waiting, by layer name, for their layer to come (back): those of a removed
    // layer until an undo restores it, and those a duplicate starts from (edit_actions.h).
    std::map<std::pair<std::string, core::LayerMap>, core::MapImage> waitingMaps;
    // A project never saved autosaves into a folder of the user's (autosave.h): its slot there,
    // empty until the first autosave, and the folder whose files were copied into it.
    std::filesystem::path unsavedSlot;
    std::filesystem::path unsavedSlotFrom;

    const core::Project& project() const { return loaded.project; }
};

// What the viewport draws differently from the project, to look at the field: the per-blade
// cull tests switched off (keys 1-4, the Render panel's checkboxes). Never saved, not undone.
struct ViewOverrides {
    bool orientation = true;
    bool frustum = true;
    bool distance = true;  // the project's thinning still decides whether the test exists
    bool occlusion = true;
};

struct ViewState {
    ViewOverrides overrides;
    bool softwareRenderer = false;  // picks the geometry path of the project's "auto"
    // What the renderer draws this frame: viewRenderOptions(state) plus the scene time, set by
    // the Editor each frame. Derived, never edited: a setting lives in the project alone.
    render::RenderOptions options;
    // The viewport's camera as the frame began (the Editor's, copied for the panels), and a view
    // a panel asks for (a camera bookmark), which the Editor takes after the panels.
    core::OrbitCamera camera;
    std::optional<core::OrbitCamera> cameraRequest;
    // The viewport's tools.
    ViewportTool tool = ViewportTool::Camera;
    PaintToolSettings paint;
    PlaceToolSettings place;
    // A stroke or a gizmo drag is under way (its command is one undo step when it ends).
    bool toolDragActive = false;
    std::optional<core::GizmoDrag> gizmoDrag;
    core::Project gizmoStart;  // the project when the drag began
    // The animation time of wind and colliders: play, pause, step, loop, speed.
    core::Timeline timeline;
    // The last scrub, step or play of the timeline panel (a jump back re-runs the simulation
    // from rest).
    core::TimeUpdate timeJump;
    // The surface's unit or up axis changed: once the field is re-grown, the view frames it.
    bool frameSurfacePending = false;
    // A reduced picture while the user interacts (Render panel: "adapt while moving").
    core::InteractionQuality quality;
};

// What the status bar shows, measured by the Editor.
struct FrameStatus {
    std::size_t blades = 0;  // live blades in the scene
    render::FrameTimings timings;
    double fps = 0.0;
    // No frame since the last update drew the viewport's picture (app/view_redraw.h): the window
    // is at rest, and its frame rate (the panels' alone, about ten a second) says nothing.
    bool atRest = false;
    // The timeline plays: at rest then means that nothing in the field moves, which the status
    // bar says rather than a bare "at rest" beside a moving clock.
    bool playing = false;
    double uiMs = 0.0;  // CPU time of building and tessellating the UI
    // Simulated time the live physics could not step in the last second (0: it keeps up).
    double physicsDroppedS = 0.0;
    // Where the live physics runs ("cpu", "gpu"; empty without physics) and, on the
    // CPU, the wall time of the last frame's steps and upload.
    std::string physicsDevice;
    double physicsMs = 0.0;
    // What the viewport lowered this frame to keep its budget (empty: full quality).
    std::string reduced;
    // The renderer's worker places the billboards the technique asked for (not drawn yet).
    bool placingBillboards = false;
};

// What replaces the open project, and so asks first when it has unsaved changes.
enum class LeaveAction { Quit, New, Open, NewFromMesh };

// The side panel's working copy of the project this frame (buildPanels): its widgets edit it in
// place, and its difference from the document becomes one EditProject command.
struct PanelDraft {
    core::Project project;
    bool regrow = false;  // a value the scene is grown from changed
};

inline constexpr std::size_t MAX_LOGGED_MESSAGES = 500;

// A layer's name as typed in its box, taken (or refused) only when the entry ends.
struct LayerNameEntry {
    std::string text;
    bool editing = false;
};

struct Transient {
    FrameStatus status;
    PanelDraft draft;
    std::map<std::size_t, LayerNameEntry> layerNames;  // by layer index
    // The file browser of Open…, Save As…, New from mesh…, Import mesh… (none: closed).
    std::optional<FileBrowser> browser;
    std::filesystem::path meshFolder;  // where the last mesh or map image was picked
    // File › Open Recent; saved to recentFile after each open and save (empty: not kept, as in
    // tests).
    RecentFiles recent;
    std::filesystem::path recentFile;
    // The "Unsaved changes" window, and what it is about (with the path for Open).
    bool quitDialog = false;
    // A Save found the project's file, or a painted map's, changed on disk by another program:
    // the window that asks whether to replace them is open (panels_changed_on_disk.cpp), naming
    // the files ("… was changed by another program …").
    bool changedOnDisk = false;
    std::string changedOnDiskSaid;
    bool changedOnDiskProjectFile = false;  // project.json among them: it can be taken instead
    LeaveAction leaveAction = LeaveAction::Quit;
    std::string leaveOpenPath;
    std::string message;  // last file operation's result, shown in the status bar
    // Every message shown, newest last, with the UI time it appeared (panels_messages.cpp),
    // and the Messages window the status bar's message opens.
    std::vector<std::string> messageLog;
    std::string loggedMessage;
    // The UI time the message was logged: for a few seconds after, the status bar makes room for
    // it before the figures (panels.cpp, statusBar). Clearing loggedMessage says the message
    // anew, for a user action that may repeat its text (a second Ctrl+S, another undo).
    double messageLoggedAtS = -1e9;
    bool messagesWindow = false;
    // The room the status bar's message had when it was pressed (0: not pressed), which it
    // keeps until the release (panels.cpp, statusBar).
    float messagePressedWidth = 0.0f;
    // A failed save stays on screen: routine messages (autosaved) do not replace it until a
    // save succeeds.
    bool messageIsSaveError = false;
    // A message to act on that is not a failed save (the project's file edited elsewhere does
    // not load): drawn in warning orange as long as it is the message shown, like a failed save,
    // without holding off the routine messages after it.
    std::string warningMessage;
    // File → Export…: the dialog's choices.
    bool exportDialog = false;
    bool shortcutsWindow = false;  // Help › Keyboard shortcuts
    bool aboutWindow = false;      // Help › About grass
    std::string exportDir;
    int exportFormat = 0;  // core::ExportFormat
    int exportLod = 0;
};

struct EditorState {
    Document doc;
    ViewState view;
    Transient transient;

    // The OpenGL renderer and version the window draws with ("llvmpipe (LLVM 15.0.6, 256 bits)
    // | 4.5 (Core Profile) Mesa 22.3.6"), for Help › About and bug reports; set by the Editor.
    std::string glRenderer;

    // The live field the document is drawn from (the Editor points these at its own).
    core::Scene* scene = nullptr;  // colours and shapes are read from it every frame
    SceneTools* tools = nullptr;
    // Patches re-grown by painting or undo go straight to whoever draws the field (the Editor
    // uploads them to the renderer and the GPU physics); unset, they are dropped.
    std::function<void(std::size_t layer, const core::RegrowReport&)> regrown;
    // Called by a job's worker when it ends (any thread): wakes the window at rest, so a job
    // that ends while it waits for input is taken in at once (editor/app/idle_wait.h).
    std::function<void()> wakeFrame;
    // Counts the changes to the live field's maps (each re-grow the brush, an import or an undo
    // reports): the map overlay is uploaded again when it moves.
    std::uint64_t mapsChanged = 0;
    // The scene must be re-grown from the document once no widget is being dragged.
    bool rebuildPending = false;
    // The field's files (a map, the surface) were changed on disk: it grows again from them,
    // whatever the project says (project_file_watch.h); with the surface's file, the re-grow
    // reads it again instead of growing on the mesh at hand.
    bool regrowFromDisk = false;
    bool surfaceChangedOnDisk = false;
    // Mesh colliders' files changed on disk (as the project names them), when nothing else the
    // field grows from changed: they are packed again and their props made again while the
    // field keeps its blades and their motion, and where a layer clears the ground under the
    // colliders the patches around them grow again (Editor::followMotionEdits,
    // LiveMotion::changedFiles).
    std::set<std::string> colliderFilesChangedOnDisk;
    // A Save wrote the project's files here: the watch of them takes their new times as its own.
    bool assetsWrittenHere = false;
    // The project's files as the editor last looked at them (project_file_watch.h; the Editor
    // looks every second).
    ProjectFileWatch fileWatch;

    // The running (or last) export. While it runs the scene must stay as it is: tools, undo and
    // re-grows wait (busy()).
    std::shared_ptr<ExportJob> exportJob;
    // The New, Open, New from mesh, Import mesh or Recover whose field grows on a worker
    // (document_job.h). Meanwhile the document stays as it is: the panels and the editing keys
    // wait, and so do tools, undo, re-grows, autosaves and further requests (busy()).
    std::unique_ptr<DocumentJob> documentJob;
    // Jobs the user cancelled: left to finish on their own, their fields dropped.
    std::vector<std::unique_ptr<DocumentJob>> cancelledJobs;
    bool loading() const { return documentJob != nullptr; }
    bool busy() const { return (exportJob && !exportJob->done()) || loading(); }
    // The field grown again after an edit of the layers, on a worker (seconds for a large mesh):
    // the window goes on with the field before the edit, and painting and undo go on too (the
    // maps painted meanwhile are carried over when the new field comes in). What would replace
    // or read the live field elsewhere waits for it (New, Open, the imports, an export).
    std::unique_ptr<DocumentJob> regrowJob;
    // A re-grow stopped by a later edit (Editor::applyRequests), ending at its next stage beside
    // the later one; it may still read the live field meanwhile.
    std::unique_ptr<DocumentJob> stoppingRegrow;
    bool regrowing() const { return regrowJob != nullptr || stoppingRegrow != nullptr; }
    // File › Export… asked for while the field grows again: it starts once the new field is in.
    bool exportWhenGrown = false;
    // An autosave left by a session that did not close cleanly, offered back at start; the
    // Editor adopts it when the user picks Recover.
    std::optional<core::LoadedProject> recoveryOffer;
    // Whether never-saved projects' autosaves (the user's unsaved folder) are offered: not to a
    // replayed script, whose run must not depend on what the user left there.
    bool offersUnsavedAutosaves = true;

    // Requests for the Editor, which owns the scene and the window.
    bool recoverRequested = false;
    std::string screenshotRequested;  // File → Save screenshot: the next frame's window
    std::string turntableRequested;   // File → Save turntable: the first view's path
    bool newRequested = false;
    std::string openRequested;  // a path to load
    // File › New from mesh…, File › Import mesh… or a dropped .gltf/.glb, and a map image for
    // the paint tool's layer and map (File › Import map image… or a dropped image): paths.
    std::string newFromMeshRequested;
    std::string importMeshRequested;
    std::string importMapRequested;
    // Colliders › add mesh…: the glTF chosen, read and copied into the project on a worker
    // (Editor::collectColliderImport adds it).
    std::string addColliderRequested;
    bool quitRequested = false;  // the user confirmed (or nothing was unsaved)
};

}  // namespace grass::editor
