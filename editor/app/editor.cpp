#include "app/editor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <utility>

#include <epoxy/gl.h>

#include "app/autosave.h"
#include "app/document.h"
#include "app/edit_actions.h"
#include "app/mesh_import.h"
#include "app/viewport_tools.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "mesh/gltf_loader.h"
#include "render/offscreen_render.h"
#include "render/scene_renderer.h"
#include "render/turntable_files.h"
#include "scene/motion_edit.h"
#include "util/image_file.h"

namespace grass::editor {

namespace {

// File → Save turntable: a 15° step, smooth enough to read as a turn on the contact sheet.
constexpr int TURNTABLE_VIEWS = 24;
// While a field grows on a worker: five frames a second at most (Editor::frame).
constexpr int LOADING_FRAME_MS = 200;
// The status bar's figures are brought up to date this often.
constexpr auto STATUS_EVERY = std::chrono::milliseconds(500);

}  // namespace

// What a document job's worker does: `read` makes the project (and may read its mesh), then its
// field grows, the job's stage following the build's; a cancel between the two skips the
// growing, one while it grows ends it at its next stage.
DocumentJob::Work Editor::documentWork(ReadDocument read, bool withPhysics, DocumentAction action,
                                       std::string name) {
    return [read = std::move(read), withPhysics, action,
            name = std::move(name)](DocumentJob& job) -> Result<GrownDocument> {
        OptionalMesh meshRead;
        GrownDocument grown;
        auto loaded = read(meshRead, grown.note, job.stopToken());
        if (!loaded)
            return loaded.error();
        if (job.cancelled())
            return makeError(job.title(), "cancelled");
        job.setStage(action == DocumentAction::ImportMesh ? "growing the grass on " + name
                                                          : "growing " + loaded->project.name);
        // The loading box follows the build's stages: a large mesh's read, its UVs, each layer.
        auto field =
            growField(std::move(*loaded), withPhysics, meshRead ? &*meshRead : nullptr, nullptr,
                      job.stopToken(), [&job](const std::string& stage) { job.setStage(stage); });
        if (!field)
            return field.error();
        grown.field = std::move(*field);
        return grown;
    };
}

bool Editor::waitForFirstField(DocumentJob& job, bool showProgress) {
    if (mReplay) {  // screenshots and scripts: the same pictures however long it takes
        job.wait();
        return true;
    }
    while (!job.done()) {
        if (mUi && showProgress) {
            char elapsed[32];
            std::snprintf(elapsed, sizeof elapsed, " … %.0f s", job.elapsedS());
            mUi->showNotice(*mWindow,
                            {job.title(), job.stage() + elapsed, "(closing the window stops it)"});
        }
        const Clock::time_point until = Clock::now() + std::chrono::milliseconds(LOADING_FRAME_MS);
        while (Clock::now() < until && !job.done()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            mWindow->pollInput();  // what the user did meanwhile is not the first frame's
        }
        if (mWindow->shouldClose()) {
            // Gone at once; the worker stops at its next stage and is waited for.
            mWindow->hide();
            job.cancel();
            return false;
        }
    }
    return true;
}

Result<std::unique_ptr<Editor>> Editor::open(EditorSettings settings) {
    std::unique_ptr<Editor> editor(new Editor());
    Editor& e = *editor;
    if (!settings.scriptFile.empty()) {
        auto parsed = loadInputScript(settings.scriptFile);
        if (!parsed)
            return makeError("--script", parsed.error().str());
        e.mScript = std::move(*parsed);
    }
    // Screenshots and scripts step the simulation once per frame, whatever the machine's speed.
    // (--wall-clock: a script runs on real time instead, for tests of time.)
    e.mReplay = !settings.screenshot.empty() || (!settings.scriptFile.empty() && !settings.wallClock);
    e.mAutosaveDueS = settings.autosaveS;
    e.mSettings = std::move(settings);

    // A mesh given instead of a project starts a new project around it, as File › New from
    // mesh does (a user who runs `grass-editor rock.glb` means that).
    const std::filesystem::path start(e.mSettings.projectPath);
    const bool fromMesh = core::isGltfPath(start);
    // The window opens before anything large is read, so the seconds a large mesh takes to read
    // and grow pass in front of a window that says what it is doing. A new project around a mesh
    // is named after the file and has the default picture size, known before the file is read.
    auto loaded =
        fromMesh ? Result<core::LoadedProject>(core::LoadedProject{}) : core::loadProject(start);
    if (!loaded)
        return loaded.error();
    const std::string name = fromMesh ? start.stem().string() : loaded->project.name;
    // A session someone works in fits the screen; a screenshot or a script keeps the exact
    // size (tests compare it with `grass render`).
    const bool interactive = e.mSettings.screenshot.empty() && e.mSettings.scriptFile.empty();
    auto window = Window::create(loaded->project.render.width, loaded->project.render.height,
                                 "grass — " + name, e.mSettings.glDebug, interactive);
    if (!window)
        return window.error();
    e.mWindow = std::move(*window);
    if (!e.mSettings.noUi) {
        auto created = EditorUi::create();
        if (!created)
            return created.error();
        e.mUi = std::move(*created);
    }
    // The field grows on a worker, as File › Open's does, while the window says what it is
    // doing and can be closed (waitForFirstField).
    const bool withPhysics = !e.mSettings.noPhysics;
    ReadDocument read;
    if (fromMesh)
        read = [start](OptionalMesh& meshRead, std::string&, std::stop_token stop) {
            return newProjectFromMesh(start, NEW_MESH_PROJECT_BLADES, &meshRead.emplace(), stop);
        };
    else
        read = [project = std::move(*loaded)](OptionalMesh&, std::string&, std::stop_token) {
            return Result<core::LoadedProject>(project);
        };
    const DocumentAction action = fromMesh ? DocumentAction::NewFromMesh : DocumentAction::Open;
    DocumentJob job(action, start, fromMesh ? "reading " + shownFileName(start) : "growing " + name,
                    documentWork(std::move(read), withPhysics, action, shownFileName(start)),
                    std::chrono::milliseconds(e.mSettings.loadDelayMs));
    if (!e.waitForFirstField(job, interactive)) {
        std::fprintf(stderr, "grass-editor: window closed while %s (%s, %.1f s): nothing opened\n",
                     job.stage().c_str(), job.title().c_str(), job.elapsedS());
        return std::unique_ptr<Editor>();
    }
    auto grown = job.take();
    if (!grown)
        return grown.error();
    std::fprintf(stderr, "grass-editor: %s: %.1f s\n", job.title().c_str(), job.elapsedS());
    EditorState& state = e.mState;
    state.doc.loaded = grown->field.loaded;
    const core::Project& project = state.doc.loaded.project;
    auto camera = render::projectCamera(project, "");
    if (!camera)
        return camera.error();
    e.mCamera = *camera;
    auto built = bringUpLive(std::move(grown->field), {}, e.mSettings.physicsDevice);
    if (!built)
        return built.error();
    e.mLive = std::move(*built);
    state.scene = e.mLive.scene.get();
    state.tools = e.mLive.tools.get();
    // Patches the brush or an undo re-grew: only those go up to the GPU, at once.
    state.wakeFrame = [] { Window::wake(); };
    state.regrown = [&e](std::size_t layer, const core::RegrowReport& report) {
        ++e.mState.mapsChanged;
        e.mLive.renderer->uploadRegrown(layer, report);
        if (e.mLive.physics)
            e.mLive.physics->regrown(layer, *e.mLive.scene, report.patches);
    };
    state.view.softwareRenderer = gl::isSoftwareRenderer();
    // Screenshots and scripts draw every frame at full quality: their pictures must not depend
    // on the machine's speed.
    state.view.quality.setSettings({.enabled = e.mSettings.adaptive && !e.mReplay,
                                    .budgetMs = e.mSettings.frameBudgetMs});
    state.view.options = viewRenderOptions(state);
    resetHistory(state);
    // File › Open Recent is the user's, kept across sessions: a replayed script (a test) neither
    // reads nor writes it, so its pictures and the user's list stay independent.
    if (!e.mReplay) {
        state.transient.recentFile = recentFilesPath();
        state.transient.recent = loadRecentFiles(state.transient.recentFile);
        if (!fromMesh)
            rememberRecent(state, state.doc.loaded.file);
    }
    if (fromMesh)
        markNewFromMesh(state, start);
    // A project read from its file is what the file holds: undoing back to here leaves nothing
    // unsaved.
    if (!state.doc.dirty)
        state.doc.history.markSaved();
    state.recoveryOffer = findAutosave(state.doc.loaded);
    // A never-saved project's autosave, left by a session that ended without a clean close, is
    // offered whatever project this session opens (it has no folder to be found by).
    state.offersUnsavedAutosaves = !e.mReplay;
    if (!state.recoveryOffer && state.offersUnsavedAutosaves)
        state.recoveryOffer = findUnsavedAutosave();
    state.recoverRequested = e.mSettings.recover && state.recoveryOffer.has_value();
    e.resetTimeline();
    state.glRenderer = gl::rendererDescription();
    std::fprintf(stderr, "grass-editor: %s, %zu blades, geometry %s\n", state.glRenderer.c_str(),
                 e.mLive.scene->totalBlades(),
                 render::geometryPathLabel(state.view.options.geometry));
    e.mStartTime = e.mLastStatus = e.mLastTick = Clock::now();
    e.mTimelineStartS = state.view.timeline.timeS();
    return editor;
}

Editor::~Editor() {
    const bool exporting = mState.exportJob && !mState.exportJob->done();
    if ((mState.regrowing() || exporting) && mWindow)
        mWindow->hide();  // the session is over: gone from the screen while the workers end
    // An export asked for is finished (its files are whole or untouched either way), said on
    // the terminal: the window is gone, and it used to stand frozen until the export's end.
    if (exporting) {
        std::fprintf(stderr, "grass-editor: finishing the export before quitting …\n");
        mState.exportJob->wait();
        std::fprintf(stderr, "grass-editor: %s\n", mState.exportJob->summary().c_str());
    }
    for (std::unique_ptr<DocumentJob>* job : {&mState.regrowJob, &mState.stoppingRegrow})
        if (*job) {
            (*job)->cancel();
            job->reset();  // waits for the worker, before mLive goes
        }
}

Result<bool> Editor::frame() {
    if (mWindow->shouldClose() && closeRequested())
        return false;
    // The wall time this frame stands for: everything since the last one, rendering included
    // (time, physics and autosave run on it, however slow the frame).
    const Clock::time_point tick = Clock::now(), previousTick = mLastTick;
    mFrameS = std::chrono::duration<double>(tick - previousTick).count();
    mLastTick = tick;
    // Only a --wall-clock script reports its frames: a session of hours would otherwise keep
    // every frame's figures.
    const bool measured = !mSettings.scriptFile.empty() && !mReplay;
    if (measured && mFrame > 0) {  // the frame just ended
        mStats.frameEnded(mPhase, mFrameS * 1000.0, mSkippedS);
        if (mFullSinceS) {
            mStats.fullQualityAfter(std::chrono::duration<double>(tick - mStartTime).count() -
                                    *mFullSinceS);
            mFullSinceS.reset();
        }
    }
    mSkippedS = 0.0;
    const std::uint64_t eventsBefore = mEventsAtPoll;
    InputState input = mWindow->pollInput();
    mEventsAtPoll = mWindow->eventCount();
    mScriptShot.clear();
    if (!mSettings.scriptFile.empty()) {
        auto step = nextScriptStep(tick);
        if (!step)
            return finishScript(previousTick);
        input = step->input;
        mScriptShot = step->screenshot;
        mPhase = step->phase;
    }
    int width = 0, height = 0;
    mWindow->framebufferSize(&width, &height);
    if (width <= 0 || height <= 0 || input.minimised) {
        // Minimised (iconified on X11, a 0×0 framebuffer on Windows and Wayland): nothing to
        // draw until it is shown again, which is an event; without the wait the loop polled at
        // full speed, and on X11 a minimised window that played drew the field on every core
        // (llvmpipe). The timeline holds meanwhile (advanceTime never sees these frames' time),
        // but the autosave keeps its clock: an edit left minimised is still saved.
        ++mMinimisedFrames;
        autosaveWhenDue();
        mWindow->waitForEvents(LONGEST_IDLE_WAIT_S);
        return true;
    }
    runInput(input, width, height);
    const bool widgetActive = mUi && mUi->context().activeId().value != 0;
    recordProjectEdit(mState, widgetActive);
    // The project's file edited by another program (a text editor) while nothing here is
    // unsaved: taken as an edit, which grows the field again below with the others.
    followProjectFileOnDisk(mState, std::chrono::duration<double>(tick - mStartTime).count(),
                            widgetActive || mState.view.toolDragActive);
    if (applyRequests())
        return false;
    autosaveWhenDue();
    const std::string title = "grass — " + mState.doc.loaded.project.name + (mState.doc.dirty ? " *" : "");
    if (title != mShownTitle) {
        mWindow->setTitle(title);
        mShownTitle = title;
    }
    // This frame's picture follows the project as it is now, with the view's overrides and the
    // adaptive quality's rung.
    chooseQuality();
    mState.view.options = viewRenderOptions(mState);
    advanceTime();
    // Statistics cost atomics and a wait when read: only the frame before a status update
    // collects them, and they are read once, after it.
    const bool statusDue = mFrame == 0 || Clock::now() - mLastStatus > STATUS_EVERY;
    // Exact pass timings wait for each pass on software GL (gl/timer_query.h). The full picture
    // the window then rests on must measure them: often the only frame drawn before the rest, it
    // was rarely a status frame, and the status bar showed the figures of a picture minutes and
    // views before. On software GL every full picture measures them (the meadow, 30 frames
    // drawn one after the other, two runs each: median 131.5 and 133.2 ms measured, 134.9 and
    // 139.2 not); elsewhere, where reading the statistics back stalls the GPU, the full picture
    // after reduced ones (input stopped, playback paused) and one after a frame that drew
    // nothing (an edit, a re-grow taken in) do, and the rest at status updates. A reduced
    // picture measures them at status updates too (the first drawn at or after one: a frame
    // whose time moved no physics step shows the last picture again): the status bar says what
    // the picture shown draws and costs. Before, it kept the last full picture's while the
    // picture was reduced, which is always while a windy field plays: "64,033 drawn" of a view
    // long left, or 0 when the window had opened playing.
    mTimingsWanted = mTimingsWanted || statusDue;
    const bool fullQuality = mState.view.quality.level() == 0;
    const bool timingsDue =
        mTimingsWanted ||
        (fullQuality && (mState.view.softwareRenderer || mLastDrawnReduced || !mViewDrawn));
    mState.view.options.cull.collectStats = timingsDue;
    render(width, height);
    if (mViewDrawn) {
        mLastDrawnReduced = !fullQuality;
        if (fullQuality)
            mLastFullPictureFrame = mFrame;
        if (timingsDue) {
            mTimingsFrame = mFrame;
            mTimingsWanted = false;
        }
    }
    auto more = writeOutputs(width, height);
    if (!more || !*more)
        return more;
    // The frame's slowness (--frame-delay-ms), spent gathering events as they come: a slow
    // frame must not stretch the time between two clicks of a double-click.
    // While a document job grows its field, frames come at most every LOADING_FRAME_MS, so the
    // worker gets the cores the renderer would take (llvmpipe draws on every core): the window
    // still answers, and the load is not slowed by frames nobody needs.
    Clock::time_point until = Clock::now() + std::chrono::milliseconds(mSettings.frameDelayMs);
    if (mState.loading() && !mReplay)
        until = std::max(until, tick + std::chrono::milliseconds(LOADING_FRAME_MS));
    const bool waitingForJob = mState.loading();
    while (Clock::now() < until && !(waitingForJob && mState.documentJob->done())) {
        std::this_thread::sleep_for(
            std::min<Clock::duration>(std::chrono::milliseconds(5), until - Clock::now()));
        mWindow->gatherEvents();
    }
    mWindow->gatherEvents();  // what came in while the frame rendered: stamped before the swap
    mWindow->swapBuffers();
    updateStatus(statusDue, timingsDue && mViewDrawn);
    // At rest (the picture as it was, no event since the last frame read its input) the next
    // frame waits for an event: a pointer moved, a key, a click end the wait at once. Scripts
    // run at the speed of their frames; a load paces its frames itself (above).
    const bool idle = !mViewDrawn && mSettings.scriptFile.empty() && !waitingForJob &&
                      eventsBefore == mEventsAtPoll && mWindow->eventCount() == mEventsAtPoll;
    if (idle)
        mWindow->waitForEvents(idleWaitS(restingFrame()));
    return true;
}

RestingFrame Editor::restingFrame() const {
    const Clock::time_point now = Clock::now();
    RestingFrame frame;
    frame.panelsChangeInS = mPanelsChangeInS;
    // The adaptive quality's clock: seconds since the editor started (chooseQuality).
    const double qualityNowS = std::chrono::duration<double>(now - mStartTime).count();
    if (const std::optional<double> fullAtS = mState.view.quality.fullPictureAtS())
        frame.fullPictureInS = *fullAtS - qualityNowS;
    if (mSettings.autosaveS > 0.0 && mState.doc.dirty)
        frame.autosaveInS = mAutosaveDueS;
    // A little after the update is due (frame() takes it once strictly past STATUS_EVERY).
    if (!mState.transient.status.atRest)
        frame.statusUpdateInS =
            std::chrono::duration<double>(mLastStatus + STATUS_EVERY - now).count() + 0.005;
    frame.progressShown = mState.regrowing() || mState.busy();
    frame.playing = mState.view.timeline.playing();
    return frame;
}

void Editor::endInterrupted(int signal) {
    cancelDocumentJob(mState);
    const char* what = signal == SIGINT ? "interrupted" : "terminated";
    if (!mState.doc.dirty) {
        std::fprintf(stderr, "grass-editor: %s: nothing was unsaved\n", what);
        return;
    }
    // Its own message, whatever the status line showed before.
    mState.transient.message.clear();
    mState.transient.messageIsSaveError = false;
    autosaveNow(mState);
    std::fprintf(stderr,
                 "grass-editor: %s: the unsaved changes: %s; the next start offers them back\n",
                 what, mState.transient.message.c_str());
}

bool Editor::closeRequested() {
    // Closing the window stops a load first, so that the question about unsaved changes is
    // asked (and answered) with the panels free.
    cancelDocumentJob(mState);
    if (!mUi || !mState.doc.dirty || mReplay) {
        // A clean close leaves nothing to recover (an autosave still on offer stays).
        if (!mState.doc.dirty && !mState.recoveryOffer)
            removeAutosave(mState.doc.loaded);
        if (!mState.doc.dirty)
            removeUnsavedSlot(mState.doc.unsavedSlot);
        return true;
    }
    mWindow->cancelClose();  // ask first
    askQuit(mState);
    return false;
}

bool Editor::applyRequests() {
    EditorState& state = mState;
    // Quitting (after saving, or choosing to drop the changes) leaves nothing to recover.
    if (state.quitRequested) {
        if (!state.recoveryOffer)
            removeAutosave(state.doc.loaded);
        removeUnsavedSlot(state.doc.unsavedSlot);  // saved or let go: nothing to recover
        return true;
    }
    finishDocumentJob();
    finishRegrow();
    // An export reads the scene on its worker, a load or a re-grow replaces it: requests wait
    // for them.
    const bool waiting = state.busy() || state.regrowing();
    if (state.newRequested && !waiting) {
        state.newRequested = false;
        startDocumentJob(DocumentAction::New, {},
                         [folder = std::filesystem::current_path()](OptionalMesh&, std::string&,
                                                                    std::stop_token) {
                             return Result<core::LoadedProject>(
                                 core::LoadedProject{core::Project{}, folder, {}});
                         });
    }
    if (!state.openRequested.empty() && !waiting) {
        const std::filesystem::path file = std::exchange(state.openRequested, {});
        startDocumentJob(DocumentAction::Open, file,
                         [file](OptionalMesh&, std::string&, std::stop_token) {
                             return core::loadProject(file);
                         });
    }
    applyImports();
    if (state.recoverRequested && !waiting) {
        state.recoverRequested = false;
        startDocumentJob(DocumentAction::Recover, {},
                         [recovered = std::move(*state.recoveryOffer)](OptionalMesh&, std::string&,
                                                                       std::stop_token) {
                             return Result<core::LoadedProject>(recovered);
                         });
        state.recoveryOffer.reset();
    }
    followMotionEdits();
    // Files of the field changed on disk: grown again from them, which the project's motion
    // alone (followMotionEdits) never asks for.
    if (std::exchange(state.regrowFromDisk, false))
        state.rebuildPending = true;
    // Re-grow once the edit has ended, not on every frame of a drag. A re-grow still running
    // for an earlier edit is stopped: its field would only be replaced (on a large mesh the
    // edit's field came a whole re-grow later). It ends at its next stage beside the new one,
    // and finishRegrow lets it go.
    const bool editEnded = state.rebuildPending && !state.view.toolDragActive && !state.busy() &&
                           (!mUi || mUi->context().activeId().value == 0);
    if (editEnded && state.regrowJob && !state.stoppingRegrow) {
        state.regrowJob->cancel();
        state.stoppingRegrow = std::move(state.regrowJob);
    }
    // A collider being packed is followed once packed, without growing the field: the re-grow
    // waits for it.
    if (editEnded && !state.regrowJob && !state.stoppingRegrow && !mPackingJob) {
        state.rebuildPending = false;
        startRegrow();
    }
    if (state.exportWhenGrown && !state.regrowing() && !state.rebuildPending && !state.busy())
        startExport(state);
    return false;
}

// A gizmo drag of a wind source or a collider, a panel edit of their settings, one added or
// deleted, or the undo of any of these changes nothing of the grown field: the live physics
// takes the new wind and colliders and the props move (or are made again), frame by frame during
// a drag, and the field goes on moving (a ball dragged through the grass pushes it aside as it
// goes). Before, nothing moved until the mouse was released, and then the whole field was grown
// again and its blades restarted from rest. Not while an export reads the scene or a re-grow
// will replace it (the edit re-grows then).
void Editor::followMotionEdits() {
    EditorState& state = mState;
    collectColliderPacking();
    collectColliderImport();
    if (!mLive.scene || state.busy() || state.regrowing())
        return;
    // Not while a packing runs: it may have read a file before its change.
    if (!state.colliderFilesChangedOnDisk.empty() && !mPackingJob) {
        mLive.motion.forgetFiles(std::exchange(state.colliderFilesChangedOnDisk, {}));
        mPackingFailedFor.reset();  // a file that did not pack may pack now
    }
    const core::Project& project = state.doc.project();
    const LiveMotion& motion = mLive.motion;
    // A preset's substeps whatever else the project changed since the field grew (its LOD and
    // segments are the renderer's, live too): before, they grew the whole field again.
    followPhysicsSteps(mLive, project.physics);
    const bool toFollow = project.wind != motion.wind || project.colliders != motion.colliders ||
                          motion.settledColliders != motion.colliders ||
                          !motion.changedFiles.empty() || motion.placementOfOldShapes;
    if (!toFollow && !state.rebuildPending)
        return;
    const core::Project& grown = mLive.builtFrom.project;
    // A mesh collider not packed yet (a new file or sphere count) is packed on a worker first:
    // packing can take seconds.
    if (!core::onlyMotionChanged(grown, project) || !packCollidersInBackground(project))
        return;
    const bool settled =
        !state.view.toolDragActive && (!mUi || mUi->context().activeId().value == 0);
    if (auto followed = followMotion(mLive, state.doc.loaded, settled); !followed) {
        // The re-grow the edit asked for reads the project again and says what is wrong.
        state.transient.message = "cannot move the colliders: " + followed.error().str();
        return;
    }
    // Blades cleared from under the colliders grow back where the colliders left, and go where
    // they now stand, once the edit ends: in the patches that changed alone.
    if ((grown.colliders == project.colliders && !motion.placementOfOldShapes) ||
        !core::placementFollowsColliders(project)) {
        state.rebuildPending = false;
        return;
    }
    if (!settled)
        return;
    const auto start = Clock::now();
    auto placed = followColliderPlacement(mLive, project);
    if (!placed) {  // the whole field grows again instead, and says what is wrong
        std::fprintf(stderr, "grass-editor: %s\n", placed.error().str().c_str());
        state.rebuildPending = true;
        return;
    }
    ++state.mapsChanged;
    state.rebuildPending = false;
    std::fprintf(stderr, "grass-editor: grew %zu patches again around the colliders, %.2f s\n",
                 *placed, std::chrono::duration<double>(Clock::now() - start).count());
}

bool Editor::packCollidersInBackground(const core::Project& project) {
    if (mLive.motion.packed(project.colliders))
        return true;
    if (mPackingJob || mPackingFailedFor == project.colliders)
        return false;
    mPackingFailedFor.reset();
    mPackingJob = std::make_unique<ColliderPackingJob>(mState.doc.loaded, mLive.scene->groundOrigin,
                                                       mLive.motion.packings, mState.wakeFrame,
                                                       mLive.motion.changedFiles);
    mState.transient.message = mPackingJob->what() + " …";
    if (!mReplay)
        return false;
    // Scripts and screenshots: packed in this frame, whatever the machine's speed.
    mPackingJob->wait();
    collectColliderPacking();
    return mLive.motion.packed(project.colliders);
}

void Editor::collectColliderPacking() {
    if (!mPackingJob || !mPackingJob->done())
        return;
    const std::unique_ptr<ColliderPackingJob> job = std::move(mPackingJob);
    auto packed = job->take();
    if (!packed) {
        mPackingFailedFor = job->colliders();
        // To fix in the file (a modeller's export half written, a broken glTF): said in orange,
        // and whole on the terminal (the status line cuts it).
        mState.transient.message = "cannot pack a collider: " + packed.error().str();
        mState.transient.warningMessage = mState.transient.message;
        std::fprintf(stderr, "grass-editor: %s\n", mState.transient.message.c_str());
        return;
    }
    // Packings are named by file relative to the project's folder, read in the ground's frame:
    // those of another document, or of a ground moved since, are not this field's.
    if (!mLive.scene || job->folder() != mLive.builtFrom.folder ||
        job->groundOrigin() != mLive.scene->groundOrigin)
        return;
    mLive.motion.takeReadAhead(std::move(packed->packings), std::move(packed->props));
    for (const std::string& note : packed->notes) {
        std::fprintf(stderr, "note: %s\n", note.c_str());
        mState.transient.message = note;
    }
}

// Re-grows the live field from the open project (after an edit that needs it) on a worker: the
// window goes on with the field before the edit meanwhile (a large mesh takes seconds).
void Editor::startRegrow() {
    // An edit of the layers keeps the surface: the field grows on the mesh at hand, not on the
    // file read again (seconds for a large mesh, each edit). The worker copies that mesh; the
    // live scene it reads stays until finishRegrow (nothing else replaces it meanwhile).
    // A surface file changed on disk (re-exported from a modeller) is read again.
    const bool surfaceChangedOnDisk = std::exchange(mState.surfaceChangedOnDisk, false);
    mRegrowOnSameSurface = mLive.scene && !surfaceChangedOnDisk &&
                           core::sameSurface(mLive.builtFrom, mState.doc.loaded);
    auto work = [loaded = mState.doc.loaded, withPhysics = !mSettings.noPhysics,
                 surface = mRegrowOnSameSurface ? mLive.scene.get() : nullptr](
                    DocumentJob& job) -> Result<GrownDocument> {
        auto field = growField(loaded, withPhysics, nullptr, surface, job.stopToken(),
                               [&job](const std::string& stage) { job.setStage(stage); });
        if (!field)
            return field.error();
        GrownDocument grown;
        grown.field = std::move(*field);
        return grown;
    };
    mState.regrowJob = std::make_unique<DocumentJob>(
        DocumentAction::Regrow, std::filesystem::path(), "",  // the badge shows the build's stages
        std::move(work), std::chrono::milliseconds(mSettings.loadDelayMs), mState.wakeFrame);
    if (mReplay)  // scripts and screenshots: the edit's field in the next frame, whatever the speed
        mState.regrowJob->wait();
    finishRegrow();
}

// Once the worker is done: its field replaces the live one, with the maps painted meanwhile
// carried over; on failure the old field stays. Not in the middle of a stroke.
void Editor::finishRegrow() {
    EditorState& state = mState;
    if (state.stoppingRegrow && state.stoppingRegrow->done()) {
        std::fprintf(stderr,
                     "grass-editor: stopped growing the field again after %.2f s: a later "
                     "edit grows it\n",
                     state.stoppingRegrow->elapsedS());
        state.stoppingRegrow.reset();
    }
    // Not while a stopped one may still read the live field this would replace.
    if (!state.regrowJob || !state.regrowJob->done() || state.view.toolDragActive ||
        state.stoppingRegrow)
        return;
    const std::unique_ptr<DocumentJob> job = std::move(state.regrowJob);
    auto grown = job->take();
    if (grown) {
        auto next = bringUpLive(
            std::move(grown->field),
            [&](core::Scene& field) { return carryPaintedMaps(state, *mLive.scene, field); },
            mSettings.physicsDevice, mRegrowOnSameSurface ? &mLive : nullptr);
        if (next) {
            adoptLive(std::move(*next));
            std::fprintf(stderr, "grass-editor: grew the field again: %zu blades, %.2f s\n",
                         mLive.scene->totalBlades(), job->elapsedS());
        } else {
            grown = next.error();
        }
    }
    if (!grown) {
        // To act on (the field on screen is the one before the edit, the project holds the
        // edit): said in orange, and whole on the terminal (the status line cuts it).
        state.transient.message = "cannot grow the field: " + grown.error().str();
        state.transient.warningMessage = state.transient.message;
        std::fprintf(stderr, "grass-editor: %s\n", state.transient.message.c_str());
        return;
    }
    if (std::exchange(state.view.frameSurfacePending, false))
        frameLiveSurface();
}

void Editor::frameLiveSurface() {
    mCamera = core::frameSurface(mLive.scene->mesh, float(mView.w) / float(std::max(mView.h, 1)));
}

void Editor::adoptLive(Live next) {
    const std::size_t steps = mLive.physics ? mLive.physics->steps : 0;
    mLive = std::move(next);
    ++mState.mapsChanged;  // a new renderer has no overlay yet, even at the old one's address
    mState.scene = mLive.scene.get();
    mState.tools = mLive.tools.get();
    if (mLive.physics)
        mLive.physics->steps = steps;  // the field restarts from rest, the clock goes on
}

void Editor::startDocumentJob(DocumentAction action, std::filesystem::path file,
                              ReadDocument read) {
    const std::string name = shownFileName(file);
    std::string stage = action == DocumentAction::New       ? "starting a new project"
                        : action == DocumentAction::Recover ? "recovering the autosave"
                                                            : "reading " + name;
    DocumentJob::Work work = documentWork(std::move(read), !mSettings.noPhysics, action, name);
    mState.documentJob = std::make_unique<DocumentJob>(
        action, std::move(file), std::move(stage), std::move(work),
        std::chrono::milliseconds(mSettings.loadDelayMs), mState.wakeFrame);
    if (mReplay) {
        mState.documentJob->wait();
        finishDocumentJob();
    }
}

void Editor::finishDocumentJob() {
    EditorState& state = mState;
    std::erase_if(state.cancelledJobs, [](const auto& job) { return job->done(); });
    if (!state.documentJob || !state.documentJob->done())
        return;
    const std::unique_ptr<DocumentJob> job = std::move(state.documentJob);
    const std::filesystem::path& file = job->file();
    const DocumentAction action = job->action();
    const std::string what = action == DocumentAction::New       ? "cannot start a new project"
                             : action == DocumentAction::Open    ? "cannot open"
                             : action == DocumentAction::Recover ? "cannot recover the autosave"
                             : action == DocumentAction::NewFromMesh
                                 ? "cannot make a project from " + file.filename().string()
                                 : "cannot import " + file.string();
    auto grown = job->take();
    std::fprintf(stderr, "grass-editor: %s: %.1f s\n", job->title().c_str(), job->elapsedS());
    if (!grown) {
        state.transient.message = what + ": " + grown.error().str();
        return;
    }
    if (action == DocumentAction::ImportMesh) {
        adoptImportedMesh(std::move(*grown), file);
        return;
    }
    if (!adoptDocument(std::move(grown->field), what))
        return;
    switch (action) {
        case DocumentAction::New:
            state.doc.dirty = true;  // exists only in memory until saved
            state.transient.message = "new project (not saved)";
            break;
        case DocumentAction::Open:
            state.doc.dirty = false;
            state.doc.history.markSaved();
            state.transient.message = "opened " + state.doc.loaded.file.string();
            rememberRecent(state, state.doc.loaded.file);
            break;
        case DocumentAction::NewFromMesh:
            markNewFromMesh(state, file);
            break;
        case DocumentAction::Recover:
            markRecoveredMaps(state);
            break;
        case DocumentAction::ImportMesh:
        case DocumentAction::Regrow:  // not a document job (finishRegrow)
            break;
    }
}

// New, Open, Recover: the document is replaced only once its field is grown.
bool Editor::adoptDocument(GrownField next, std::string_view what) {
    if (!replaceDocument(mState, mLive, std::move(next), what, mSettings.physicsDevice))
        return false;
    // The document left was saved or let go: its unsaved autosave has nothing to recover. A
    // recovered never-saved project goes on autosaving into the slot it came from.
    removeUnsavedSlot(mState.doc.unsavedSlot);
    if (mState.doc.loaded.file.empty() && isUnsavedSlot(mState.doc.loaded.folder)) {
        mState.doc.unsavedSlot = mState.doc.loaded.folder;
        mState.doc.unsavedSlotFrom = mState.doc.loaded.folder;
    }
    if (auto camera = render::projectCamera(mState.doc.loaded.project, ""))
        mCamera = *camera;
    resetTimeline();
    // The previous document's failed save (or "not autosaved") is not this one's to keep.
    mState.transient.messageIsSaveError = false;
    return true;
}

void Editor::resetTimeline() {
    core::Timeline& timeline = mState.view.timeline;
    timeline = core::timelineFor(mState.doc.loaded.project);
    // A minute at least, so an unkeyed scene does not restart its sway every few seconds.
    timeline.setRange(timeline.startS(), std::max(timeline.endS(), timeline.startS() + 60.0));
    timeline.setLoop(true);
    timeline.play();
}

void Editor::autosaveWhenDue() {
    // On the simulation's clock when replaying, so scripts see it at a fixed frame.
    mAutosaveDueS -= mReplay ? mState.view.timeline.stepS() : mFrameS;
    if (mSettings.autosaveS > 0.0 && mAutosaveDueS <= 0.0 && mState.doc.dirty && !mState.busy() &&
        !mState.view.toolDragActive) {
        mAutosaveDueS = mSettings.autosaveS;
        autosaveNow(mState);
    }
}

void Editor::advanceTime() {
    EditorState& state = mState;
    // Screenshots advance exactly one step per frame, so they do not depend on machine speed;
    // otherwise the timeline plays at wall-clock time × its speed.
    const double elapsedS = !mReplay ? mFrameS : state.view.timeline.stepS();
    const core::TimeUpdate moved = state.view.timeline.advance(elapsedS);
    const bool jumped = state.view.timeJump.needsReset() || moved.needsReset() ||
                        state.view.timeJump.change == core::TimeChange::JumpForward;
    state.view.timeJump = {};
    if (mLive.physics) {
        LivePhysics& physics = *mLive.physics;
        // An edit of the Snow section re-grows nothing: once it ends (not on every frame of a
        // drag: weighing the snow takes a while), the physics weighs the project's snow.
        if ((!mUi || mUi->context().activeId().value == 0) && !state.view.toolDragActive)
            physics.followSnow(state.doc.project().snow, *mLive.scene);
        if (jumped) {
            // The field restarts from rest at the new time (re-simulating from the start would
            // stall the scrub).
            if (auto reset = resetPhysics(mLive); !reset)
                state.transient.message = "cannot reset the simulation: " + reset.error().str();
            physics.steps = static_cast<std::size_t>(
                std::floor(state.view.timeline.timeS() / physics.scene.params.dtS));
        }
        // What the machine could not step, per second of wall time, for the status bar.
        // While the picture is reduced for interaction, one step a frame on the GPU: the physics
        // is the one cost the rungs do not lower (4 compute-shader steps of the meadow: ~110 ms
        // on llvmpipe). On the CPU as many as fit its budget (LivePhysics): 4 steps of the meadow
        // take ~11 ms there.
        const auto physicsStart = std::chrono::steady_clock::now();
        const std::size_t computedBefore = physics.computedSteps;
        mSkippedS = physics.cpu ? physics.advanceTo(state.view.timeline.timeS(),
                                                    LivePhysics::MAX_CPU_STEPS_PER_FRAME,
                                                    LivePhysics::CPU_STEP_BUDGET_MS)
                                : physics.advanceTo(state.view.timeline.timeS(),
                                                    state.view.quality.level() > 0
                                                        ? 1
                                                        : LivePhysics::MAX_STEPS_PER_FRAME);
        state.transient.status.physicsDevice = physics.deviceLabel();
        // The GPU's steps are queued, not run, here: only the CPU's time means something, and
        // only in a frame that computed a step (paused or resting, the label says where the
        // physics runs alone).
        const bool stepped = physics.computedSteps > computedBefore;
        state.transient.status.physicsMs =
            physics.cpu && stepped ? std::chrono::duration<double, std::milli>(
                                         std::chrono::steady_clock::now() - physicsStart)
                                         .count()
                                   : 0.0;
        mDropped.simS += mSkippedS;
        mDropped.wallS += elapsedS;
        if (mDropped.wallS >= 1.0) {
            state.transient.status.physicsDroppedS = mDropped.simS / mDropped.wallS;
            mDropped = {};
        }
    }
    // Cut blades grow back with the scene's time (issue 30 item 10): the patches a regrowth step
    // changed go up to the GPU and to the physics as a repaint's do.
    if (mLive.scene && state.regrown)
        for (std::size_t i = 0; i < mLive.scene->layers.size(); ++i) {
            const core::RegrowReport report = core::regrowCut(
                mLive.scene->layers[i], static_cast<float>(state.view.timeline.timeS()));
            if (!report.patches.empty())
                state.regrown(i, report);
        }
    state.view.options.timeS = static_cast<float>(state.view.timeline.timeS());
}

void Editor::chooseQuality() {
    ViewState& view = mState.view;
    // Playback counts as interaction (issue 24): the field moves, so a reduced picture keeps it
    // fluid; the physics runs one step a frame meanwhile (advanceTime) and drops the rest, said
    // in the status bar. Pausing refines to the full picture.
    // A field that nothing moves (no wind, its blades settled, no billboards, props or snow
    // changing with time) plays at full quality: its picture does not change.
    const bool fieldMoves = (mLive.physics && mLive.physics->moved) ||
                            timeChangesThePicture(*mLive.scene, view.options);
    const bool playing = view.timeline.playing() && !mReplay && fieldMoves;
    const double nowS = std::chrono::duration<double>(Clock::now() - mStartTime).count();
    const bool wasReduced = view.quality.level() > 0;
    view.quality.update(mFrameS * 1000.0, mInteracting || playing, nowS, mViewDrawn || mFrame == 0);
    // The first full frame after a reduced one: how long after the last input it is done.
    if (wasReduced && view.quality.level() == 0)
        mFullSinceS = view.quality.lastInteractionS();
    mState.transient.status.reduced = view.quality.level() > 0 ? view.quality.reduction().label : "";
}

void Editor::syncMapOverlay() {
    const PaintToolSettings& paint = mState.view.paint;
    const bool wanted = paint.showMap && mState.view.tool == ViewportTool::Paint &&
                        paint.layer < mLive.scene->layers.size();
    std::optional<OverlayShown> shown;
    if (wanted)
        shown = OverlayShown{mLive.renderer.get(), paint.layer, paint.map, mState.mapsChanged};
    if (shown == mOverlayShown)
        return;
    mLive.renderer->setMapOverlay(
        shown ? &core::layerMap(mLive.scene->layers[paint.layer].source.maps, paint.map) : nullptr);
    mOverlayShown = shown;
}

void Editor::render(int width, int height) {
    const core::Reduction& r = mState.view.quality.reduction();
    const int samples = r.msaaOff ? 0 : mState.doc.project().render.msaaSamples;
    // The ladder lowers the resolution only with MSAA off: a scaled blit needs one sample.
    const int w = std::max(1, int(float(mView.w) * r.resolutionScale));
    const int h = std::max(1, int(float(mView.h) * r.resolutionScale));
    // Kept from frame to frame: a project without MSAA, and every reduced frame, asked for 0
    // samples, got 1, and made a new framebuffer each frame.
    if (!mTarget || !mTarget->fits(w, h, samples)) {
        mTarget = std::make_unique<gl::Framebuffer>(w, h, samples);
        mDrawnView.reset();
    }
    syncMapOverlay();
    // In a session the window goes on while a worker places billboards (seconds on a large
    // mesh); scripts and screenshots draw them in the frame that asks, as `grass render` does.
    mLive.renderer->placeBillboardsInBackground(!mReplay);
    // The picture is drawn only when what it shows changed (app/view_redraw.h).
    // The GPU physics steps the drawn blades in place; the CPU's steps reach the picture as
    // uploads (the renderer's content generation), and only when they moved the blades.
    // Those computed: a resting field's clock goes on without a step, and is not drawn again.
    const std::size_t gpuSteps =
        mLive.physics && !mLive.physics->cpu ? mLive.physics->computedSteps : 0;
    ViewInputs inputs =
        viewInputsOf(*mLive.renderer, mState.mapsChanged, gpuSteps, mCamera, {w, h, samples},
                     mState.view.options, mState.doc.project(), *mLive.scene);
    mViewDrawn = mSettings.redrawEveryFrame ||
                 !viewStillDrawn(mDrawnView, inputs, mLive.renderer->placingBillboards());
    if (mViewDrawn) {
        mLive.renderer->render(mCamera, w, h, *mTarget, mState.view.options);
        mDrawnView = std::move(inputs);
        ++mViewsDrawn;
    }
    mState.transient.status.placingBillboards = mLive.renderer->placingBillboards();
    for (std::string& note : mLive.renderer->takeNotes())
        mState.transient.message = std::move(note);  // e.g. billboards refused after T
    if (!mUi) {
        mTarget->blitTo(0, width, height);
        return;
    }
    // The panels cover the rest; clear it so nothing stale shows through at the edges.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.106f, 0.106f, 0.106f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // A multisampled blit may move the rectangle but not scale it: sizes match then. A reduced
    // picture (one sample) is scaled up.
    glBlitNamedFramebuffer(mTarget->id(), 0, 0, 0, w, h, mView.x, mView.y, mView.x + mView.w,
                           mView.y + mView.h, GL_COLOR_BUFFER_BIT,
                           w == mView.w && h == mView.h ? GL_NEAREST : GL_LINEAR);
    mUi->draw(width, height);
}

Result<bool> Editor::writeOutputs(int width, int height) {
    EditorState& state = mState;
    const auto shownImage = [&](const std::string& file) {
        const gl::Rgba8Image shown = gl::readFramebuffer(0, width, height);
        return writeRgba8Image(file, shown.width, shown.height, shown.pixels);
    };
    if (!state.screenshotRequested.empty()) {
        const auto written = shownImage(state.screenshotRequested);
        state.transient.message = written ? "saved " + state.screenshotRequested
                                : "screenshot not saved: " + written.error().str();
        state.screenshotRequested.clear();
    }
    if (!state.turntableRequested.empty()) {
        // The views show the field as grown (at rest), from the viewport's camera and size.
        render::OffscreenRequest request;
        request.width = mView.w;
        request.height = mView.h;
        request.frames = 1;
        request.options = state.view.options;
        auto turned = render::writeTurntable(*mLive.scene, mCamera, request, TURNTABLE_VIEWS,
                                             state.turntableRequested);
        state.transient.message = turned ? "saved a turntable of " + std::to_string(turned->framesWritten) +
                                     " views: " + turned->sheet.string()
                               : "turntable not saved: " + turned.error().str();
        state.turntableRequested.clear();
    }
    if (!mScriptShot.empty()) {
        const std::string& shot = mScriptShot;
        if (auto written = shownImage(shot); !written)
            return written.error();
        std::printf("wrote %s (%dx%d) at frame %d\n", shot.c_str(), width, height, mFrame + 1);
    }
    ++mFrame;
    if (!mSettings.screenshot.empty() && mFrame >= mSettings.frames) {
        if (auto written = shownImage(mSettings.screenshot); !written)
            return written.error();
        std::printf("wrote %s (%dx%d) after %d frames\n", mSettings.screenshot.c_str(), width,
                    height, mFrame);
        return false;
    }
    return true;
}

void Editor::updateStatus(bool statusDue, bool timingsDue) {
    const Clock::time_point now = Clock::now();
    ++mFramesSinceStatus;
    mState.transient.status.blades = mLive.scene->totalBlades();  // live: a re-grow shows at once
    if (timingsDue)
        mState.transient.status.timings = mLive.renderer->lastTimings();
    if (statusDue) {
        // Frames over the time since the last update (≥ 0.5 s): the rate now, readable, and
        // right at once when the frame time jumps (reduced ↔ full picture), which a per-frame
        // moving average at 1–10 fps is not.
        const double sinceS = std::chrono::duration<double>(now - mLastStatus).count();
        if (sinceS > 0.0)
            mState.transient.status.fps = double(mFramesSinceStatus) / sinceS;
        mState.transient.status.atRest = mViewsDrawn == mViewsDrawnAtStatus;
        mState.transient.status.playing = mState.view.timeline.playing();
        mViewsDrawnAtStatus = mViewsDrawn;
        mFramesSinceStatus = 0;
        mLastStatus = now;
    }
}

}  // namespace grass::editor
