#include "cli/bench_measure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string_view>

#include "blade/strip_batch.h"
#include "cli/bench_editor.h"
#include "cli/commands.h"
#include "gl/framebuffer.h"
#include "gl/headless_context.h"
#include "mesh/surface_mesh.h"
#include "render/offscreen_render.h"
#include "render/scene_physics_gpu.h"
#include "scene/field_simulation.h"
#include "scene/scene_physics.h"
#include "tools/median.h"
#include "tools/ms_since.h"
#include "tools/process_memory.h"
#include "tools/ui_cost.h"
#include "ui/font.h"
#include "util/blade_pass_group.h"

namespace grass::cli {

namespace {

using tools::Clock;
using tools::median;
using tools::msSince;

struct CaseContext {
    const BenchArgs& args;
    const ui::FontAtlas& fonts;
    render::GeometryPath geometry;
    std::string progress;  // "bench: [2/5] nature-1m"
};

// A case's project as grown for it, and the camera its frames are drawn from.
struct GrownCase {
    core::LoadedProject loaded;
    core::Scene scene;
    core::OrbitCamera camera;
    double buildS = 0.0;  // buildSceneFromMesh, seconds
};

// Scales the project to about targetBlades: every layer's uniform density is multiplied by
// s = target / estimate and its clump spacing divided by √s (s times the clumps), where the
// estimate is core::estimateLayerBlades summed over the layers on the mesh's area.
Result<void> scaleToTarget(const BenchCase& c, core::LoadedProject& loaded,
                           const core::SurfaceMesh& mesh) {
    const double area = core::surfaceArea(mesh);
    double estimate = 0.0;
    for (const core::GrassLayer& layer : loaded.project.layers)
        estimate += core::estimateLayerBlades(layer.scatter, area);
    if (!(estimate > 0.0))
        return makeError(loaded.file.string(), "no layer grows any blade: nothing to scale");
    const double scale = c.targetBlades / estimate;
    for (core::GrassLayer& layer : loaded.project.layers) {
        layer.scatter.density = static_cast<float>(layer.scatter.density * scale);
        if (layer.scatter.clumpSpacing > 0.0f)
            layer.scatter.clumpSpacing =
                static_cast<float>(layer.scatter.clumpSpacing / std::sqrt(scale));
    }
    return {};
}

// The samples per pixel of a case: the run's --msaa, or none for the equal-work case.
int caseMsaa(const BenchCase& c, const BenchArgs& args) {
    return c.everyBlade ? 0 : std::stoi(args.msaa);
}

// Loads the case's project and grows it to about targetBlades (scaleToTarget).
Result<GrownCase> growCase(const BenchCase& c, const CaseContext& ctx) {
    const std::filesystem::path projectPath = std::filesystem::path(ctx.args.root) / c.project;
    std::fprintf(stderr, "%s: growing %s on %s\n", ctx.progress.c_str(),
                 c.targetBlades > 0.0
                     ? ("~" + std::to_string(std::lround(c.targetBlades)) + " blades").c_str()
                     : "the project's blades",
                 projectPath.string().c_str());
    auto loaded = core::loadProject(projectPath);
    if (!loaded)
        return loaded.error();
    std::vector<std::string> notes;
    glm::dvec3 groundOrigin{0.0};
    auto mesh = core::loadProjectMesh(*loaded, &notes, nullptr, nullptr, &groundOrigin);
    if (!mesh)
        return mesh.error();
    if (c.targetBlades > 0.0)
        if (auto scaled = scaleToTarget(c, *loaded, *mesh); !scaled)
            return scaled.error();
    if (c.technique) {
        auto technique = core::parseGrassTechnique(c.technique);
        if (!technique)
            return makeError(c.name, technique.error().message);
        loaded->project.render.technique = *technique;
        std::fprintf(stderr, "%s: technique %s instead of the project's\n", ctx.progress.c_str(),
                     c.technique);
    }
    const auto buildStart = Clock::now();
    auto scene =
        core::buildSceneFromMesh(*loaded, std::move(*mesh), std::move(notes), groundOrigin);
    if (!scene)
        return scene.error();
    const double buildS = msSince(buildStart) / 1000.0;
    std::fprintf(stderr, "%s: %zu blades built in %.2f s\n", ctx.progress.c_str(),
                 scene->totalBlades(), buildS);
    printNotes(scene->notes);
    auto camera = render::projectCamera(loaded->project, "");
    if (!camera)
        return makeError(projectPath.string(), camera.error().message);
    return GrownCase{std::move(*loaded), std::move(*scene), *camera, buildS};
}

// A timer of a pass the frame did not run can read a stale value (docs/rendering.md: an empty
// billboard timer read 31 ms), so only the passes in FrameTimings::passes count.
bool ran(const render::FrameTimings& frame, std::string_view pass) {
    return std::find(frame.passes.begin(), frame.passes.end(), pass) != frame.passes.end();
}

// The untimed warm-up frames; the last gives the cull counts, since statistics cost atomics the
// timed frames should not pay.
void warmUp(render::SceneRenderer& renderer, const GrownCase& grown, const CaseContext& ctx,
            const gl::Framebuffer& framebuffer, render::RenderOptions& options,
            BenchCaseResult& result) {
    const BenchArgs& args = ctx.args;
    options.cull.collectStats = true;
    for (int frame = 0; frame < args.warmup; ++frame) {
        renderer.render(grown.camera, args.width, args.height, framebuffer, options);
        glFinish();
    }
    const render::FrameTimings warm = renderer.lastTimings();
    result.bladesIn = warm.cull.bladesIn;
    result.drawn = warm.cull.drawn;
    result.bladeTriangles = core::drawnBladeTriangles(
        warm.cull.drawnPerLod, options.geometry == render::GeometryPath::Tessellation
                                   ? options.tessLevel
                                   : options.stripSegments);
    result.culledShare = result.bladesIn > 0 ? static_cast<double>(result.bladesIn - result.drawn) /
                                                   static_cast<double>(result.bladesIn)
                                             : 0.0;
    options.cull.collectStats = false;
}

// The warm-up, then result.frames frames timed by the wall clock, then as many with every pass
// timed exactly (RenderOptions::exactStageTimings): medians of each into `result`. On software
// GL a GL_TIME_ELAPSED range absorbs the next pass's deferred work (gl/timer_query.h: the
// meadow's cull read 107 ms for a pass of 23 ms), while finishing the work around each pass
// costs the overlap a real frame has, so the two figures come from separate frames. Returns the
// last frame's timings.
Result<render::FrameTimings> measureFrames(const BenchCase& c, const GrownCase& grown,
                                           const CaseContext& ctx, bool large, render::RenderOptions& options,
                                           BenchCaseResult& result) {
    const BenchArgs& args = ctx.args;
    auto renderer = render::SceneRenderer::create(grown.scene);
    if (!renderer)
        return renderer.error();
    gl::Framebuffer framebuffer(args.width, args.height, caseMsaa(c, args));
    std::fprintf(stderr, "%s: %zu blades, %d warm-up + 2 x %d timed frame(s) at %dx%d%s\n",
                 ctx.progress.c_str(), grown.scene.totalBlades(), args.warmup, result.frames,
                 args.width, args.height,
                 large ? " (a large case: a frame can take seconds on a software rasterizer)" : "");
    warmUp(**renderer, grown, ctx, framebuffer, options, result);
    std::vector<double> wall, cull, opaque, grass, snow;
    for (int frame = 0; frame < result.frames; ++frame) {
        const auto start = Clock::now();
        (*renderer)->render(grown.camera, args.width, args.height, framebuffer, options);
        glFinish();
        wall.push_back(msSince(start));
    }
    render::FrameTimings last;
    options.exactStageTimings = true;
    for (int frame = 0; frame < result.frames; ++frame) {
        (*renderer)->render(grown.camera, args.width, args.height, framebuffer, options);
        glFinish();
        last = (*renderer)->lastTimings();
        cull.push_back(last.cullMs);
        opaque.push_back(last.meshMs);
        grass.push_back(last.grassMs + (ran(last, "billboards") ? last.billboardMs : 0.0) +
                        (ran(last, "stem_sets") ? last.stemSetMs : 0.0));
        snow.push_back(ran(last, "snow_depth") ? last.snowMs : 0.0);
    }
    options.exactStageTimings = false;
    result.frameMs = median(wall);
    result.cullMs = median(cull);
    result.opaqueMs = median(opaque);
    result.grassMs = median(grass);
    result.snowMs = median(snow);
    return last;
}

// 1 warm-up step, then `steps` timed ones of the compute shader, then the same on the CPU's SIMD
// execution: ms per step and blade-steps per second of each into `result`.
Result<void> measurePhysics(GrownCase& grown, const CaseContext& ctx, int steps,
                            BenchCaseResult& result) {
    std::fprintf(stderr, "%s: physics, 1 warm-up + %d timed step(s) on the compute shader\n",
                 ctx.progress.c_str(), steps);
    auto physics = core::buildScenePhysics(grown.loaded, grown.scene.groundOrigin);
    if (!physics)
        return physics.error();
    core::SceneSimulation simulation(grown.scene, std::move(*physics));
    auto gpu = render::ScenePhysicsGpu::create(grown.scene);
    if (!gpu)
        return gpu.error();
    const float dtS = simulation.physics().params.dtS;
    gpu->step(simulation.physics(), 0.0f);
    glFinish();
    const auto start = Clock::now();
    for (int step = 1; step <= steps; ++step)
        gpu->step(simulation.physics(), static_cast<float>(step) * dtS);
    glFinish();
    const double ms = msSince(start);
    result.physicsSteps = steps;
    result.physicsMsPerStep = ms / steps;
    const auto perSecond = [&](double wallMs) {
        return wallMs > 0.0
                   ? static_cast<double>(grown.scene.totalBlades()) * steps / (wallMs / 1000.0)
                   : 0.0;
    };
    result.bladeStepsPerS = perSecond(ms);
    // The same steps on the CPU's SIMD execution, on a copy of the blades (issue 29).
    std::fprintf(stderr, "%s: physics, 1 warm-up + %d timed step(s) on the CPU (SIMD %s)\n",
                 ctx.progress.c_str(), steps, core::physicsSimdTarget().c_str());
    core::FieldSimulation cpu(grown.scene);
    cpu.step(simulation.physics(), 0.0f);
    const auto cpuStart = Clock::now();
    for (int step = 1; step <= steps; ++step)
        cpu.step(simulation.physics(), static_cast<float>(step) * dtS);
    const double cpuMs = msSince(cpuStart);
    result.cpuPhysicsMsPerStep = cpuMs / steps;
    result.cpuBladeStepsPerS = perSecond(cpuMs);
    return {};
}

// The editor case: the real editor in its own process (cli/bench_editor.h); the headless
// figures stay 0, the frame column shows the orbit's median.
Result<BenchCaseResult> measureEditorCase(const BenchCase& c, const CaseContext& ctx) {
    std::fprintf(stderr, "%s: the editor window, about 30 s\n", ctx.progress.c_str());
    auto figures = measureEditor(std::filesystem::path(ctx.args.root) / c.project, ctx.args.glDebug);
    if (!figures)
        return figures.error();
    BenchCaseResult result;
    result.name = c.name;
    result.project = c.project;
    result.frames = figures->orbit.frames;
    result.frameMs = figures->orbit.medianMs;
    result.editor = *figures;
    return result;
}

Result<BenchCaseResult> measureCase(const BenchCase& c, const CaseContext& ctx) {
    if (c.editor)
        return measureEditorCase(c, ctx);
    const bool large = isLargeCase(c);
    auto grown = growCase(c, ctx);
    if (!grown)
        return grown.error();
    BenchCaseResult result;
    result.name = c.name;
    result.project = c.project;
    result.frames = large ? ctx.args.framesLarge : ctx.args.frames;
    render::RenderOptions options = render::renderOptionsFor(grown->loaded.project, true);
    options.geometry = ctx.geometry;
    if (c.everyBlade) {
        options.cull.frustum = options.cull.orientation = options.cull.distance = false;
        options.cull.occlusion = false;
        options.cull.lodDistanceM = 0.0f;
    }
    auto last = measureFrames(c, *grown, ctx, large, options, result);
    if (!last)
        return last.error();
    const int steps = large ? ctx.args.stepsLarge : ctx.args.steps;
    if (auto physics = measurePhysics(*grown, ctx, steps, result); !physics)
        return physics.error();
    const tools::UiCost ui =
        tools::measureUi(ctx.fonts, grown->loaded, grown->scene, options, *last);
    result.uiMs = ui.ms;
    result.buildS = grown->buildS;
    result.peakRssMb = static_cast<double>(tools::peakResidentBytes()) / (1024.0 * 1024.0);
    std::fprintf(stderr, "%s: editor panels, %d frames of %zu shapes, %zu vertices\n",
                 ctx.progress.c_str(), tools::UI_FRAMES, ui.shapes, ui.vertices);
    return result;
}

// The run's header: the renderer, the image and the geometry path every case is drawn with.
BenchRun startRun(const BenchArgs& args, render::GeometryPath geometry,
                  std::uint32_t computeGroup) {
    BenchRun run;
    run.renderer = gl::rendererDescription();
    run.width = args.width;
    run.height = args.height;
    run.msaaSamples = std::stoi(args.msaa);
    run.geometry = render::geometryPathLabel(geometry);
    run.computeGroup = computeGroup;
    return run;
}

}  // namespace

Result<BenchRun> measureRun(const BenchArgs& args, const std::vector<const BenchCase*>& cases,
                            std::stop_token stop) {
    std::string fontError;
    auto fonts = ui::FontAtlas::load(ui::FontAtlas::defaultFontPath(), &fontError);
    if (!fonts)
        return makeError(ui::FontAtlas::defaultFontPath().string(), fontError);
    auto context = gl::HeadlessContext::create(args.glDebug);
    if (!context)
        return context.error();
    // A bad GRASS_COMPUTE_GROUP ends the run before any case.
    const auto group = core::bladePassGroupSizeFromEnvironment();
    if (!group)
        return group.error();
    const auto path = core::parseGeometryPath(args.geometry);
    const render::GeometryPath geometry = render::resolveGeometryPath(
        path ? *path : core::GeometryPath::Auto, gl::isSoftwareRenderer());
    BenchRun run = startRun(args, geometry, *group);
    std::fprintf(stderr, "bench: %zu case(s) on %s\n", cases.size(), run.renderer.c_str());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (stop.stop_requested()) {
            std::fprintf(stderr,
                         "bench: stopped after %zu of %zu case(s): the cases measured follow\n", i,
                         cases.size());
            break;
        }
        const auto start = Clock::now();
        const CaseContext ctx{args, *fonts, geometry,
                              "bench: [" + std::to_string(i + 1) + "/" +
                                  std::to_string(cases.size()) + "] " + cases[i]->name};
        auto result = measureCase(*cases[i], ctx);
        if (!result)
            return result.error();
        std::fprintf(stderr, "%s: frame %.1f ms, %zu of %zu blades drawn; case took %.1f s\n",
                     ctx.progress.c_str(), result->frameMs, result->drawn, result->bladesIn,
                     msSince(start) / 1000.0);
        run.cases.push_back(std::move(*result));
    }
    return run;
}

}  // namespace grass::cli
