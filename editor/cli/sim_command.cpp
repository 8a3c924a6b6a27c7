// grass sim: run a project's physics headless and report its cost and health (issue 4).
#include <algorithm>
#include <cstdio>
#include <memory>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "physics/step_count.h"
#include "cli/preset_option.h"
#include "project/project_inputs.h"
#include "scene/scene_physics.h"
#include "cli/simulation_runner.h"
#include "util/arg_parser.h"
#include "util/atomic_file.h"

namespace grass::cli {

namespace {

struct SimArgs {
    std::string project, report, backend = "cpu", preset = "project";
    double seconds = 5.0;
    double dtS = 0.0;
    int threads = 0;
    std::uint64_t seed = 0;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
};

nlohmann::ordered_json reportJson(const SimArgs& args, const core::Scene& scene,
                                  const core::ScenePhysics& physics, const SimRun& run,
                                  const std::string& device, unsigned threads) {
    const core::FieldHealth& health = run.health;
    nlohmann::ordered_json out;
    out["project"] = args.project;
    out["blades"] = health.blades;
    out["layers"] = scene.layers.size();
    out["steps"] = run.steps;
    out["dt"] = physics.params.dtS;
    out["substeps"] = core::substepCount(physics.params);
    out["seconds"] = static_cast<double>(run.steps) * physics.params.dtS;
    out["backend"] = args.backend;
    out["device"] = device;
    out["threads"] = threads;
    out["wind_sources"] = physics.wind.size();
    out["collider_spheres"] = physics.colliders.size();
    out["ms_per_step"] = run.msPerStep;
    out["blade_steps_per_s"] = run.wallMs > 0.0
                                   ? static_cast<double>(scene.totalBlades()) *
                                         static_cast<double>(run.steps) / (run.wallMs / 1000.0)
                                   : 0.0;
    out["max_rel_length_error"] = health.maxRelLengthError;
    out["nonfinite"] = health.nonfinite;
    out["below_ground"] = health.belowGround;
    out["mean_tip_displacement"] = health.meanTipDisplacementM();
    out["max_tip_displacement"] = health.maxTipDisplacementM;
    out["crushed_share"] = health.crushedShare();
    return out;
}

}  // namespace

int runSim(const std::vector<std::string>& argv) {
    SimArgs args;
    ArgParser parser(
        "grass sim <project-dir|project.json> [--seconds S] [--dt DT] [--backend cpu|gpu] "
        "[--report out.json]",
        "Grows the project's grass and runs its physics (gravity, wind sources, colliders) "
        "headless for S simulated seconds in steps of DT, on the CPU reference or the compute "
        "shader, with a progress line on stderr. Prints the cost per step and the health of the "
        "field: length error, blades with NaN/Inf, tips below the ground, tip displacement and "
        "the share of crushed blades; --report writes them as one JSON object.");
    parser.positional("project", "a project folder (with project.json) or a project .json file",
                      &args.project, true);
    parser.number("--seconds", "S", "simulated time", &args.seconds, 0.0, 86400.0, "5");
    parser.number("--dt", "DT", "step length in seconds", &args.dtS, 1e-6, 60.0,
                  "the project's physics.step_s");
    parser.choice("--backend", {"cpu", "gpu"},
                  "cpu: the multithreaded C++ reference; gpu: the compute shader on the GL device",
                  &args.backend);
    parser.integer("--threads", "CPU threads for the cpu backend (0: all cores)", &args.threads, 0,
                   256);
    parser.text("--report", "FILE", "write the figures as a JSON object to FILE", &args.report);
    parser.unsignedInteger("--seed", "scatter seed, overrides the project's", &args.seed);
    parser.flag("--gl-debug", "print GL debug output (gpu backend)", &args.glDebug);
    addPresetOption(parser, &args.preset);
    if (auto parsed = parser.parse(argv); !parsed) {
        printError("sim", parsed.error().str());
        return EXIT_USAGE;
    }
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    if (!args.report.empty())
        if (auto writable = checkFileWritable(args.report, "report.json"); !writable) {
            printError("sim", "--report: " + writable.error().str());
            return EXIT_USAGE;
        }

    auto loaded = core::loadProject(args.project);
    if (!loaded) {
        printError("sim", loaded.error().str());
        return EXIT_FAILED;
    }
    if (!args.report.empty())
        if (auto refused = core::refuseOverwritingInput(*loaded, args.report, "--report");
            !refused) {
            printError("sim", refused.error().str());
            return EXIT_USAGE;
        }
    if (parser.given("--seed"))
        loaded->project.seed = args.seed;
    if (parser.given("--dt"))
        loaded->project.physics.dtS = static_cast<float>(args.dtS);
    // After --dt: the preset fits its substeps into the step actually taken.
    applyPresetOption(args.preset, loaded->project);
    if (auto steps = core::simulationSteps(args.seconds, loaded->project.physics.dtS, "--seconds");
        !steps) {
        printError("sim", steps.error().str());
        return EXIT_USAGE;
    }
    auto scene = core::buildScene(*loaded);
    if (!scene) {
        printError("sim", scene.error().str());
        return EXIT_FAILED;
    }
    auto physics = core::buildScenePhysics(*loaded);
    if (!physics) {
        printError("sim", physics.error().str());
        return EXIT_FAILED;
    }
    for (const auto& note : scene->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    for (const auto& note : physics->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());

    const SimBackend backend = args.backend == "gpu" ? SimBackend::Gpu : SimBackend::Cpu;
    std::string device = "CPU reference";
    std::unique_ptr<gl::HeadlessContext> context;
    if (backend == SimBackend::Gpu) {
        auto created = gl::HeadlessContext::create(args.glDebug);
        if (!created) {
            printError("sim", created.error().str());
            return EXIT_FAILED;
        }
        context = std::move(*created);
        device = gl::rendererDescription();
    }
    const unsigned threads = args.threads > 0
                                 ? static_cast<unsigned>(args.threads)
                                 : std::max(1u, std::min(std::thread::hardware_concurrency(), 8u));
    core::SceneSimulation simulation(*scene, *physics, threads);
    auto run = runSimulation(*scene, simulation, args.seconds, backend, "sim");
    if (!run) {
        printError("sim", run.error().str());
        return EXIT_FAILED;
    }

    const core::PhysicsParams& params = physics->params;
    const core::FieldHealth& health = run->health;
    std::printf("simulated %.3f s of %s: %zu steps of %.4g s (%u substeps each)\n",
                static_cast<double>(run->steps) * params.dtS, loaded->project.name.c_str(),
                run->steps, static_cast<double>(params.dtS), core::substepCount(params));
    std::printf(
        "  scene      %zu blades in %zu layer(s), %zu wind source(s), %zu collider "
        "sphere(s)\n",
        health.blades, scene->layers.size(), physics->wind.size(), physics->colliders.size());
    std::printf(
        "  backend    %s (%s%s)\n", args.backend.c_str(), device.c_str(),
        backend == SimBackend::Cpu ? (", " + std::to_string(threads) + " threads").c_str() : "");
    std::printf("  cost       %.3f ms/step, %.3g blade-steps/s\n", run->msPerStep,
                run->wallMs > 0.0 ? static_cast<double>(scene->totalBlades()) *
                                        static_cast<double>(run->steps) / (run->wallMs / 1000.0)
                                  : 0.0);
    std::printf("  health     max rel length error %.3g, nonfinite %zu, below ground %zu\n",
                health.maxRelLengthError, health.nonfinite, health.belowGround);
    std::printf("  tips       mean displacement %.4g m, max %.4g m, crushed %.2f %%\n",
                health.meanTipDisplacementM(), health.maxTipDisplacementM,
                100.0 * health.crushedShare());
    if (!args.report.empty()) {
        const auto report = reportJson(args, *scene, *physics, *run, device, threads);
        if (auto written = writeFileAtomic(args.report, report.dump(2) + "\n"); !written) {
            printError("sim", written.error().str());
            return EXIT_FAILED;
        }
        std::printf("wrote %s\n", args.report.c_str());
    }
    return 0;
}

}  // namespace grass::cli
