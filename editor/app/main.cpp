// grass-editor: the authoring window. A menu bar (File), a side panel with the project's layers,
// wind, colliders and render settings, a status bar with blade counts and pass times, and the
// 3D viewport in what is left: drag to orbit, wheel to zoom, middle- or shift-drag to pan, F to
// frame the scene; 1–4 switch the cull tests, T the technique, L the lighting. Quitting with
// unsaved changes asks first. The UI takes the pointer and keys when it wants them
// (ui::Output). --screenshot saves what the window shows after --frames frames and exits, so
// tests and users can see the editor without a person; --no-ui shows the viewport alone.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include <epoxy/gl.h>

#include "autosave.h"
#include "debug_output.h"
#include "edit_actions.h"
#include "editor_ui.h"
#include "framebuffer.h"
#include "headless_context.h"
#include "input_script.h"
#include "document.h"
#include "live_scene.h"
#include "offscreen_render.h"
#include "panels.h"
#include "scene/scene_physics.h"
#include "scene_physics_gpu.h"
#include "scene_renderer.h"
#include "turntable_files.h"
#include "util/arg_parser.h"
#include "util/image_file.h"
#include "viewport_tools.h"
#include "window.h"

namespace {

using namespace grass;

// File → Save turntable: a 15° step, smooth enough to read as a turn on the contact sheet.
constexpr int TURNTABLE_VIEWS = 24;

int fail(const std::string& message, int code = 1) {
    std::fprintf(stderr, "grass-editor: %s\n", message.c_str());
    return code;
}

// Keys that change how the field is drawn (window.h); returns what changed, for the console.
// 1-4 switch a cull test of the view; T and L change the project's technique and lighting (a
// project edit like the Render panel's combo boxes: saved, undoable, marking it unsaved).
std::string applyRenderKeys(const editor::InputState& input, editor::EditorState& state) {
    editor::ViewOverrides& view = state.view;
    bool* tests[] = {&view.orientation, &view.frustum, &view.distance, &view.occlusion};
    const char* names[] = {"orientation", "frustum", "distance", "occlusion"};
    if (input.toggledCullTest >= 1 && input.toggledCullTest <= 4) {
        bool& test = *tests[input.toggledCullTest - 1];
        test = !test;
        return std::string(names[input.toggledCullTest - 1]) + " culling " + (test ? "on" : "off");
    }
    core::Project& project = state.loaded.project;
    if (input.nextTechnique) {
        project.render.technique =
            static_cast<core::GrassTechnique>((static_cast<int>(project.render.technique) + 1) % 4);
        return "technique " + std::string(core::grassTechniqueName(project.render.technique));
    }
    if (input.toggleLighting) {
        core::LightingModel& model = project.lighting.model;
        model = model == core::LightingModel::Grass ? core::LightingModel::Simple
                                                    : core::LightingModel::Grass;
        return model == core::LightingModel::Grass ? "grass lighting" : "simple lighting";
    }
    return {};
}

void applyInput(editor::InputState input, bool drag, bool wheel, int viewportHeight,
                const core::Scene& scene, core::OrbitCamera& camera) {
    if (!drag)
        input.leftDown = input.middleDown = false;
    if (!wheel)
        input.scrollSteps = 0.0;
    const bool panning = input.middleDown || (input.leftDown && input.shiftDown);
    if (panning)
        camera.pan(static_cast<float>(input.dragDx), static_cast<float>(input.dragDy),
                   static_cast<float>(viewportHeight));
    else if (input.leftDown)
        camera.orbit(static_cast<float>(input.dragDx), static_cast<float>(input.dragDy));
    if (input.scrollSteps != 0.0)
        camera.zoom(static_cast<float>(input.scrollSteps));
    if (input.frameRequested)
        camera = core::frameBounds(scene.bounds, camera.fovYRad);
    // Keep the depth range proportional to the distance so zooming never clips the field.
    camera.nearPlane = std::max(camera.distance * 1e-3f, 1e-4f);
    camera.farPlane = camera.distance * 20.0f + 100.0f;
}

// The viewport rect (points, y down) in GL pixels (y up), at least one pixel.
struct PixelRect {
    int x = 0, y = 0, w = 1, h = 1;
};
PixelRect toPixels(ui::Rect r, float ppp, int framebufferHeight) {
    PixelRect p;
    p.x = int(std::lround(r.min.x * ppp));
    p.w = std::max(1, int(std::lround(r.max.x * ppp)) - p.x);
    const int top = int(std::lround(r.min.y * ppp));
    p.h = std::max(1, int(std::lround(r.max.y * ppp)) - top);
    p.y = framebufferHeight - top - p.h;
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    std::string projectPath = std::string(GRASS_SOURCE_DIR) + "/projects/meadow";
    std::string screenshot;
    int frames = 0;
    bool noPhysics = false;
    bool noUi = false;
    ArgParser parser("grass-editor [project-dir|project.json] [--screenshot F.png --frames N]",
                     "Opens the grass editor on a project (default: projects/meadow): a File "
                     "menu, a side panel with the layers, wind, colliders and render settings, "
                     "and the viewport. Drag to orbit, wheel to zoom, middle- or shift-drag to "
                     "pan, F to frame (Esc closes with --no-ui); keys 1-4 switch the "
                     "orientation, frustum, distance and occlusion culling, T cycles blades / "
                     "billboards / hybrid / growth (stem sets), L toggles the grass lighting.");
    parser.positional("project", "a project folder (with project.json) or a .json file",
                      &projectPath, false);
    parser.text("--screenshot", "FILE",
                "save what the window shows after --frames frames, then exit", &screenshot);
    parser.integer("--frames",
                   "frames to draw before the screenshot (with --screenshot: default 3)", &frames,
                   1, 100000);
    std::string scriptFile;
    parser.text("--script", "FILE",
                "replay recorded input (pointer, keys, waits, screenshots; see "
                "editor/app/input_script.h), one step of physics per frame, then exit",
                &scriptFile);
    double autosaveS = 180.0;
    parser.number("--autosave-s", "S",
                  "seconds between autosaves of unsaved changes to <project>.autosave.json (0: "
                  "never)",
                  &autosaveS, 0.0, 86400.0, "180");
    bool recover = false;
    parser.flag("--recover",
                "take back an autosave left by a session that did not close cleanly without "
                "asking (otherwise a window offers it)",
                &recover);
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
    parser.flag("--gl-debug", "print GL debug output (driver errors and warnings) to stderr",
                &glDebug);
    parser.flag("--no-physics",
                "show the field at rest (by default gravity, wind and colliders run live on the "
                "GPU, one physics step of the project's step_s per elapsed step, at most 4 per "
                "frame)",
                &noPhysics);
    parser.flag("--no-ui",
                "show the viewport alone over the whole window (what `grass render` draws; "
                "tests compare the two)",
                &noUi);
    if (auto parsed = parser.parse(std::vector<std::string>(argv + 1, argv + argc)); !parsed)
        return fail(parsed.error().str(), 2);
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    if (!screenshot.empty() && frames == 0)
        frames = 3;
    if (!screenshot.empty())
        if (auto writable = checkImageWritable(screenshot); !writable)
            return fail(writable.error().str(), 2);

    std::vector<editor::ScriptFrame> script;
    if (!scriptFile.empty()) {
        auto parsed = editor::loadInputScript(scriptFile);
        if (!parsed)
            return fail("--script: " + parsed.error().str(), 2);
        script = std::move(*parsed);
    }
    // Screenshots and scripts step the simulation once per frame, whatever the machine's speed.
    const bool replay = !screenshot.empty() || !scriptFile.empty();

    auto loaded = core::loadProject(projectPath);
    if (!loaded)
        return fail(loaded.error().str());
    editor::EditorState state;
    state.loaded = std::move(*loaded);
    const core::Project& project = state.loaded.project;

    auto window = editor::Window::create(project.render.width, project.render.height,
                                         "grass — " + project.name, glDebug);
    if (!window)
        return fail(window.error().message);
    auto camera = render::projectCamera(project, "");
    if (!camera)
        return fail(camera.error().str());
    auto built = editor::buildLive(state.loaded, !noPhysics);
    if (!built)
        return fail(built.error().str());
    editor::Live live = std::move(*built);
    state.scene = live.scene.get();
    state.tools = live.tools.get();
    state.softwareRenderer = gl::isSoftwareRenderer();
    state.options = editor::viewRenderOptions(state);
    editor::resetHistory(state);
    state.recoveryOffer = editor::findAutosave(state.loaded);
    state.recoverRequested = recover && state.recoveryOffer.has_value();
    const auto resetTimeline = [&] {
        state.timeline = core::timelineFor(state.loaded.project);
        // A minute at least, so an unkeyed scene does not restart its sway every few seconds.
        state.timeline.setRange(state.timeline.startS(),
                                std::max(state.timeline.endS(), state.timeline.startS() + 60.0));
        state.timeline.setLoop(true);
        state.timeline.play();
    };
    resetTimeline();
    std::fprintf(stderr, "grass-editor: %s, %zu blades, geometry %s\n",
                 gl::rendererDescription().c_str(), live.scene->totalBlades(),
                 render::geometryPathLabel(state.options.geometry));
    std::unique_ptr<editor::EditorUi> ui;
    if (!noUi) {
        auto created = editor::EditorUi::create();
        if (!created)
            return fail(created.error().str());
        ui = std::move(*created);
    }

    // Re-grows the live field from the open project (after an edit that needs it), keeping the
    // maps painted since the last save; on failure the old field stays.
    const auto regrowLive = [&] {
        auto next = editor::buildLive(state.loaded, !noPhysics, [&](core::Scene& grown) {
            return editor::carryPaintedMaps(state, *live.scene, grown);
        });
        if (!next) {
            state.message = "cannot grow the field: " + next.error().str();
            return;
        }
        const std::size_t steps = live.physics ? live.physics->steps : 0;
        live = std::move(*next);
        state.scene = live.scene.get();
        state.tools = live.tools.get();
        state.regrown.clear();
        if (live.physics)
            live.physics->steps = steps;  // the field restarts from rest, the clock goes on
    };
    // New, Open, Recover: the document is replaced only once its field is grown.
    const auto adoptDocument = [&](core::LoadedProject next, std::string_view what) {
        if (!editor::replaceDocument(state, live, std::move(next), !noPhysics, what))
            return false;
        if (auto cam = render::projectCamera(state.loaded.project, ""))
            *camera = *cam;
        resetTimeline();
        return true;
    };

    std::unique_ptr<gl::Framebuffer> target;
    int frame = 0;
    bool cameraDrag = false;  // a drag that began in the viewport stays the camera's
    bool toolDrag = false;    // a drag that began on a tool (brush, gizmo) stays the tool's
    std::string shownTitle;
    double autosaveDueS = autosaveS;
    const auto startTime = std::chrono::steady_clock::now();
    auto lastStatus = startTime;
    auto lastFrameEnd = startTime;
    double fps = 0.0;
    while (true) {
        if ((*window)->shouldClose()) {
            if (!ui || !state.dirty || replay) {
                // A clean close leaves nothing to recover (an autosave still on offer stays).
                if (!state.dirty && !state.recoveryOffer)
                    editor::removeAutosave(state.loaded);
                break;
            }
            (*window)->cancelClose();  // ask first
            editor::askQuit(state);
        }
        editor::InputState input = (*window)->pollInput();
        if (!scriptFile.empty()) {
            if (static_cast<std::size_t>(frame) >= script.size())
                break;
            input = script[static_cast<std::size_t>(frame)].input;
        }
        int width = 0, height = 0;
        (*window)->framebufferSize(&width, &height);
        if (width <= 0 || height <= 0)
            continue;  // minimised

        // The UI first: it decides who gets the pointer and the keys this frame.
        const auto uiStart = std::chrono::steady_clock::now();
        PixelRect view{0, 0, width, height};
        bool uiPointer = false, uiKeyboard = false;
        editor::ViewportPointer pointer;
        if (ui) {
            ui->beginFrame(**window, input,
                           std::chrono::duration<double>(uiStart - startTime).count());
            const ui::Rect central = editor::buildPanels(ui->context(), state);
            const float ppp = ui->pixelsPerPoint();
            const ui::Vec2 at = ui->context().pointerPos();
            pointer.pixel = glm::vec2(at.x - central.min.x, at.y - central.min.y) * ppp;
            pointer.viewportSize = glm::vec2(central.width(), central.height()) * ppp;
            pointer.inside = input.cursorInside && central.contains(at);
            editor::drawViewportOverlay(ui->context(), central, ppp, state, *camera, pointer);
            const ui::Output& out = ui->endFrame(**window);
            uiPointer = out.wantsPointer;
            uiKeyboard = out.wantsKeyboard;
            view = toPixels(central, out.pixelsPerPoint, height);
            state.status.uiMs = std::chrono::duration<double, std::milli>(
                                    std::chrono::steady_clock::now() - uiStart)
                                    .count();
        }
        // The viewport's tools: a press on the mesh (brush) or on an object (gizmo) makes the
        // drag theirs; the camera orbits with the right button meanwhile.
        bool toolUsed = false;
        if (ui) {
            pointer.inside = pointer.inside && !uiPointer && !cameraDrag;
            pointer.down = input.leftDown;
            pointer.pressed = input.leftPressed;
            pointer.released = !input.leftDown;
            pointer.ctrl = input.modifiers.ctrl;
            pointer.shift = input.modifiers.shift;
            pointer.pressure = input.pressure;
            toolUsed = editor::runViewportTool(state, *camera, pointer);
            if (toolUsed && pointer.pressed)
                toolDrag = true;
            if (!input.leftDown)
                toolDrag = false;
            if (toolDrag || state.toolDragActive)
                input.leftDown = false;
            if (state.tool != editor::ViewportTool::Camera && input.rightDown)
                input.leftDown = true;
        }
        const bool anyDown = input.leftDown || input.middleDown || input.rightDown;
        if (!ui || !anyDown)
            cameraDrag = anyDown && !toolUsed;
        else if (!cameraDrag && !uiPointer && !toolDrag && ui->context().activeId().value == 0)
            cameraDrag = true;
        applyInput(input, cameraDrag, !uiPointer, view.h, *live.scene, *camera);
        if (!uiKeyboard) {
            if (const std::string changed = applyRenderKeys(input, state); !changed.empty())
                std::fprintf(stderr, "grass-editor: %s\n", changed.c_str());
            editor::applyToolKeys(state, input.typed);
            for (const ui::KeyEvent& key : input.keys) {
                if (!key.modifiers.ctrl)
                    continue;
                if (key.key == ui::Key::Z)
                    key.modifiers.shift ? editor::redo(state) : editor::undo(state);
                else if (key.key == ui::Key::Y)
                    editor::redo(state);
                else if (key.key == ui::Key::S && ui) {
                    if (state.loaded.file.empty())
                        state.fileDialog = editor::FileDialog::SaveAs;
                    else
                        editor::saveTo(state, state.loaded.file.string());
                }
            }
            // With the UI, Escape belongs to it (closing popups and text edits): one press
            // must not also quit. File → Quit and the window's close button remain.
            if (input.escapePressed && !ui)
                (*window)->requestClose();
        }
        editor::recordProjectEdit(state, ui && ui->context().activeId().value != 0);

        // What the panels asked for. Quitting (after saving, or choosing to drop the changes)
        // leaves nothing to recover.
        if (state.quitRequested) {
            if (!state.recoveryOffer)
                editor::removeAutosave(state.loaded);
            break;
        }
        // An export reads the scene on its worker: replacing or re-growing it waits.
        if (state.newRequested && !state.busy()) {
            state.newRequested = false;
            if (adoptDocument(core::LoadedProject{core::Project{}, std::filesystem::current_path(), {}},
                        "cannot start a new project")) {
                state.dirty = true;  // exists only in memory until saved
                state.message = "new project (not saved)";
            }
        }
        if (!state.openRequested.empty() && !state.busy()) {
            auto opened = core::loadProject(state.openRequested);
            state.openRequested.clear();
            if (!opened) {
                state.message = "cannot open: " + opened.error().str();
            } else if (adoptDocument(std::move(*opened), "cannot open")) {
                state.dirty = false;
                state.message = "opened " + state.loaded.file.string();
            }
        }
        if (state.recoverRequested && !state.busy()) {
            state.recoverRequested = false;
            core::LoadedProject recovered = std::move(*state.recoveryOffer);
            state.recoveryOffer.reset();
            if (adoptDocument(std::move(recovered), "cannot recover the autosave"))
                editor::markRecoveredMaps(state);
        }
        // Re-grow once the edit has ended, not on every frame of a drag.
        if (state.rebuildPending && !state.toolDragActive && !state.busy() &&
            (!ui || ui->context().activeId().value == 0)) {
            state.rebuildPending = false;
            regrowLive();
        }
        // Patches the brush or an undo re-grew: only those go up to the GPU.
        for (const auto& [layer, report] : state.regrown) {
            live.renderer->uploadRegrown(layer, report);
            if (live.physics)
                live.physics->gpu.uploadRegrown(layer, *live.scene, report.patches);
        }
        state.regrown.clear();
        // Autosave on the simulation's clock when replaying, so scripts see it at a fixed frame.
        autosaveDueS -=
            replay ? state.timeline.stepS()
                   : std::chrono::duration<double>(std::chrono::steady_clock::now() - lastFrameEnd)
                         .count();
        if (autosaveS > 0.0 && autosaveDueS <= 0.0 && state.dirty && !state.busy() &&
            !state.toolDragActive) {
            autosaveDueS = autosaveS;
            editor::autosaveNow(state);
        }
        const std::string title =
            "grass — " + state.loaded.project.name + (state.dirty ? " *" : "");
        if (title != shownTitle) {
            (*window)->setTitle(title);
            shownTitle = title;
        }

        if (!target || target->width() != view.w || target->height() != view.h)
            target = std::make_unique<gl::Framebuffer>(view.w, view.h,
                                                       state.loaded.project.render.msaaSamples);
        const auto start = std::chrono::steady_clock::now();
        // This frame's picture follows the project as it is now, with the view's overrides.
        state.options = editor::viewRenderOptions(state);
        {
            // Screenshots advance exactly one step per frame, so they do not depend on
            // machine speed.
            const double elapsedS =
                !replay ? std::chrono::duration<double>(start - lastFrameEnd).count()
                        : state.timeline.stepS();
            const core::TimeUpdate moved = state.timeline.advance(elapsedS);
            const bool jumped = state.timeJump.needsReset() || moved.needsReset() ||
                                state.timeJump.change == core::TimeChange::JumpForward;
            state.timeJump = {};
            if (live.physics) {
                editor::LivePhysics& physics = *live.physics;
                if (jumped) {
                    // The field restarts from rest at the new time (re-simulating from the
                    // start would stall the scrub).
                    if (auto reset = editor::resetPhysics(live); !reset)
                        state.message = "cannot reset the simulation: " + reset.error().str();
                    physics.steps = static_cast<std::size_t>(
                        std::floor(state.timeline.timeS() / physics.scene.params.dtS));
                }
                physics.advanceTo(state.timeline.timeS());
            }
        }
        state.options.timeS = static_cast<float>(state.timeline.timeS());
        // Statistics cost atomics and a wait when read: only the frame before a status update
        // collects them, and they are read once, after it.
        const bool statusDue = frame == 0 || std::chrono::steady_clock::now() - lastStatus >
                                                 std::chrono::milliseconds(500);
        state.options.cull.collectStats = statusDue;
        live.renderer->render(*camera, view.w, view.h, target->id(), state.options);
        if (ui) {
            // The panels cover the rest; clear it so nothing stale shows through at the edges.
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glDisable(GL_SCISSOR_TEST);
            glClearColor(0.106f, 0.106f, 0.106f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            // A multisampled blit may move the rectangle but not scale it: sizes match here.
            glBlitNamedFramebuffer(target->id(), 0, 0, 0, view.w, view.h, view.x, view.y,
                                   view.x + view.w, view.y + view.h, GL_COLOR_BUFFER_BIT,
                                   GL_NEAREST);
            ui->draw(width, height);
        } else {
            target->blitTo(0, width, height);
        }
        if (!state.screenshotRequested.empty()) {
            const gl::Rgba8Image shown = gl::readFramebuffer(0, width, height);
            const auto written =
                writeRgba8Image(state.screenshotRequested, shown.width, shown.height, shown.pixels);
            state.message = written ? "saved " + state.screenshotRequested
                                    : "screenshot not saved: " + written.error().str();
            state.screenshotRequested.clear();
        }
        if (!state.turntableRequested.empty()) {
            // The views show the field as grown (at rest), from the viewport's camera and size.
            render::OffscreenRequest request;
            request.width = view.w;
            request.height = view.h;
            request.frames = 1;
            request.options = state.options;
            auto turned = render::writeTurntable(*live.scene, *camera, request, TURNTABLE_VIEWS,
                                                 state.turntableRequested);
            state.message = turned
                                ? "saved a turntable of " + std::to_string(turned->framesWritten) +
                                      " views: " + turned->sheet.string()
                                : "turntable not saved: " + turned.error().str();
            state.turntableRequested.clear();
        }
        if (!scriptFile.empty() && !script[static_cast<std::size_t>(frame)].screenshot.empty()) {
            const std::string& shot = script[static_cast<std::size_t>(frame)].screenshot;
            const gl::Rgba8Image shown = gl::readFramebuffer(0, width, height);
            if (auto written = writeRgba8Image(shot, shown.width, shown.height, shown.pixels);
                !written)
                return fail(written.error().str());
            std::printf("wrote %s (%dx%d) at frame %d\n", shot.c_str(), width, height, frame + 1);
        }
        ++frame;
        if (!screenshot.empty() && frame >= frames) {
            const gl::Rgba8Image shown = gl::readFramebuffer(0, width, height);
            if (auto written = writeRgba8Image(screenshot, shown.width, shown.height, shown.pixels);
                !written)
                return fail(written.error().str());
            std::printf("wrote %s (%dx%d) after %d frames\n", screenshot.c_str(), width, height,
                        frame);
            return 0;
        }
        (*window)->swapBuffers();
        const auto now = std::chrono::steady_clock::now();
        const double frameS = std::chrono::duration<double>(now - lastFrameEnd).count();
        lastFrameEnd = now;
        // Smoothed, so the number stays readable.
        if (frameS > 0.0)
            fps = fps == 0.0 ? 1.0 / frameS : 0.9 * fps + 0.1 / frameS;
        state.status.blades = live.scene->totalBlades();  // live: a re-grow shows at once
        if (statusDue) {
            state.status.timings = live.renderer->lastTimings();
            state.status.fps = fps;
            lastStatus = now;
        }
    }
    return 0;
}
