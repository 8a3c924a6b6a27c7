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
#include <memory>
#include <optional>

#include <epoxy/gl.h>

#include "editor_ui.h"
#include "framebuffer.h"
#include "headless_context.h"
#include "offscreen_render.h"
#include "scene/scene_physics.h"
#include "scene_physics_gpu.h"
#include "scene_renderer.h"
#include "util/arg_parser.h"
#include "util/image_file.h"
#include "panels.h"
#include "window.h"

namespace {

using namespace grass;

int fail(const std::string& message, int code = 1) {
    std::fprintf(stderr, "grass-editor: %s\n", message.c_str());
    return code;
}

// Keys that change how the field is drawn (window.h); returns what changed, for the console.
std::string applyRenderKeys(const editor::InputState& input, render::RenderOptions& options) {
    render::CullSettings& cull = options.cull;
    bool* tests[] = {&cull.orientation, &cull.frustum, &cull.distance, &cull.occlusion};
    const char* names[] = {"orientation", "frustum", "distance", "occlusion"};
    if (input.toggledCullTest >= 1 && input.toggledCullTest <= 4) {
        bool& test = *tests[input.toggledCullTest - 1];
        test = !test;
        return std::string(names[input.toggledCullTest - 1]) + " culling " + (test ? "on" : "off");
    }
    if (input.nextTechnique) {
        options.technique =
            static_cast<core::GrassTechnique>((static_cast<int>(options.technique) + 1) % 4);
        return "technique " + std::string(core::grassTechniqueName(options.technique));
    }
    if (input.toggleLighting) {
        options.lighting.model = options.lighting.model == core::LightingModel::Grass
                                     ? core::LightingModel::Simple
                                     : core::LightingModel::Grass;
        return options.lighting.model == core::LightingModel::Grass ? "grass lighting"
                                                                     : "simple lighting";
    }
    return {};
}

void applyInput(editor::InputState input, bool drag, bool wheel, int viewportHeight,
                const core::Scene& scene,
                core::OrbitCamera& camera) {
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

// Physics stepping the renderer's blade buffers on the GPU in fixed steps of the project's
// step_s, catching up with wall time but never more than MAX_STEPS_PER_FRAME per frame (a slow
// device runs the simulation slower than real time instead of falling further behind).
struct LivePhysics {
    static constexpr int MAX_STEPS_PER_FRAME = 4;
    core::ScenePhysics scene;
    render::ScenePhysicsGpu gpu;
    double owedS = 0.0;
    std::size_t steps = 0;
    std::chrono::steady_clock::time_point lastFrame = std::chrono::steady_clock::now();

    void advance(double elapsedS) {
        const double dtS = scene.params.dtS;
        owedS = std::min(owedS + elapsedS, dtS * MAX_STEPS_PER_FRAME);
        while (owedS >= dtS * (1.0 - 1e-6)) {
            gpu.step(scene, static_cast<float>(static_cast<double>(steps) * dtS));
            ++steps;
            owedS -= dtS;
        }
    }
};

// What a project becomes on the GPU; rebuilt whole when the project is re-grown or replaced.
// Members are destroyed in reverse order: the physics (which steps the renderer's buffers)
// before the renderer, the renderer (which points at the scene) before the scene.
struct Live {
    std::unique_ptr<core::Scene> scene;
    std::unique_ptr<render::SceneRenderer> renderer;
    std::optional<LivePhysics> physics;
};

Result<Live> buildLive(const core::LoadedProject& loaded, bool withPhysics) {
    auto scene = core::buildScene(loaded);
    if (!scene)
        return scene.error();
    for (const auto& note : scene->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    Live live;
    live.scene = std::make_unique<core::Scene>(std::move(*scene));
    auto renderer = render::SceneRenderer::create(*live.scene);
    if (!renderer)
        return renderer.error();
    live.renderer = std::move(*renderer);
    if (withPhysics) {
        auto built = core::buildScenePhysics(loaded);
        if (!built)
            return built.error();
        for (const auto& note : built->notes)
            std::fprintf(stderr, "note: %s\n", note.c_str());
        auto gpu = render::ScenePhysicsGpu::createOn(*live.scene, live.renderer->bladeBuffers());
        if (!gpu)
            return gpu.error();
        live.physics.emplace(LivePhysics{std::move(*built), std::move(*gpu)});
    }
    return live;
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

    auto loaded = core::loadProject(projectPath);
    if (!loaded)
        return fail(loaded.error().str());
    editor::EditorState state;
    state.loaded = std::move(*loaded);
    const core::Project& project = state.loaded.project;

    auto window = editor::Window::create(project.render.width, project.render.height,
                                         "grass — " + project.name);
    if (!window)
        return fail(window.error().message);
    auto camera = render::projectCamera(project, "");
    if (!camera)
        return fail(camera.error().str());
    auto built = buildLive(state.loaded, !noPhysics);
    if (!built)
        return fail(built.error().str());
    Live live = std::move(*built);
    state.scene = live.scene.get();
    state.options = render::renderOptionsFor(project, gl::isSoftwareRenderer());
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

    // Replaces the live field (New, Open, re-grow); on failure the old one stays.
    const auto rebuild = [&](bool resetCamera) {
        auto next = buildLive(state.loaded, !noPhysics);
        if (!next) {
            state.message = "cannot grow the field: " + next.error().str();
            return;
        }
        live = std::move(*next);
        state.scene = live.scene.get();
        if (resetCamera) {
            if (auto cam = render::projectCamera(state.loaded.project, ""))
                *camera = *cam;
            state.options = render::renderOptionsFor(state.loaded.project,
                                                     gl::isSoftwareRenderer());
            (*window)->setTitle("grass — " + state.loaded.project.name);
        }
    };

    std::unique_ptr<gl::Framebuffer> target;
    int frame = 0;
    bool cameraDrag = false;  // a drag that began in the viewport stays the camera's
    const auto startTime = std::chrono::steady_clock::now();
    auto lastStatus = startTime;
    auto lastFrameEnd = startTime;
    double fps = 0.0;
    while (true) {
        if ((*window)->shouldClose()) {
            if (!ui || !state.dirty || !screenshot.empty())
                break;
            (*window)->cancelClose();  // ask first
            editor::askQuit(state);
        }
        editor::InputState input = (*window)->pollInput();
        int width = 0, height = 0;
        (*window)->framebufferSize(&width, &height);
        if (width <= 0 || height <= 0)
            continue;  // minimised

        // The UI first: it decides who gets the pointer and the keys this frame.
        const auto uiStart = std::chrono::steady_clock::now();
        PixelRect view{0, 0, width, height};
        bool uiPointer = false, uiKeyboard = false;
        if (ui) {
            ui->beginFrame(**window, input,
                           std::chrono::duration<double>(uiStart - startTime).count());
            const ui::Rect central = editor::buildPanels(ui->context(), state);
            const ui::Output& out = ui->endFrame(**window);
            uiPointer = out.wantsPointer;
            uiKeyboard = out.wantsKeyboard;
            view = toPixels(central, out.pixelsPerPoint, height);
            state.status.uiMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                          uiStart)
                    .count();
        }
        const bool anyDown = input.leftDown || input.middleDown || input.rightDown;
        if (!ui || !anyDown)
            cameraDrag = anyDown;
        else if (!cameraDrag && !uiPointer && ui->context().activeId().value == 0)
            cameraDrag = true;
        applyInput(input, cameraDrag, !uiPointer, view.h, *live.scene, *camera);
        if (!uiKeyboard) {
            if (const std::string changed = applyRenderKeys(input, state.options);
                !changed.empty())
                std::fprintf(stderr, "grass-editor: %s\n", changed.c_str());
            // With the UI, Escape belongs to it (closing popups and text edits): one press
            // must not also quit. File → Quit and the window's close button remain.
            if (input.escapePressed && !ui)
                (*window)->requestClose();
        }

        // What the panels asked for.
        if (state.quitRequested)
            break;
        if (state.newRequested) {
            state.newRequested = false;
            state.loaded = core::LoadedProject{core::Project{}, std::filesystem::current_path(),
                                               {}};
            state.dirty = true;  // exists only in memory until saved
            state.message = "new project (not saved)";
            rebuild(true);
        }
        if (!state.openRequested.empty()) {
            auto opened = core::loadProject(state.openRequested);
            state.openRequested.clear();
            if (!opened) {
                state.message = "cannot open: " + opened.error().str();
            } else {
                state.loaded = std::move(*opened);
                state.dirty = false;
                state.message = "opened " + state.loaded.file.string();
                rebuild(true);
            }
        }
        // Re-grow once the edit has ended, not on every frame of a drag.
        if (state.rebuildPending && (!ui || ui->context().activeId().value == 0)) {
            state.rebuildPending = false;
            rebuild(false);
        }

        if (!target || target->width() != view.w || target->height() != view.h)
            target = std::make_unique<gl::Framebuffer>(view.w, view.h,
                                                       state.loaded.project.render.msaaSamples);
        const auto start = std::chrono::steady_clock::now();
        if (live.physics) {
            // Screenshots step exactly once per frame, so they do not depend on machine speed.
            LivePhysics& physics = *live.physics;
            const double elapsedS =
                screenshot.empty()
                    ? std::chrono::duration<double>(start - physics.lastFrame).count()
                    : physics.scene.params.dtS;
            physics.advance(elapsedS);
            physics.lastFrame = start;
            state.options.timeS = static_cast<float>(static_cast<double>(physics.steps) *
                                                     physics.scene.params.dtS);
        }
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
