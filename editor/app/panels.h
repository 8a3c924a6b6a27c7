// The editor's panels over the UI library: the menu bar (File: New, Open, Save, Save As, Quit),
// the left side panel (project, layers, wind, colliders, render settings), the status bar under
// the viewport, and the small windows the File menu opens (path entry, quit confirmation).
//
// Panels edit the project in EditorState in place and say what the edit needs, because edits
// differ in cost: colours, shapes and render settings are read by the renderer every frame and
// apply at once (the render options are derived from the project each frame: viewRenderOptions);
// scatter, growth, wind and collider edits need the scene re-grown, which takes long enough that
// main.cpp does it only once the drag or text entry has ended (rebuildPending + no active widget).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "edit/gizmo_drag.h"
#include "edit/history.h"
#include "edit/timeline.h"
#include "app/export_job.h"
#include "app/viewport_tools.h"

#include "project/project.h"
#include "scene/scene.h"
#include "render/scene_renderer.h"
#include "ui/context.h"
#include "ui/ui.h"

namespace grass::editor {

// What the status bar shows, measured by main.cpp.
struct FrameStatus {
    std::size_t blades = 0;  // live blades in the scene
    render::FrameTimings timings;
    double fps = 0.0;
    double uiMs = 0.0;  // CPU time of building and tessellating the UI
};

enum class FileDialog { None, Open, SaveAs };

// What the viewport draws differently from the project, to look at the field: the per-blade
// cull tests switched off (keys 1-4, the Render panel's checkboxes). Never saved, not undone.
struct ViewOverrides {
    bool orientation = true;
    bool frustum = true;
    bool distance = true;  // the project's thinning still decides whether the test exists
    bool occlusion = true;
};

// What replaces the open project, and so asks first when it has unsaved changes.
enum class LeaveAction { Quit, New, Open };

struct EditorState {
    core::LoadedProject loaded;  // file empty: a new project not saved yet
    ViewOverrides view;
    bool softwareRenderer = false;  // picks the geometry path of the project's "auto"
    // What the renderer draws this frame: viewRenderOptions(*this) plus the scene time, set by
    // main.cpp each frame. Derived, never edited: a setting lives in the project alone.
    render::RenderOptions options;
    core::Scene* scene = nullptr;  // the live field the renderer draws (colours, shapes)
    FrameStatus status;

    // Set whenever a panel changes a value; cleared by a save or a load.
    bool dirty = false;
    // Undo and redo. `committed` is the project as of the last history step: once no widget or
    // gizmo drag is active, a project that differs from it becomes one step (so a drag is one
    // step, not one per frame).
    core::EditHistory history;
    core::Project committed;
    // Maps painted since the last save, by layer; saving writes them (edit_actions.h).
    std::set<std::pair<std::size_t, core::LayerMap>> paintedMaps;

    // The viewport's tools and what they work on (main.cpp points `tools` at the live scene's).
    ViewportTool tool = ViewportTool::Camera;
    PaintToolSettings paint;
    PlaceToolSettings place;
    SceneTools* tools = nullptr;
    // A stroke or a gizmo drag is under way (no history step until it ends).
    bool toolDragActive = false;
    std::optional<core::GizmoDrag> gizmoDrag;
    core::Project gizmoStart;  // the project when the drag began
    // Patches re-grown by painting or undo, for main.cpp to upload to the renderer.
    std::vector<std::pair<std::size_t, core::RegrowReport>> regrown;
    // The animation time of wind and colliders: play, pause, step, loop, speed.
    core::Timeline timeline;
    // File → Export…: the dialog's choices and the running (or last) job. While it runs the
    // scene must stay as it is: tools, undo and re-grows wait (busy()).
    bool exportDialog = false;
    std::string exportDir;
    int exportFormat = 0;  // core::ExportFormat
    int exportLod = 0;
    std::shared_ptr<ExportJob> exportJob;
    bool busy() const { return exportJob && !exportJob->done(); }
    // An autosave left by a session that did not close cleanly, offered back at start; main.cpp
    // adopts it when the user picks Recover.
    std::optional<core::LoadedProject> recoveryOffer;
    bool recoverRequested = false;
    // File → Save screenshot: where main.cpp saves the next frame's window (empty: none).
    std::string screenshotRequested;
    // File → Save turntable: the first view's path (main.cpp renders TURNTABLE_VIEWS views).
    std::string turntableRequested;
    // The last scrub, step or play of the timeline panel, for main.cpp (a jump back re-runs the
    // simulation from rest).
    core::TimeUpdate timeJump;
    // The scene must be re-grown from `loaded` once no widget is being dragged.
    bool rebuildPending = false;

    // Requests for main.cpp, which owns the scene and the window.
    bool newRequested = false;
    std::string openRequested;  // a path to load
    bool quitRequested = false;  // the user confirmed (or nothing was unsaved)

    // UI-only state.
    FileDialog fileDialog = FileDialog::None;
    std::string pathText;
    // The "Unsaved changes" window, and what it is about (with the path for Open).
    bool quitDialog = false;
    LeaveAction leaveAction = LeaveAction::Quit;
    std::string leaveOpenPath;
    std::string message;  // last file operation's result, shown in the status bar
    // A failed save stays on screen: routine messages (autosaved) do not replace it until a
    // save succeeds.
    bool messageIsSaveError = false;
};

// Builds every panel for this frame (between Context::beginFrame and endFrame) and returns the
// rect left for the 3D viewport, in points.
ui::Rect buildPanels(ui::Context& ctx, EditorState& state);

// Saves to `file` (atomic), updating the state's file, folder and dirty flag; the message says
// what happened. Into another folder, the project's files (core::projectAssetPaths) are copied
// along first.
bool saveTo(EditorState& state, const std::string& file);
// Asks to quit, start a new project or open another (`openPath`): straight away when nothing is
// unsaved, else through the confirmation window.
void askLeave(EditorState& state, LeaveAction action, const std::string& openPath = {});
void askQuit(EditorState& state);

// File → Export… (panels_export.cpp): the dialog, and the progress window while the job runs.
void exportWindow(ui::Context& ctx, EditorState& state);
// Starts exporting the live scene with the dialog's choices.
void startExport(EditorState& state);

// The viewport tools' settings (brush, gizmo) and the timeline (panels_tools.cpp).
void toolSection(ui::Ui& ui, EditorState& state);
void timelineSection(ui::Ui& ui, EditorState& state);

// The side panel's sections (panels_scene.cpp).
void layerSection(ui::Ui& ui, EditorState& state);
void windSection(ui::Ui& ui, EditorState& state);
void colliderSection(ui::Ui& ui, EditorState& state);
void renderSection(ui::Ui& ui, EditorState& state);
// The Render section's quality preset menu and measured cost/error readout
// (panels_quality.cpp).
void qualityRows(ui::Ui& ui, EditorState& state);
// Snow accumulation (panels_snow.cpp).
void snowSection(ui::Ui& ui, EditorState& state);

// The render options of the viewport: the project's (render::renderOptionsFor) with the view's
// overrides. One function, so the panels, the keys and undo can never disagree with the picture.
render::RenderOptions viewRenderOptions(const EditorState& state);

}  // namespace grass::editor
