// The editor's panels over the UI library: the menu bar (File: New, Open, Save, Save As, Quit),
// the left side panel (project, layers, wind, colliders, render settings), the status bar under
// the viewport, and the small windows the File menu opens (path entry, quit confirmation).
//
// The side panel's widgets edit a working copy of the project (Transient::draft) and say what the
// edit needs, because edits differ in cost: colours, shapes and render settings are read by the
// renderer every frame and apply at once (the render options are derived from the project each
// frame: viewRenderOptions); scatter, growth, wind and collider edits need the scene re-grown,
// which takes long enough that the Editor does it only once the drag or text entry has ended.
// buildPanels turns the copy's difference into one command (commands.h).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/editor_state.h"
#include "ui/context.h"
#include "ui/ui.h"

namespace grass::editor {

// Builds every panel for this frame (between Context::beginFrame and endFrame) and returns the
// rect left for the 3D viewport, in points.
ui::Rect buildPanels(ui::Context& ctx, EditorState& state);

// Saves to `file` (atomic), updating the state's file, folder and dirty flag; the message says
// what happened. Into another folder, the project's files (core::projectAssetPaths) are copied
// along first. The project's own file, changed on disk by another program since it was opened
// or saved here, is not replaced unless `replaceChangedFile`: the "Changed on disk" window asks
// instead (changedOnDiskWindow).
bool saveTo(EditorState& state, const std::string& file, bool replaceChangedFile = false);
// The window a Save refused for a project file changed on disk opens: replace it, save
// elsewhere, or cancel (panels_changed_on_disk.cpp).
void changedOnDiskWindow(ui::Context& ctx, EditorState& state);
// Asks to quit, start a new project or open another (`openPath`): straight away when nothing is
// unsaved, else through the confirmation window.
void askLeave(EditorState& state, LeaveAction action, const std::string& openPath = {});
void askQuit(EditorState& state);
// Ctrl+S and File › Save: to the project's file, or through the browser when it has none.
void saveOrAsk(EditorState& state);

// The file browser (panels_file_browser.cpp): opened for a purpose at the place it suits (the
// project's folder, its parent for Open, the last mesh's folder for meshes), drawn each frame
// while open; what it chooses goes where the menu item says.
void openBrowser(EditorState& state, BrowsePurpose purpose);

// Where File › Save screenshot, Save turntable and Export… (its default folder, export/) write:
// the project's folder, else (not writable, gone, or a recovered project's autosave slot) the
// working folder, else HOME; a read-only project still gets its pictures and exports.
std::filesystem::path outputFolder(const EditorState& state);
// <outputFolder>/<stem>-<n><extension> with the first n whose file (and turntable frames) do
// not exist yet, so repeated shots never overwrite each other.
std::string freshPicturePath(const EditorState& state, const std::string& stem,
                             const std::string& extension);
void fileBrowserWindow(ui::Context& ctx, EditorState& state);
// Files dropped on the window: a .gltf/.glb is imported as the surface, a picture as the brush's
// map, a project folder or .json opened (asking first when there are unsaved changes); anything
// else is refused in the status bar with what can be dropped. With several, the last of each
// kind wins.
void routeDroppedFiles(EditorState& state, const std::vector<std::string>& paths);
// The message log (panels_messages.cpp): a new status message is appended (at `timeS`, the
// UI's clock); the Messages window shows each whole.
void logMessage(EditorState& state, double timeS);
void messagesWindow(ui::Context& ctx, EditorState& state);
// Puts a project just opened or saved first in File › Open Recent (and its file, when kept).
void rememberRecent(EditorState& state, const std::filesystem::path& projectFile);

// While a document job grows its field (panels_loading.cpp): the panels around `viewport` wait
// under a veil, and a box says what is read or grown, with Cancel.
void loadingWindow(ui::Context& ctx, ui::Rect viewport, EditorState& state);
// Its Cancel (and the window's close button while it runs): the panels are the user's again
// at once, the document as it was; the worker's field is dropped when it is done.
void cancelDocumentJob(EditorState& state);

// File → Export… (panels_export.cpp): the dialog, and the progress window while the job runs.
void exportWindow(ui::Context& ctx, EditorState& state);

// Help › Keyboard shortcuts (panels_help.cpp): the editor's keys, one table.
struct Shortcut {
    std::string_view keys;
    std::string_view what;
};
std::span<const Shortcut> keyboardShortcuts();
void helpMenu(ui::Ui& bar, EditorState& state);
void shortcutsWindow(ui::Context& ctx, EditorState& state);
// Help › About grass: what the window says, line by line (its Copy button copies them).
std::vector<std::string> aboutLines(const EditorState& state);
void aboutWindow(ui::Context& ctx, EditorState& state);
// Starts exporting the live scene with the dialog's choices.
void startExport(EditorState& state);

// The viewport tools' settings (brush, gizmo) (panels_tools.cpp).
void toolSection(ui::Ui& ui, EditorState& state);
// The timeline strip under the viewport (panels_timeline.cpp): transport, typed time and speed,
// and the track with the keys' ticks and the playhead.
inline constexpr float TIMELINE_STRIP_HEIGHT = 56.0f;
// A bar along the viewport's bottom (status bar, timeline strip): filled, a line on top, and
// taking the pointer.
void paintBar(ui::Context& ctx, ui::Rect rect);
void timelineStrip(ui::Context& ctx, ui::Rect rect, EditorState& state);

// The side panel's sections (panels_scene.cpp).
void layerSection(ui::Ui& ui, EditorState& state);
// Where a new wind source, ball or mesh collider stands: above the scene's centre, half its
// height up.
glm::vec3 newObjectPosition(const EditorState& state);
// Add a point wind source or a ball above the scene's centre to the draft and select it (the
// gizmo's and the Wind and Colliders sections' buttons).
void addWindSource(EditorState& state);
void addBallCollider(EditorState& state);
// Removes a wind source or collider from the draft; the selection keeps its object (cleared
// when it was this one, one place down when it came after).
void removeFromDraft(EditorState& state, PlacedObject object);
void windSection(ui::Ui& ui, EditorState& state);
void colliderSection(ui::Ui& ui, EditorState& state);
void renderSection(ui::Ui& ui, EditorState& state);
void lightSection(ui::Ui& ui, EditorState& state);
// What the grass grows on: the glTF file with its unit and up axis, or the procedural shape
// (panels_surface.cpp).
void surfaceSection(ui::Ui& ui, EditorState& state);
void cameraSection(ui::Ui& ui, EditorState& state);
// The Render section's quality preset menu and measured cost/error readout
// (panels_quality.cpp).
void qualityRows(ui::Ui& ui, EditorState& state);
// Snow accumulation (panels_snow.cpp).
void snowSection(ui::Ui& ui, EditorState& state);

// The render options of the viewport: the project's (render::renderOptionsFor) with the view's
// overrides and, while the user interacts, the adaptive quality's reductions (thinning, wider
// blades, fewer segments). One function, so the panels, the keys and undo can never disagree
// with the picture.
render::RenderOptions viewRenderOptions(const EditorState& state);
// The status bar's frame rate: "12 fps", or "at rest" when no frame since the last update drew
// the viewport's picture ("nothing moves" while the timeline plays a still field).
std::string frameRateText(const FrameStatus& status);

}  // namespace grass::editor
