// grass render: grow and render a project (or any glTF mesh) headless to an image file.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/commands.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "mesh/gltf_loader.h"
#include "render/offscreen_render.h"
#include "physics/step_count.h"
#include "cli/preset_option.h"
#include "project/project_inputs.h"
#include "scene/scene_physics.h"
#include "scene/turntable.h"
#include "cli/simulation_runner.h"
#include "render/turntable_files.h"
#include "util/arg_parser.h"
#include "util/atomic_file.h"
#include "util/byte_size.h"
#include "util/image_file.h"
#include "util/path_inside.h"

namespace grass::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct RenderArgs {
    std::string project, mesh, out, camera, geometry = "project", msaa = "project";
    std::string backend = "gpu", shape = "project";
    std::string cull = "all", stats, lighting = "project", technique = "project",
                animation = "project", preset = "project";
    double timeS = 0.0;
    double lodDistanceM = render::CullSettings{}.lodDistanceM;
    int width = 0, height = 0, frames = 3, blades = 60000, turntable = 0;
    std::uint64_t seed = 0;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
    bool lightPerVertex = false;
    bool snow = false;
};

// The frame buffers of the image asked for (--width/--height/--msaa over the project's) must fit
// core::MAX_FRAMEBUFFER_BYTES: refused before the scene is grown or a GL context is made.
Result<void> checkFramebuffer(const RenderArgs& args, const core::RenderSettings& settings) {
    const int width = args.width > 0 ? args.width : settings.width;
    const int height = args.height > 0 ? args.height : settings.height;
    const int samples = args.msaa == "project" ? settings.msaaSamples : std::stoi(args.msaa);
    const double bytes = core::framebufferBytes(width, height, samples);
    if (bytes <= core::MAX_FRAMEBUFFER_BYTES)
        return {};
    return makeError(
        "--width/--height/--msaa",
        std::to_string(width) + "×" + std::to_string(height) + " at " + std::to_string(samples) +
            " samples needs " + byteSizeText(bytes) + " of frame buffers; the limit is " +
            byteSizeText(core::MAX_FRAMEBUFFER_BYTES) + ": lower the size or the samples");
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

Result<core::LoadedProject> loadInput(RenderArgs& args, const ArgParser& parser,
                                      core::Scene* scene) {
    if (!args.mesh.empty()) {
        std::vector<core::ProjectInput> inputs{{realPath(args.mesh), args.mesh, "--mesh file"}};
        for (const auto& part : core::gltfExternalFiles(args.mesh))
            inputs.push_back({realPath(part), part, "--mesh file's " + part.filename().string()});
        if (auto refused = refuseOutputsOverInputs(args, inputs); !refused)
            return refused.error();
        auto imported = core::loadGltf(args.mesh);
        if (!imported)
            return imported.error();
        auto loaded =
            core::projectForMesh(args.mesh, imported->mesh, static_cast<std::size_t>(args.blades));
        if (!loaded)
            return loaded.error();
        applyPresetOption(args.preset, loaded->project);
        if (auto fits = checkFramebuffer(args, loaded->project.render); !fits)
            return fits.error();
        std::vector<std::string> notes;
        for (auto& note : imported->notes)
            notes.push_back(args.mesh + ": " + note);
        auto built = core::buildSceneFromMesh(*loaded, std::move(imported->mesh), std::move(notes));
        if (!built)
            return built.error();
        *scene = std::move(*built);
        return loaded;
    }
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
    if (parser.given("--seed"))
        loaded->project.seed = args.seed;
    applyPresetOption(args.preset, loaded->project);
    if (auto fits = checkFramebuffer(args, loaded->project.render); !fits)
        return fits.error();
    auto built = core::buildScene(*loaded);
    if (!built)
        return built.error();
    *scene = std::move(*built);
    return loaded;
}

// `--cull LIST`: which of the per-blade tests run (SPEC §6); collectStats is set by the caller.
Result<render::CullSettings> parseCullList(const std::string& list) {
    render::CullSettings settings;
    if (list == "all")
        return settings;
    settings.orientation = settings.frustum = settings.distance = settings.occlusion = false;
    if (list == "none")
        return settings;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        if (name == "orientation")
            settings.orientation = true;
        else if (name == "frustum")
            settings.frustum = true;
        else if (name == "distance")
            settings.distance = true;
        else if (name == "occlusion")
            settings.occlusion = true;
        else
            return makeError("--cull", "unknown test \"" + name +
                                           "\" (valid: orientation, frustum, distance, "
                                           "occlusion, or all, none)");
        start = comma + 1;
    }
    return settings;
}

std::string statsJson(const render::FrameTimings& frame, double physicsMs, double wallMs) {
    const render::CullStats& c = frame.cull;
    // The grass stage is everything that draws grass: blades, billboards and stem sets.
    const double grassMs = frame.grassMs + frame.billboardMs + frame.stemSetMs;
    const double total = physicsMs + frame.cullMs + frame.meshMs + grassMs;
    char text[1024];
    std::snprintf(text, sizeof text,
                  "{\n  \"blades_in\": %zu,\n  \"culled\": {\"patch\": %zu, \"orientation\": %zu, "
                  "\"frustum\": %zu, \"distance\": %zu, \"occlusion\": %zu, \"snow\": %zu},\n"
                  "  \"drawn\": %zu,\n"
                  "  \"ms\": {\"physics\": %.4f, \"cull\": %.4f, \"opaque\": %.4f, \"grass\": "
                  "%.4f, \"total\": %.4f, \"frame_wall\": %.4f},\n"
                  "  \"drawn_per_lod\": [%zu, %zu, %zu],\n"
                  "  \"billboards\": {\"drawn\": %zu, \"draw_calls\": %zu, \"ms\": %.4f},\n"
                  "  \"stem_sets\": {\"drawn\": %zu, \"ms\": %.4f},\n"
                  "  \"snow\": {\"depth_pass_ms\": %.4f},\n",
                  c.bladesIn, c.culledPatch, c.culledOrientation, c.culledFrustum, c.culledDistance,
                  c.culledOcclusion, c.culledSnow, c.drawn, physicsMs, frame.cullMs, frame.meshMs,
                  grassMs, total, wallMs, c.drawnPerLod[0], c.drawnPerLod[1], c.drawnPerLod[2],
                  frame.billboardsDrawn, frame.billboardDrawCalls, frame.billboardMs,
                  frame.stemSetsDrawn, frame.stemSetMs, frame.snowMs);
    const auto list = [](const std::vector<std::string>& names) {
        std::string out = "[";
        for (const std::string& name : names)
            out += (out.size() > 1 ? ", \"" : "\"") + name + "\"";
        return out + "]";
    };
    // Which passes ran and what the renderer allocated: a feature a scene does not use shows in
    // neither (issue 10).
    return std::string(text) + "  \"passes\": " + list(frame.passes) +
           ",\n  \"allocated\": " + list(frame.allocated) + "\n}\n";
}

// `--time`: the field as it is after T seconds of the project's physics. Returns ms per step.
Result<double> simulateBeforeRender(const RenderArgs& args, const core::LoadedProject& loaded,
                                    core::Scene& scene) {
    auto physics = core::buildScenePhysics(loaded);
    if (!physics)
        return physics.error();
    for (const auto& note : physics->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
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
    auto run = render::writeTurntable(scene, camera, request, args.turntable, args.out);
    if (!run) {
        printError("render", run.error().str());
        return EXIT_FAILED;
    }
    if (args.stats.empty())
        return 0;
    if (auto written =
            writeFileAtomic(args.stats, statsJson(run->last, physicsMsPerStep, run->lastWallMs));
        !written) {
        printError("render", written.error().str());
        return EXIT_FAILED;
    }
    std::printf("wrote %s\n", args.stats.c_str());
    return 0;
}

}  // namespace

int runRender(const std::vector<std::string>& argv) {
    RenderArgs args;
    ArgParser parser(
        "grass render <project-dir|project.json> [--out F.png] [options]\n"
        "       grass render --mesh M.gltf|M.glb [--out F.png] [options]",
        "Grows the project's grass and renders it headless (EGL, no display needed) to an image "
        "through OpenImageIO; the format follows the extension (.png, .tif, .jpg, .exr). Prints "
        "where it wrote the image and the frame timings. With --mesh, grows a default field on "
        "any glTF file with a camera framing its bounds.");
    parser.positional("project", "a project folder (with project.json) or a project .json file",
                      &args.project, false);
    parser.text("--mesh", "FILE", "render a default field on this glTF file instead of a project",
                &args.mesh);
    parser.text("--out", "FILE",
                "image to write (default: <project name>.png in the working folder, the name kept "
                "to letters, digits, - and _)",
                &args.out);
    parser.integer("--width", "image width in pixels (default: the project's)", &args.width, 1,
                   16384);
    parser.integer("--height", "image height in pixels (default: the project's)", &args.height, 1,
                   16384);
    parser.unsignedInteger("--seed", "scatter seed, overrides the project's", &args.seed);
    parser.text("--camera", "NAME", "which of the project's cameras (default: the first)",
                &args.camera);
    parser.choice("--geometry", {"project", "auto", "tess", "strips"},
                  "blade geometry path: tessellation shaders or instanced strips; auto = strips on "
                  "software GL, tessellation on a GPU",
                  &args.geometry);
    parser.choice(
        "--shape", {"project", "quad", "triangle", "quadratic", "triangle-tip", "dandelion"},
        "blade outline for every layer (SPEC §7); project = each layer's own", &args.shape);
    parser.choice("--technique", {"project", "blades", "billboards", "hybrid", "growth"},
                  "what draws the grass: geometric blades, star billboards (SPEC §8), blades "
                  "near the camera cross-faded into billboards far away, or Kim & Cho's "
                  "instanced stem sets grown from the soil and light maps (SPEC §9)",
                  &args.technique);
    parser.choice("--animation", {"project", "per-cluster", "per-vertex", "per-object"},
                  "billboard wind animation: a CPU offset per cluster (one draw each), or in the "
                  "shader by vertex position or by object centre",
                  &args.animation);
    parser.choice("--lighting", {"project", "grass", "simple"},
                  "blade lighting: the grass model of SPEC §10 or a wrapped Lambert",
                  &args.lighting);
    parser.flag("--light-per-vertex",
                "light blades per vertex (as the article does) instead of per pixel",
                &args.lightPerVertex);
    parser.flag("--snow",
                "snow on (SPEC §11) with the project's snow settings (their defaults when the "
                "project has none); --stats adds the snow pass time",
                &args.snow);
    parser.number("--lod-distance", "M",
                  "blades nearer than M metres get every strip segment / tessellation level, "
                  "half up to 3·M, a quarter beyond",
                  &args.lodDistanceM, 0.0, 1e5,
                  "the project's lod_distance; 0: full detail everywhere");
    addPresetOption(parser, &args.preset);
    parser.choice("--msaa", {"project", "0", "1", "2", "4", "8"},
                  "multisample anti-aliasing samples per pixel", &args.msaa);
    parser.integer("--frames", "frames to draw and time", &args.frames, 1, 1000);
    parser.integer("--turntable",
                   "render N views (0: one image) orbiting 360° about the vertical axis through "
                   "the camera's target, each drawn once, to <out stem>_0000.png ... and a contact "
                   "sheet <out stem>_sheet.png; with --time every view shows the same moment",
                   &args.turntable, core::TURNTABLE_MIN_FRAMES, core::TURNTABLE_MAX_FRAMES);
    parser.integer("--blades", "with --mesh: about how many blades to grow", &args.blades, 1,
                   20000000);
    parser.number("--time", "T",
                  "simulate the project's physics (wind, colliders, gravity) for T seconds first, "
                  "so the picture shows the wind and the trails",
                  &args.timeS, 0.0, 86400.0, "0: blades at rest");
    parser.choice("--backend", {"gpu", "cpu"},
                  "with --time: run the physics as the compute shader or the CPU reference",
                  &args.backend);
    parser.text("--cull", "LIST",
                "per-blade culling tests, comma-separated: orientation,frustum,distance,occlusion; "
                "all or none (none draws every blade); distance thins only where the project "
                "has a render.thinning_distance (0 turns it off)",
                &args.cull);
    parser.text("--stats", "FILE.json",
                "write the last frame's blade counts per cull test and pass timings as JSON",
                &args.stats);
    parser.flag("--gl-debug", "print GL debug output (errors and warnings from the driver)",
                &args.glDebug);
    // Parsed before the defaults that depend on it are shown, so 0 reads as "the project's".
    if (auto parsed = parser.parse(argv); !parsed) {
        printError("render", parsed.error().str());
        return EXIT_USAGE;
    }
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    if (args.project.empty() == args.mesh.empty()) {
        printError("render", args.mesh.empty() ? "give a project folder or --mesh FILE (see --help)"
                                               : "give either a project or --mesh, not both");
        return EXIT_USAGE;
    }

    if (!args.project.empty()) {
        const std::string extension = std::filesystem::path(args.project).extension().string();
        if (extension == ".gltf" || extension == ".glb") {
            printError("render", args.project + ": is a glTF mesh, not a project: use --mesh " +
                                     args.project);
            return EXIT_USAGE;
        }
    }
    auto cullSettings = parseCullList(args.cull);
    if (!cullSettings) {
        printError("render", cullSettings.error().str());
        return EXIT_USAGE;
    }
    if (!args.stats.empty())
        if (auto writable = checkFileWritable(args.stats, "stats.json"); !writable) {
            printError("render", "--stats: " + writable.error().str());
            return EXIT_USAGE;
        }
    // Fail before the (possibly long) scene build and render when the image can't be written.
    if (!args.out.empty())
        if (auto writable = checkImageWritable(args.out); !writable) {
            printError("render", writable.error().str());
            return EXIT_USAGE;
        }

    const auto buildStart = Clock::now();
    core::Scene scene;
    auto loaded = loadInput(args, parser, &scene);
    if (!loaded) {
        printError("render", loaded.error().str());
        return EXIT_FAILED;
    }
    const double buildMs = msSince(buildStart);
    for (const auto& note : scene.notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    const core::Project& project = loaded->project;

    auto camera = render::projectCamera(project, args.camera);
    if (!camera) {
        printError("render", camera.error().str());
        return EXIT_USAGE;
    }
    if (args.out.empty())
        args.out = core::fileSafeName(project.name) + ".png";

    auto context = gl::HeadlessContext::create(args.glDebug);
    if (!context) {
        printError("render", context.error().str());
        return EXIT_FAILED;
    }
    double physicsMsPerStep = 0.0;
    if (args.timeS > 0.0) {
        auto simulated = simulateBeforeRender(args, *loaded, scene);
        if (!simulated) {
            printError("render", simulated.error().str());
            return EXIT_FAILED;
        }
        physicsMsPerStep = *simulated;
    }
    const core::RenderSettings& settings = project.render;
    render::OffscreenRequest request;
    request.width = args.width > 0 ? args.width : settings.width;
    request.height = args.height > 0 ? args.height : settings.height;
    request.msaaSamples = args.msaa == "project" ? settings.msaaSamples : std::stoi(args.msaa);
    request.frames = args.frames;
    request.options = render::renderOptionsFor(project, gl::isSoftwareRenderer());
    if (args.geometry != "project") {
        if (auto path = core::parseGeometryPath(args.geometry))
            request.options.geometry = render::resolveGeometryPath(*path, gl::isSoftwareRenderer());
    }
    // Counters are read once after the last frame: cheap for a one-shot render. The list picks
    // the tests; distances come from the project (thinning only where it has a distance).
    render::CullSettings& culling = request.options.cull;
    culling.frustum = cullSettings->frustum;
    culling.orientation = cullSettings->orientation;
    culling.occlusion = cullSettings->occlusion;
    culling.distance = culling.distance && cullSettings->distance;
    culling.collectStats = true;
    if (parser.given("--lod-distance"))
        culling.lodDistanceM = static_cast<float>(args.lodDistanceM);
    request.options.timeS = static_cast<float>(args.timeS);
    request.options.lightPerVertex = args.lightPerVertex;
    if (args.snow)
        request.options.snow.enabled = 1u;
    if (args.technique != "project")
        if (auto technique = core::parseGrassTechnique(args.technique))
            request.options.technique = *technique;
    if (args.animation != "project")
        if (auto animation = core::parseBillboardAnimation(args.animation))
            request.options.billboards.animation = *animation;
    if (args.lighting != "project")
        request.options.lighting.model =
            args.lighting == "grass" ? core::LightingModel::Grass : core::LightingModel::Simple;
    if (args.shape != "project") {
        if (auto shape = core::parseBladeShape(args.shape))
            request.options.shape = *shape;
    }

    if (args.turntable > 0)
        return finishTurntable(args, scene, *camera, request, physicsMsPerStep);
    auto rendered = render::renderOffscreen(scene, *camera, request);
    if (!rendered) {
        printError("render", rendered.error().str());
        return EXIT_FAILED;
    }
    if (auto written = writeRgba8Image(args.out, rendered->image.width, rendered->image.height,
                                       rendered->image.pixels);
        !written) {
        printError("render", written.error().str());
        return EXIT_FAILED;
    }
    std::vector<double> frames = rendered->frameWallMs;
    std::sort(frames.begin(), frames.end());
    std::printf("wrote %s (%dx%d)\n", args.out.c_str(), request.width, request.height);
    std::printf("  scene      %zu triangles, %zu blades in %zu layer(s), built in %.1f ms\n",
                scene.mesh.n_faces(), scene.totalBlades(), scene.layers.size(), buildMs);
    std::printf("  renderer   %s, geometry %s, %dx MSAA\n", gl::rendererDescription().c_str(),
                render::geometryPathLabel(request.options.geometry), request.msaaSamples);
    std::printf("  frames     %zu, wall ms: first %.1f, median %.1f, min %.1f\n",
                rendered->frameWallMs.size(), rendered->frameWallMs.front(),
                frames[frames.size() / 2], frames.front());
    std::printf(
        "  gpu ms     mesh %.2f, grass %.2f, billboards %.2f, stem sets %.2f, snow map "
        "%.2f (last frame, timer queries)\n",
        rendered->lastFrame.meshMs, rendered->lastFrame.grassMs, rendered->lastFrame.billboardMs,
        rendered->lastFrame.stemSetMs, rendered->lastFrame.snowMs);
    std::printf("  technique  %s; billboards drawn %zu in %zu draw call(s); stem sets drawn %zu\n",
                std::string(core::grassTechniqueName(request.options.technique)).c_str(),
                rendered->lastFrame.billboardsDrawn, rendered->lastFrame.billboardDrawCalls,
                rendered->lastFrame.stemSetsDrawn);
    const render::CullStats& cull = rendered->lastFrame.cull;
    const double inBlades = static_cast<double>(std::max<std::size_t>(cull.bladesIn, 1));
    std::printf(
        "  culling    %zu in, %zu drawn (%.1f %%); culled: patch %zu, orientation %zu, "
        "frustum %zu, distance %zu, occlusion %zu, snow %zu; cull %.2f ms\n",
        cull.bladesIn, cull.drawn, 100.0 * static_cast<double>(cull.drawn) / inBlades,
        cull.culledPatch, cull.culledOrientation, cull.culledFrustum, cull.culledDistance,
        cull.culledOcclusion, cull.culledSnow, rendered->lastFrame.cullMs);
    std::printf(
        "  detail     drawn per LOD %zu / %zu / %zu (full, half, quarter segments; "
        "--lod-distance %.3g m)\n",
        cull.drawnPerLod[0], cull.drawnPerLod[1], cull.drawnPerLod[2],
        static_cast<double>(request.options.cull.lodDistanceM));
    if (!args.stats.empty()) {
        const std::string json =
            statsJson(rendered->lastFrame, physicsMsPerStep, rendered->frameWallMs.back());
        if (auto written = writeFileAtomic(args.stats, json); !written) {
            printError("render", written.error().str());
            return EXIT_FAILED;
        }
        std::printf("wrote %s\n", args.stats.c_str());
    }
    return 0;
}

}  // namespace grass::cli
