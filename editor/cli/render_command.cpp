// grass render: grow and render a project (or any glTF mesh) headless to an image file.
#include <cstdio>
#include <filesystem>

#include "cli/commands.h"
#include "cli/preset_option.h"
#include "cli/render_options.h"
#include "cli/render_report.h"
#include "cli/simulation_runner.h"
#include "gl/headless_context.h"
#include "mesh/gltf_loader.h"
#include "physics/step_count.h"
#include "project/project_inputs.h"
#include "render/offscreen_render.h"
#include "render/turntable_files.h"
#include "scene/scene_physics.h"
#include "tools/ms_since.h"
#include "util/byte_size.h"
#include "util/image_file.h"
#include "util/interrupt_stop.h"
#include "util/path_inside.h"

namespace grass::cli {

namespace {

using tools::Clock;
using tools::msSince;

// The frame buffers of the image asked for (--width/--height/--msaa over the project's) must fit
// core::MAX_FRAMEBUFFER_BYTES: refused before the scene is grown or a GL context is made.
Result<void> checkFramebuffer(const RenderArgs& args, const core::RenderSettings& settings) {
    const FrameSize size = frameSize(args, settings);
    const double bytes = core::framebufferBytes(size.width, size.height, size.samples);
    if (bytes <= core::MAX_FRAMEBUFFER_BYTES)
        return {};
    return makeError("--width/--height/--msaa",
                     std::to_string(size.width) + "×" + std::to_string(size.height) + " at " +
                         std::to_string(size.samples) + " samples needs " + byteSizeText(bytes) +
                         " of frame buffers; the limit is " +
                         byteSizeText(core::MAX_FRAMEBUFFER_BYTES) +
                         ": lower the size or the samples");
}

// Refuses, before any work, an --out or --stats that is one of the files read.
Result<void> refuseOutputsOverInputs(const RenderArgs& args,
                                     const std::vector<core::ProjectInput>& inputs) {
    for (const auto& [option, file] : {std::pair{"--out", &args.out}, {"--stats", &args.stats}})
        if (!file->empty())
            if (auto refused = core::refuseOverwritingInput(inputs, *file, option); !refused)
                return refused;
    return {};
}

// --mesh: a default project around the glTF file, grown to about --blades blades.
// --technique draws the scene, and the scene places the billboards only for a technique that
// draws them (core::placeBillboards): the project is grown with the technique it is drawn with.
void applyTechniqueOption(const RenderArgs& args, core::Project& project) {
    if (args.technique == "project")
        return;
    if (auto technique = core::parseGrassTechnique(args.technique))
        project.render.technique = *technique;
}

Result<core::LoadedProject> loadMeshInput(const RenderArgs& args, core::Scene* scene) {
    std::vector<core::ProjectInput> inputs{{realPath(args.mesh), args.mesh, "--mesh file"}};
    for (const auto& part : core::gltfExternalFiles(args.mesh))
        inputs.push_back({realPath(part), part, "--mesh file's " + part.filename().string()});
    if (auto refused = refuseOutputsOverInputs(args, inputs); !refused)
        return refused.error();
    // Checked by checkRenderArgs.
    const float metresPerUnit = core::parseMeshUnit(args.unit).value();
    const core::UpAxis up = core::parseUpAxis(args.up).value();
    const auto progress = buildProgressNotes();
    progress("reading " + std::filesystem::path(args.mesh).filename().string());
    auto imported = core::loadGltf(args.mesh, core::GltfPlacement::GroundNearOrigin, metresPerUnit);
    if (!imported)
        return imported.error();
    core::applyMeshFrame(imported->mesh, metresPerUnit, up);
    auto loaded = core::projectForMesh(args.mesh, imported->mesh,
                                       static_cast<std::size_t>(args.blades), &imported->notes);
    if (!loaded)
        return loaded.error();
    loaded->project.mesh.metresPerUnit = metresPerUnit;
    loaded->project.mesh.up = up;
    applyPresetOption(args.preset, loaded->project);
    applyTechniqueOption(args, loaded->project);
    if (auto fits = checkFramebuffer(args, loaded->project.render); !fits)
        return fits.error();
    std::vector<std::string> notes;
    for (auto& note : imported->notes)
        notes.push_back(args.mesh + ": " + note);
    core::SurfaceLook look = core::surfaceLookOf(args.mesh, imported->hasUv);
    notes.insert(notes.end(), look.notes.begin(), look.notes.end());
    auto built = core::buildSceneFromMesh(*loaded, std::move(imported->mesh), std::move(notes),
                                          glm::dvec3(0.0), {}, progress);
    if (built)
        built->look = std::move(look);
    if (!built)
        return built.error();
    *scene = std::move(*built);
    return loaded;
}

// A project, with the command line's seed and preset, its default --out named after it.
Result<core::LoadedProject> loadProjectInput(RenderArgs& args, core::Scene* scene) {
    auto loaded = core::loadProject(args.project);
    if (!loaded)
        return loaded.error();
    if (args.out.empty())
        args.out = core::fileSafeName(loaded->project.name) + ".png";
    if (auto steps = core::simulationSteps(args.timeS, loaded->project.physics.dtS, "--time");
        !steps)
        return steps.error();
    if (auto refused = refuseOutputsOverInputs(args, core::projectInputFiles(*loaded)); !refused)
        return refused.error();
    if (args.seedGiven)
        loaded->project.seed = args.seed;
    applyPresetOption(args.preset, loaded->project);
    applyTechniqueOption(args, loaded->project);
    if (auto fits = checkFramebuffer(args, loaded->project.render); !fits)
        return fits.error();
    auto built = core::buildScene(*loaded, nullptr, {}, buildProgressNotes());
    if (!built)
        return built.error();
    *scene = std::move(*built);
    return loaded;
}

// `--time`: the field as it is after T seconds of the project's physics. Returns ms per step
// (0 without --time).
Result<double> simulateBeforeRender(const RenderArgs& args, const core::LoadedProject& loaded,
                                    core::Scene& scene) {
    if (!(args.timeS > 0.0))
        return 0.0;
    // Cut blades have grown back for T seconds (issue 30 item 10) before the physics takes them.
    for (core::LayerField& layer : scene.layers)
        (void)core::regrowCut(layer, static_cast<float>(args.timeS));
    auto physics = core::buildScenePhysics(loaded, scene.groundOrigin);
    if (!physics)
        return physics.error();
    printNotes(physics->notes);
    core::SceneSimulation simulation(scene, std::move(*physics));
    const SimBackend backend = args.backend == "cpu" ? SimBackend::Cpu : SimBackend::Gpu;
    auto run = runSimulation(scene, simulation, args.timeS, backend, "render");
    if (!run)
        return run.error();
    std::printf(
        "simulated  %.3f s in %zu steps on the %s, %.2f ms/step; tips moved %.3g m on "
        "average, %.2f %% crushed\n",
        static_cast<double>(simulation.timeS()), run->steps, args.backend.c_str(), run->msPerStep,
        run->health.meanTipDisplacementM(), 100.0 * run->health.crushedShare());
    return run->msPerStep;
}

// `--turntable N`: the views and their sheet (turntable_files.h); --stats gets the last view.
int finishTurntable(const RenderArgs& args, const core::Scene& scene,
                    const core::OrbitCamera& camera, const render::OffscreenRequest& request,
                    double physicsMsPerStep) {
    // Ctrl+C ends the turn after the view under way; the sheet holds the views done.
    const core::InterruptStop interrupt;
    auto run =
        render::writeTurntable(scene, camera, request, args.turntable, args.out, interrupt.token());
    if (!run)
        return reportFailure("render", run.error(), EXIT_FAILED);
    const int done = interrupt.exitCodeOr(0);
    if (args.stats.empty())
        return done;
    if (auto written = writeStats(args.stats, run->last, physicsMsPerStep, run->lastWallMs,
                                  args.timeS > 0.0 ? args.backend : "none");
        !written)
        return reportFailure("render", written.error(), EXIT_FAILED);
    return done;
}

// One image: rendered, written, summed up; --stats gets the last frame.
int finishImage(const RenderArgs& args, const core::Scene& scene, const core::OrbitCamera& camera,
                const render::OffscreenRequest& request, double buildMs, double physicsMsPerStep) {
    auto rendered = render::renderOffscreen(scene, camera, request);
    if (!rendered)
        return reportFailure("render", rendered.error(), EXIT_FAILED);
    if (auto written = writeRgba8Image(args.out, rendered->image.width, rendered->image.height,
                                       rendered->image.pixels);
        !written)
        return reportFailure("render", written.error(), EXIT_FAILED);
    printRenderSummary(args.out, scene, buildMs, request, *rendered);
    if (args.stats.empty())
        return 0;
    if (auto written = writeStats(args.stats, rendered->lastFrame, physicsMsPerStep,
                                  rendered->frameWallMs.back(),
                                  args.timeS > 0.0 ? args.backend : "none");
        !written)
        return reportFailure("render", written.error(), EXIT_FAILED);
    return 0;
}

}  // namespace

int runRender(const std::vector<std::string>& argv) {
    RenderArgs args;
    if (const auto exitCode = parseRenderArgs(argv, args))
        return *exitCode;
    const auto cullTests = checkRenderArgs(args);
    if (!cullTests)
        return reportFailure("render", cullTests.error(), EXIT_USAGE);

    const auto buildStart = Clock::now();
    core::Scene scene;
    auto loaded = args.mesh.empty() ? loadProjectInput(args, &scene) : loadMeshInput(args, &scene);
    if (!loaded)
        return reportFailure("render", loaded.error(), EXIT_FAILED);
    const double buildMs = msSince(buildStart);
    printNotes(scene.notes);
    const core::Project& project = loaded->project;
    auto camera = render::projectCamera(project, args.camera);
    if (!camera)
        return reportFailure("render", camera.error(), EXIT_USAGE);
    if (args.out.empty())
        args.out = core::fileSafeName(project.name) + ".png";

    auto context = gl::HeadlessContext::create(args.glDebug);
    if (!context)
        return reportFailure("render", context.error(), EXIT_FAILED);
    // Physics where it is fastest (docs/physics.md): the CPU on software GL.
    if (args.backend == "auto")
        args.backend = gl::isSoftwareRenderer() ? "cpu" : "gpu";
    const auto physicsMsPerStep = simulateBeforeRender(args, *loaded, scene);
    if (!physicsMsPerStep)
        return reportFailure("render", physicsMsPerStep.error(), EXIT_FAILED);
    const render::OffscreenRequest request = offscreenRequest(args, project, *cullTests);
    if (args.turntable > 0)
        return finishTurntable(args, scene, *camera, request, *physicsMsPerStep);
    return finishImage(args, scene, *camera, request, buildMs, *physicsMsPerStep);
}

}  // namespace grass::cli
