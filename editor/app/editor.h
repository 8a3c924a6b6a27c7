// The editor window's session (issue 23): the document and its live field, the view, the UI, and
// what one frame does to them. main.cpp is the table of contents (arguments, one Editor, the
// loop); this is the chapter. A frame, in order:
//   input (the window's, or the replayed script's)
//   → UI (panels first: they decide who gets the pointer and the keys)
//   → viewport tools and camera → keys (render keys, tool keys, undo, save)
//   → settle (an edit that has just ended becomes one undo step, editor/app/commands.h)
//   → requests (New, Open, Recover replace the document whole, editor/app/document.h;
//     a pending re-grow; re-grown patches up to the GPU)
//   → autosave → time and physics → render → outputs (screenshots, turntable) → status.
// Edits of the document come from the panels, the tools and the keys as commands, applied in one
// place (commands.h); the render settings are derived from the document (viewRenderOptions).
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/collider_packing_job.h"
#include "app/document_job.h"
#include "app/editor_keys.h"
#include "app/editor_ui.h"
#include "app/idle_wait.h"
#include "app/input_script.h"
#include "app/live_scene.h"
#include "app/mesh_import.h"
#include "app/panels.h"
#include "app/project_file_watch.h"
#include "app/session_stats.h"
#include "app/view_redraw.h"
#include "app/window.h"
#include "app/worker_job.h"
#include "gl/framebuffer.h"
#include "scene/camera.h"
#include "util/result.h"

namespace grass::editor {

// What the command line chose (grass-editor --help says each).
struct EditorSettings {
    std::string projectPath;
    std::string screenshot;  // save the window after `frames` frames, then stop
    int frames = 0;
    std::string scriptFile;  // replay recorded input, then stop
    double autosaveS = 180.0;
    bool recover = false;
    bool glDebug = false;
    bool noPhysics = false;
    // Where the live physics runs (live_scene.h): auto picks the CPU on software GL.
    PhysicsDevice physicsDevice = PhysicsDevice::Auto;
    bool noUi = false;
    // Tests of time: a script on wall-clock time (not one physics step per frame), and a
    // delay added to every frame to stand for a slow machine.
    bool wallClock = false;
    int frameDelayMs = 0;
    // Tests of a slow load: a delay before every New, Open, import, recovery or re-grow grows
    // its field (the first project's too), standing for a large file (document_job.h).
    int loadDelayMs = 0;
    // The viewport's adaptive quality (core/quality/interaction_quality.h).
    bool adaptive = true;
    double frameBudgetMs = 80.0;
    // Draw the viewport's picture every frame, even when it would be the last one again
    // (app/view_redraw.h): for tests that compare the two.
    bool redrawEveryFrame = false;
};

// The viewport rect (points, y down) in GL pixels (y up), at least one pixel.
struct PixelRect {
    int x = 0, y = 0, w = 1, h = 1;
};

class Editor {
public:
    // Opens the window on the project, grows its field and, unless --no-ui, builds the UI. No
    // editor (and no error) when the user closed the window before the field was grown.
    static Result<std::unique_ptr<Editor>> open(EditorSettings settings);
    // Runs one frame; false once the session is over (quit, the script's end, the screenshot
    // saved). An error (a script's screenshot that cannot be written) ends it too.
    Result<bool> frame();
    // After SIGINT or SIGTERM (main.cpp): a load stops, the unsaved changes go into the autosave
    // (offered back at the next start), and what became of them is said on stderr; the caller
    // then ends the process without asking.
    void endInterrupted(int signal);
    // A re-grow still running reads the live field's mesh: it is waited for before that goes.
    ~Editor();

private:
    Editor() = default;
    using Clock = std::chrono::steady_clock;

    // The window's close button: true when the session ends here (else it asks first).
    bool closeRequested();
    // Panels, overlay and the viewport's tools and camera; the keys unless the UI took them.
    void runInput(InputState input, int width, int height);
    // The frame's keys not applied before one of its presses (`taken`, editor_keys.h).
    void applyKeys(const InputState& input, KeysTaken taken);
    // A key's change, for the console (nothing when empty).
    static void logKeyChange(const std::string& changed);
    // New, Open, Recover and re-grows; true when the user quit.
    bool applyRequests();
    // The field grown again after an edit (DocumentAction::Regrow), and taken in once grown.
    void startRegrow();
    void finishRegrow();
    // An edit that moved only the wind sources or the colliders: the live physics and the props
    // follow it at once (followMotion), and no re-grow is due unless placement follows them.
    void followMotionEdits();
    // A mesh collider the field holds no packing of is packed on a worker (collider_packing_job.h)
    // while the window goes on: true once every mesh collider of `project` is packed. False
    // meanwhile, and after the packing failed (the re-grow the edit asked for then says why).
    bool packCollidersInBackground(const core::Project& project);
    // Takes a finished packing into the live field's packings.
    void collectColliderPacking();
    // Colliders › add mesh… (EditorState::addColliderRequested): the file read, checked and
    // copied on a worker (mesh_import.h importColliderMesh); once done the collider is added,
    // its mesh kept for its prop (LiveMotion::readAheadProps). The window reads no glTF.
    void startColliderImport();
    void collectColliderImport();
    // The same project's field, grown again: it replaces the live one, the clock goes on.
    void adoptLive(Live next);
    // The view framed on the live surface (after a new mesh, unit or up axis).
    void frameLiveSurface();
    // The grown field becomes the document (replaceDocument), the view goes to its camera.
    bool adoptDocument(GrownField next, std::string_view what);
    // New, Open, New from mesh, Import mesh, Recover: `read` makes the project (and may read its
    // mesh) on a worker, which then grows its field (document_job.h). A replayed script waits
    // for it in this frame, so its pictures do not depend on the machine's speed.
    using OptionalMesh = std::optional<core::GltfImport>;
    // `stop`: the job's (its Cancel, the window closed), for a read of a large mesh to end early.
    using ReadDocument = std::function<Result<core::LoadedProject>(
        OptionalMesh& meshRead, std::string& note, std::stop_token stop)>;
    void startDocumentJob(DocumentAction action, std::filesystem::path file, ReadDocument read);
    // The worker's part of a document job: `read`, then the field grown (`name`: the file, for
    // the stage shown).
    static DocumentJob::Work documentWork(ReadDocument read, bool withPhysics,
                                          DocumentAction action, std::string name);
    // The first field, grown on a worker before the first frame while the window says what it
    // does (`showProgress`) and answers its close button: false when the user closed it.
    bool waitForFirstField(DocumentJob& job, bool showProgress);
    // Once the job is done: its field replaces the document, or the message says why not.
    void finishDocumentJob();
    // What the finished job does with its field besides (editor_imports.cpp: the imports).
    void adoptImportedMesh(GrownDocument imported, const std::filesystem::path& file);
    // New from mesh, Import mesh and Import map image requests (editor_imports.cpp).
    void applyImports();
    void resetTimeline();
    void autosaveWhenDue();
    void advanceTime();
    // The script's input for this frame (a `wait-s` step holds until its time has passed);
    // none once the script is over.
    std::optional<ScriptFrame> nextScriptStep(Clock::time_point now);
    // The end of a script: on wall-clock time, says how far the timeline moved by the start of
    // the last frame.
    bool finishScript(Clock::time_point lastFrame);
    // The adaptive quality's rung for this frame (viewRenderOptions applies it).
    void chooseQuality();
    void render(int width, int height);
    // Gives the renderer the map overlay the paint tool asks for, when it changed.
    void syncMapOverlay();
    // Screenshots and the turntable; false when the --screenshot was written (the end).
    Result<bool> writeOutputs(int width, int height);
    void updateStatus(bool statusDue, bool timingsDue);
    // What will change on screen without input (how long a frame at rest may wait).
    RestingFrame restingFrame() const;

    EditorSettings mSettings;
    bool mReplay = false;  // screenshots and scripts: one physics step per frame
    std::vector<ScriptFrame> mScript;
    EditorState mState;
    std::unique_ptr<Window> mWindow;
    std::unique_ptr<EditorUi> mUi;
    core::OrbitCamera mCamera;
    Live mLive;
    bool mRegrowOnSameSurface = false;  // the running re-grow grows on mLive's mesh
    std::unique_ptr<ColliderPackingJob> mPackingJob;
    // The colliders a packing failed for: not packed again in the background (the re-grow packs
    // them and reports the error) until they change.
    std::optional<std::vector<core::ColliderDesc>> mPackingFailedFor;
    std::unique_ptr<WorkerJob<Result<ImportedCollider>>> mColliderImport;
    std::filesystem::path mColliderImportFolder;  // the project folder it copies into
    std::unique_ptr<gl::Framebuffer> mTarget;
    // What mTarget's picture was drawn from (app/view_redraw.h); whether this frame drew it.
    std::optional<ViewInputs> mDrawnView;
    bool mViewDrawn = false;
    int mViewsDrawn = 0;  // for the --wall-clock summary
    int mMinimisedFrames = 0;     // frames that found the window minimised and drew nothing
    int mViewsDrawnAtStatus = 0;  // at the last status update: none since means "at rest"
    bool mLastDrawnReduced =
        false;  // the last picture drawn was the adaptive quality's reduced one
    // The frames that drew the last full picture and the status bar's timings (the script summary).
    int mLastFullPictureFrame = -1;
    int mTimingsFrame = -1;
    // A status update came and no picture drawn since has measured its figures.
    bool mTimingsWanted = false;
    // The window's event count after this frame's input was read: a frame that drew nothing new
    // and saw no event since waits for one (Editor::frame).
    std::uint64_t mEventsAtPoll = 0;
    PixelRect mView;
    int mFrame = 0;
    std::size_t mScriptStep = 0;
    std::optional<Clock::time_point> mHoldStart;  // when the current `wait-s` step began
    std::string mScriptShot;  // this frame's script screenshot (empty: none)
    double mFrameS = 0.0;     // wall time since the previous frame
    // The --wall-clock summary: frame times by script phase, physics skipped, refinement.
    SessionStats mStats;
    std::string mPhase;
    double mSkippedS = 0.0;                // physics time skipped in this frame
    std::optional<double> mFullSinceS;     // a full frame drawn after the input of this time
    double mTimelineStartS = 0.0;
    struct {
        double simS = 0.0, wallS = 0.0;
    } mDropped;  // physics time skipped over the current second
    bool mCameraDrag = false;  // a drag that began in the viewport stays the camera's
    bool mToolDrag = false;    // a drag that began on a tool (brush, gizmo) stays the tool's
    bool mInteracting = false;  // orbiting, zooming, painting, dragging, playing: this frame
    std::string mShownTitle;
    // What the renderer's map overlay shows (syncMapOverlay): none, or a layer's map as of a
    // count of map changes, on one renderer.
    struct OverlayShown {
        const void* renderer = nullptr;
        std::size_t layer = 0;
        core::LayerMap map = core::LayerMap::Density;
        std::uint64_t changes = 0;
        bool operator==(const OverlayShown&) const = default;
    };
    std::optional<OverlayShown> mOverlayShown;
    double mAutosaveDueS = 0.0;
    std::optional<double> mPanelsChangeInS;  // the last frame's ui::Output::repaintAfterS
    Clock::time_point mStartTime, mLastStatus, mLastTick;
    int mFramesSinceStatus = 0;  // for the status bar's frame rate
};

}  // namespace grass::editor
