// grass bench: the project's standard benchmark set (issue 10, item 4). Each case loads a
// project, scales its layers' densities to a blade count, and measures on one headless GL
// context: frames of the project's first camera (per-stage GPU timer queries and wall time,
// medians after a warm-up), the cull pass's counts, the compute-shader physics (blade-steps per
// second) and the CPU time of one frame of the editor's real side panel (build + tessellate).
// bench_report.cpp prints the table, writes the JSON and compares runs.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string_view>

#include "cli/bench_report.h"
#include "cli/commands.h"
#include "gl/debug_output.h"
#include "gl/framebuffer.h"
#include "gl/headless_context.h"
#include "mesh/surface_mesh.h"
#include "render/offscreen_render.h"
#include "scene/scene_physics.h"
#include "render/scene_physics_gpu.h"
#include "tools/median.h"
#include "tools/ui_cost.h"
#include "ui/font.h"
#include "util/arg_parser.h"
#include "util/atomic_file.h"

namespace grass::cli {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A case: a project (relative to --root) grown to about `targetBlades` (0: as the project says).
struct BenchCase {
    const char* name;
    const char* project;
    double targetBlades;
};

// The paper scenes at 100k and 1M blades (SPEC §14: nature 398k, helicopter 900k in the paper),
// winter for the snow pass (the paper scenes have no snow), and tiny for tests.
constexpr std::array<BenchCase, 6> CASES = {{
    {"nature-100k", "projects/nature", 1e5},
    {"helicopter-100k", "projects/helicopter", 1e5},
    {"winter-100k", "projects/winter", 1e5},
    {"nature-1m", "projects/nature", 1e6},
    {"helicopter-1m", "projects/helicopter", 1e6},
    {"tiny", "tests/data/projects/tiny", 0.0},
}};
constexpr std::string_view DEFAULT_CASES =
    "nature-100k,helicopter-100k,winter-100k,nature-1m,helicopter-1m";
// Above this many blades a case is "large": fewer frames and steps (a 1M-blade frame takes
// seconds on llvmpipe), and --quick leaves it out.
constexpr double LARGE_CASE_BLADES = 1e5;

struct BenchArgs {
    std::string cases{DEFAULT_CASES}, out, compare, results, root = GRASS_SOURCE_DIR;
    std::string geometry = "auto", msaa = "4";
    int frames = 5, framesLarge = 2, warmup = 1, steps = 10, stepsLarge = 3;
    int width = 1280, height = 720;
    bool quick = false;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
};

using tools::median;

Result<std::vector<const BenchCase*>> selectCases(const BenchArgs& args) {
    std::vector<const BenchCase*> chosen;
    std::string known;
    for (const BenchCase& c : CASES)
        known += (known.empty() ? "" : ", ") + std::string(c.name);
    std::size_t start = 0;
    while (start <= args.cases.size()) {
        const std::size_t comma = std::min(args.cases.find(',', start), args.cases.size());
        const std::string name = args.cases.substr(start, comma - start);
        start = comma + 1;
        const auto found = std::find_if(CASES.begin(), CASES.end(),
                                        [&](const BenchCase& c) { return name == c.name; });
        if (found == CASES.end())
            return makeError("--cases", "unknown case \"" + name + "\" (cases: " + known + ")");
        if (std::find(chosen.begin(), chosen.end(), &*found) != chosen.end())
            return makeError("--cases", "case \"" + name + "\" given twice");
        if (!args.quick || found->targetBlades <= LARGE_CASE_BLADES)
            chosen.push_back(&*found);
    }
    if (chosen.empty())
        return makeError("--quick",
                         "leaves none of the --cases (--quick runs only the cases of "
                         "100k blades or fewer)");
    return chosen;
}

// Loads the case's project and grows it to about targetBlades: every layer's uniform density is
// multiplied by s = target / estimate and its clump spacing divided by √s (s times the clumps),
// where the estimate is core::estimateLayerBlades summed over the layers on the mesh's area.
Result<core::Scene> growCase(const BenchCase& c, core::LoadedProject& loaded) {
    std::vector<std::string> notes;
    auto mesh = core::loadProjectMesh(loaded, &notes);
    if (!mesh)
        return mesh.error();
    if (c.targetBlades > 0.0) {
        const double area = core::surfaceArea(*mesh);
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
    }
    return core::buildSceneFromMesh(loaded, std::move(*mesh), std::move(notes));
}

// A timer of a pass the frame did not run can read a stale value (docs/rendering.md: an empty
// billboard timer read 31 ms), so only the passes in FrameTimings::passes count.
bool ran(const render::FrameTimings& frame, std::string_view pass) {
    return std::find(frame.passes.begin(), frame.passes.end(), pass) != frame.passes.end();
}

struct CaseContext {
    const BenchArgs& args;
    const ui::FontAtlas& fonts;
    render::GeometryPath geometry;
    std::string progress;  // "bench: [2/5] nature-1m"
};

Result<BenchCaseResult> measureCase(const BenchCase& c, const CaseContext& ctx) {
    const BenchArgs& args = ctx.args;
    const bool large = c.targetBlades > LARGE_CASE_BLADES;
    const int frames = large ? args.framesLarge : args.frames;
    const int steps = large ? args.stepsLarge : args.steps;
    const std::filesystem::path projectPath = std::filesystem::path(args.root) / c.project;
    std::fprintf(stderr, "%s: growing %s on %s\n", ctx.progress.c_str(),
                 c.targetBlades > 0.0
                     ? ("~" + std::to_string(std::lround(c.targetBlades)) + " blades").c_str()
                     : "the project's blades",
                 projectPath.string().c_str());
    auto loaded = core::loadProject(projectPath);
    if (!loaded)
        return loaded.error();
    auto scene = growCase(c, *loaded);
    if (!scene)
        return scene.error();
    for (const auto& note : scene->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    auto camera = render::projectCamera(loaded->project, "");
    if (!camera)
        return makeError(projectPath.string(), camera.error().message);

    BenchCaseResult result;
    result.name = c.name;
    result.project = c.project;
    result.frames = frames;
    render::RenderOptions options = render::renderOptionsFor(loaded->project, true);
    options.geometry = ctx.geometry;
    auto renderer = render::SceneRenderer::create(*scene);
    if (!renderer)
        return renderer.error();
    gl::Framebuffer framebuffer(args.width, args.height, std::stoi(args.msaa));
    std::fprintf(stderr, "%s: %zu blades, %d warm-up + %d timed frame(s) at %dx%d%s\n",
                 ctx.progress.c_str(), scene->totalBlades(), args.warmup, frames, args.width,
                 args.height,
                 large ? " (a large case: a frame can take seconds on a software rasterizer)" : "");
    // The counts come from the warm-up: statistics cost atomics the timed frames should not pay.
    options.cull.collectStats = true;
    for (int frame = 0; frame < args.warmup; ++frame) {
        (*renderer)->render(*camera, args.width, args.height, framebuffer.id(), options);
        glFinish();
    }
    const render::FrameTimings warm = (*renderer)->lastTimings();
    result.bladesIn = warm.cull.bladesIn;
    result.drawn = warm.cull.drawn;
    result.culledShare = result.bladesIn > 0 ? static_cast<double>(result.bladesIn - result.drawn) /
                                                   static_cast<double>(result.bladesIn)
                                             : 0.0;
    options.cull.collectStats = false;
    std::vector<double> wall, cull, opaque, grass, snow;
    render::FrameTimings last;
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = Clock::now();
        (*renderer)->render(*camera, args.width, args.height, framebuffer.id(), options);
        glFinish();
        wall.push_back(msSince(start));
        last = (*renderer)->lastTimings();
        cull.push_back(last.cullMs);
        opaque.push_back(last.meshMs);
        grass.push_back(last.grassMs + (ran(last, "billboards") ? last.billboardMs : 0.0) +
                        (ran(last, "stem_sets") ? last.stemSetMs : 0.0));
        snow.push_back(ran(last, "snow_depth") ? last.snowMs : 0.0);
    }
    result.frameMs = median(wall);
    result.cullMs = median(cull);
    result.opaqueMs = median(opaque);
    result.grassMs = median(grass);
    result.snowMs = median(snow);
    renderer->reset();

    std::fprintf(stderr, "%s: physics, 1 warm-up + %d timed step(s) on the compute shader\n",
                 ctx.progress.c_str(), steps);
    auto physics = core::buildScenePhysics(*loaded);
    if (!physics)
        return physics.error();
    {
        core::SceneSimulation simulation(*scene, std::move(*physics));
        auto gpu = render::ScenePhysicsGpu::create(*scene);
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
        result.bladeStepsPerS =
            ms > 0.0 ? static_cast<double>(scene->totalBlades()) * steps / (ms / 1000.0) : 0.0;
    }
    const tools::UiCost ui = tools::measureUi(ctx.fonts, *loaded, *scene, options, last);
    result.uiMs = ui.ms;
    std::fprintf(stderr, "%s: editor panels, %d frames of %zu shapes, %zu vertices\n",
                 ctx.progress.c_str(), tools::UI_FRAMES, ui.shapes, ui.vertices);
    return result;
}

void describeOptions(ArgParser& parser, BenchArgs& args) {
    parser.text("--cases", "LIST",
                "comma-separated cases: nature-100k, helicopter-100k, winter-100k (snow on), "
                "nature-1m, helicopter-1m, tiny (tests/data/projects/tiny, for tests); default "
                "all but tiny",
                &args.cases);
    parser.flag("--quick", "only the cases of 100k blades or fewer", &args.quick);
    parser.integer("--frames", "timed frames per case, after the warm-up", &args.frames, 1, 1000);
    parser.integer("--frames-1m", "timed frames of the 1M-blade cases", &args.framesLarge, 1, 1000);
    parser.integer("--warmup", "untimed frames first; the last gives the cull counts", &args.warmup,
                   1, 100);
    parser.integer("--steps", "timed physics steps per case", &args.steps, 1, 10000);
    parser.integer("--steps-1m", "timed physics steps of the 1M-blade cases", &args.stepsLarge, 1,
                   10000);
    parser.integer("--width", "image width in pixels", &args.width, 1, 16384);
    parser.integer("--height", "image height in pixels", &args.height, 1, 16384);
    parser.choice("--msaa", {"0", "1", "2", "4", "8"},
                  "multisample anti-aliasing samples per pixel", &args.msaa);
    parser.choice("--geometry", {"auto", "tess", "strips"},
                  "blade geometry path for every case; auto = strips on software GL, "
                  "tessellation on a GPU",
                  &args.geometry);
    parser.text("--root", "DIR",
                "folder holding projects/ and tests/data/ (default: the source tree)", &args.root);
    parser.text("--out", "FILE.json", "write the results as JSON (atomically)", &args.out);
    parser.text("--compare", "OLD.json",
                "also print each figure as this run / OLD (a file from --out) as ratios",
                &args.compare);
    parser.text("--results", "FILE.json",
                "print a saved run (from --out) instead of measuring; with --compare, compare "
                "two saved runs",
                &args.results);
    parser.flag("--gl-debug", "print GL debug output (errors and warnings from the driver)",
                &args.glDebug);
}

// Measures every chosen case on one context; the error names the case's file or the GL failure.
Result<BenchRun> measureRun(const BenchArgs& args, const std::vector<const BenchCase*>& cases) {
    std::string fontError;
    auto fonts = ui::FontAtlas::load(ui::FontAtlas::defaultFontPath(), &fontError);
    if (!fonts)
        return makeError(ui::FontAtlas::defaultFontPath().string(), fontError);
    auto context = gl::HeadlessContext::create(args.glDebug);
    if (!context)
        return context.error();
    BenchRun run;
    run.renderer = gl::rendererDescription();
    run.width = args.width;
    run.height = args.height;
    run.msaaSamples = std::stoi(args.msaa);
    const auto path = core::parseGeometryPath(args.geometry);
    const render::GeometryPath geometry = render::resolveGeometryPath(
        path ? *path : core::GeometryPath::Auto, gl::isSoftwareRenderer());
    run.geometry = render::geometryPathLabel(geometry);
    std::fprintf(stderr, "bench: %zu case(s) on %s\n", cases.size(), run.renderer.c_str());
    for (std::size_t i = 0; i < cases.size(); ++i) {
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

int fail(const Error& error, int code) {
    printError("bench", error.str());
    return code;
}

}  // namespace

int runBench(const std::vector<std::string>& argv) {
    BenchArgs args;
    ArgParser parser(
        "grass bench [--quick] [--cases LIST] [--frames N] [--out FILE.json] [--compare "
        "OLD.json]",
        "Runs the standard benchmark set: the paper scenes projects/nature and "
        "projects/helicopter at about 100k and 1M blades, and projects/winter at 100k with its "
        "snow, at 1280x720 from each project's first camera. A case scales every layer's density "
        "by target / (estimated blades of the project) and divides clump spacing by the square "
        "root of that factor. Prints one table: blades in and drawn, culled share, frame wall "
        "ms and per-stage GPU ms (cull, opaque, grass, snow depth pass) as medians over the "
        "timed frames, physics ms per step and blade-steps per second (compute shader), and UI "
        "ms (one frame of the editor's panels: build, layout, tessellation), under the GL "
        "renderer string. Progress goes to stderr. The full set takes a few minutes on a 2-core "
        "software rasterizer; --quick under a minute.");
    describeOptions(parser, args);
    if (auto parsed = parser.parse(argv); !parsed)
        return fail(parsed.error(), EXIT_USAGE);
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    std::optional<BenchRun> old;
    if (!args.compare.empty()) {
        auto read = readBenchRun(args.compare);
        if (!read)
            return fail(read.error(), EXIT_FAILED);
        old = std::move(*read);
    }
    // A saved run: print it (and its comparison), measure nothing.
    if (!args.results.empty()) {
        for (const char* option :
             {"--cases", "--quick", "--out", "--frames", "--frames-1m", "--warmup", "--steps",
              "--steps-1m", "--width", "--height", "--msaa", "--geometry", "--root"})
            if (parser.given(option))
                return fail(makeError(option,
                                      "not with --results, which prints a saved run "
                                      "and measures nothing"),
                            EXIT_USAGE);
        auto saved = readBenchRun(args.results);
        if (!saved)
            return fail(saved.error(), EXIT_FAILED);
        printBenchTable(*saved);
        if (old)
            if (auto compared = printBenchComparison(*saved, *old, args.compare); !compared)
                return fail(compared.error(), EXIT_FAILED);
        return 0;
    }
    auto cases = selectCases(args);
    if (!cases)
        return fail(cases.error(), EXIT_USAGE);
    for (const BenchCase* c : *cases)
        if (const auto project = std::filesystem::path(args.root) / c->project;
            !std::filesystem::exists(project))
            return fail(
                makeError("--root", project.string() + ": no such project (--root names the folder "
                                                       "holding projects/ and tests/data/)"),
                EXIT_USAGE);
    if (!args.out.empty())
        if (auto writable = checkFileWritable(args.out, "bench.json"); !writable)
            return fail(writable.error(), EXIT_USAGE);
    // A file that cannot be compared fails now, not after minutes of measuring.
    if (old) {
        std::vector<std::string> names;
        for (const BenchCase* c : *cases)
            names.emplace_back(c->name);
        if (auto comparable = checkComparable(*old, args.compare, names, args.width, args.height);
            !comparable)
            return fail(comparable.error(), EXIT_FAILED);
    }

    const auto start = Clock::now();
    auto run = measureRun(args, *cases);
    if (!run)
        return fail(run.error(), EXIT_FAILED);
    printBenchTable(*run);
    if (old)
        if (auto compared = printBenchComparison(*run, *old, args.compare); !compared)
            return fail(compared.error(), EXIT_FAILED);
    std::printf("wall time %.1f s for %zu case(s)\n", msSince(start) / 1000.0, run->cases.size());
    if (!args.out.empty()) {
        if (auto written = writeFileAtomic(args.out, benchRunJson(*run)); !written)
            return fail(written.error(), EXIT_FAILED);
        std::printf("wrote %s\n", args.out.c_str());
    }
    return 0;
}

}  // namespace grass::cli
