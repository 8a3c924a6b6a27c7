// grass-editor: the authoring window. This first version shows the project's mesh and grass
// in a viewport with an orbit camera: drag to orbit, wheel to zoom, middle- or shift-drag to
// pan, F to frame the scene, Esc to close; 1–4 switch the cull tests, T the technique (blades,
// billboards, hybrid, growth), L the lighting, and the title shows the cull counts and pass
// times twice a second. --screenshot saves what the window shows after --frames frames and
// exits, so tests and users can see the editor without a person.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>

#include "framebuffer.h"
#include "headless_context.h"
#include "offscreen_render.h"
#include "scene/scene_physics.h"
#include "scene_physics_gpu.h"
#include "scene_renderer.h"
#include "util/arg_parser.h"
#include "util/image_file.h"
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

void applyInput(const editor::InputState& input, int viewportHeight, const core::Scene& scene,
                core::OrbitCamera& camera) {
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

}  // namespace

int main(int argc, char** argv) {
    std::string projectPath = std::string(GRASS_SOURCE_DIR) + "/projects/meadow";
    std::string screenshot;
    int frames = 0;
    bool noPhysics = false;
    ArgParser parser("grass-editor [project-dir|project.json] [--screenshot F.png --frames N]",
                     "Opens the grass editor on a project (default: projects/meadow). Drag "
                     "to orbit, wheel to zoom, middle- or shift-drag to pan, F to frame, Esc "
                     "to close; keys 1-4 switch the orientation, frustum, distance and occlusion "
                     "culling, T cycles blades / billboards / hybrid / growth (stem sets), L "
                     "toggles the grass lighting; the title shows cull counts and pass times.");
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
    auto scene = core::buildScene(*loaded);
    if (!scene)
        return fail(scene.error().str());
    for (const auto& note : scene->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    const core::Project& project = loaded->project;

    auto window = editor::Window::create(project.render.width, project.render.height,
                                         "grass — " + project.name);
    if (!window)
        return fail(window.error().message);
    auto camera = render::projectCamera(project, "");
    if (!camera)
        return fail(camera.error().str());
    auto renderer = render::SceneRenderer::create(*scene);
    if (!renderer)
        return fail(renderer.error().str());
    render::RenderOptions options =
        render::renderOptionsFor(project, gl::isSoftwareRenderer());
    std::fprintf(stderr, "grass-editor: %s, %zu blades, geometry %s\n",
                 gl::rendererDescription().c_str(), scene->totalBlades(),
                 render::geometryPathLabel(options.geometry));

    std::optional<LivePhysics> physics;
    if (!noPhysics) {
        auto built = core::buildScenePhysics(*loaded);
        if (!built)
            return fail(built.error().str());
        for (const auto& note : built->notes)
            std::fprintf(stderr, "note: %s\n", note.c_str());
        auto gpu = render::ScenePhysicsGpu::createOn(*scene, (*renderer)->bladeBuffers());
        if (!gpu)
            return fail(gpu.error().str());
        physics.emplace(LivePhysics{std::move(*built), std::move(*gpu)});
    }

    std::unique_ptr<gl::Framebuffer> target;
    int frame = 0;
    auto lastTitle = std::chrono::steady_clock::now();
    while (!(*window)->shouldClose()) {
        const editor::InputState input = (*window)->pollInput();
        int width = 0, height = 0;
        (*window)->framebufferSize(&width, &height);
        if (width <= 0 || height <= 0)
            continue;  // minimised
        applyInput(input, height, *scene, *camera);
        if (const std::string changed = applyRenderKeys(input, options); !changed.empty())
            std::fprintf(stderr, "grass-editor: %s\n", changed.c_str());
        if (!target || target->width() != width || target->height() != height)
            target = std::make_unique<gl::Framebuffer>(width, height, project.render.msaaSamples);
        const auto start = std::chrono::steady_clock::now();
        if (physics) {
            // Screenshots step exactly once per frame, so they do not depend on machine speed.
            const double elapsedS =
                screenshot.empty()
                    ? std::chrono::duration<double>(start - physics->lastFrame).count()
                    : physics->scene.params.dtS;
            physics->advance(elapsedS);
            physics->lastFrame = start;
            options.timeS = static_cast<float>(static_cast<double>(physics->steps) *
                                               physics->scene.params.dtS);
        }
        // Statistics cost atomics and a wait when read: only the frame before a title update
        // collects them, and they are read once, after it.
        const bool titleDue =
            std::chrono::steady_clock::now() - lastTitle > std::chrono::milliseconds(500);
        options.cull.collectStats = titleDue;
        (*renderer)->render(*camera, width, height, target->id(), options);
        target->blitTo(0, width, height);
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
        if (titleDue) {
            const render::FrameTimings timings = (*renderer)->lastTimings();
            const double cpuMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            const render::CullStats& c = timings.cull;
            char title[512];
            std::snprintf(title, sizeof title,
                          "grass — %s — %zu in, %zu drawn (culled patch %zu, orient %zu, frustum "
                          "%zu, dist %zu, occl %zu) — frame %.1f ms: cull %.1f, opaque %.1f, "
                          "grass %.1f, billboards %.1f",
                          project.name.c_str(), c.bladesIn, c.drawn, c.culledPatch,
                          c.culledOrientation, c.culledFrustum, c.culledDistance,
                          c.culledOcclusion, cpuMs, timings.cullMs, timings.meshMs,
                          timings.grassMs, timings.billboardMs);
            (*window)->setTitle(title);
            lastTitle = std::chrono::steady_clock::now();
        }
    }
    return 0;
}
