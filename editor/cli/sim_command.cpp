// grass sim: run a project's physics headless and report its cost and health (issue 4).
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/output_files.h"
#include "cli/parse_arguments.h"
#include "cli/preset_option.h"
#include "cli/simulation_runner.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "physics/step_count.h"
#include "project/project_inputs.h"
#include "scene/scene_physics.h"
#include "util/arg_parser.h"
#include "util/blade_pass_group.h"
#include "util/interrupt_stop.h"

namespace grass::cli {

namespace {

struct SimArgs {
    std::string project, report, backend = "cpu", preset = "project", cpuPath = "simd";
    double seconds = 5.0;
    double dtS = 0.0;
    int threads = 0;
    std::uint64_t seed = 0;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
    // Given on the command line: they override the project's, which they default to.
    bool seedGiven = false, dtGiven = false;
};

// The grown field and the physics that moves it.
struct SimField {
    core::Scene scene;
    core::ScenePhysics physics;
};

// Where the physics runs: the GPU backend holds a GL context for as long as it steps.
struct SimDevice {
    SimBackend backend = SimBackend::Cpu;
    std::string description = "CPU";
    std::unique_ptr<gl::HeadlessContext> context;
};

std::optional<int> parseSimArgs(const std::vector<std::string>& argv, SimArgs& args) {
    ArgParser parser(
        "grass sim <project-dir|project.json> [--seconds S] [--dt DT] [--backend cpu|gpu] "
        "[--cpu-path simd|scalar] [--report out.json]",
        "Grows the project's grass and runs its physics (gravity, wind sources, colliders) "
        "headless for S simulated seconds in steps of DT, on the CPU reference or the compute "
        "shader, with a progress line on stderr. Prints the cost per step and the health of the "
        "field: length error, blades with NaN/Inf, tips below the ground, tip displacement and "
        "the share of crushed blades; --report writes them as one JSON object. Ctrl+C ends the "
        "run before its next step with the summary and report of the steps run (exit 130).");
    addProjectArgument(parser, &args.project, true);
    parser.number("--seconds", "S", "simulated time", &args.seconds, 0.0, 86400.0, "5");
    parser.number("--dt", "DT", "step length in seconds", &args.dtS, 1e-6, 60.0,
                  "the project's physics.step_s");
    parser.choice("--backend", {"cpu", "gpu"},
                  "cpu: the multithreaded C++ reference; gpu: the compute shader on the GL device",
                  &args.backend);
    parser.integer("--threads", "CPU threads for the cpu backend (0: all cores)", &args.threads, 0,
                   256);
    parser.choice("--cpu-path", {"simd", "scalar"},
                  "cpu backend: the SIMD execution (Highway, widest instruction set of this CPU) "
                  "or the scalar reference it is tested against (docs/physics.md)",
                  &args.cpuPath);
    parser.text("--report", "FILE", "write the figures as a JSON object to FILE", &args.report);
    parser.unsignedInteger("--seed", "scatter seed, overrides the project's", &args.seed);
    parser.flag("--gl-debug", "print GL debug output (gpu backend)", &args.glDebug);
    addPresetOption(parser, &args.preset);
    if (const auto exitCode = parseArguments(parser, argv, "sim"))
        return exitCode;
    args.seedGiven = parser.given("--seed");
    args.dtGiven = parser.given("--dt");
    return std::nullopt;
}

// The command line over the loaded project, checked against it before anything is grown.
Result<void> applyArgs(const SimArgs& args, core::LoadedProject& loaded) {
    if (!args.report.empty())
        if (auto refused = core::refuseOverwritingInput(loaded, args.report, "--report"); !refused)
            return refused;
    if (args.seedGiven)
        loaded.project.seed = args.seed;
    if (args.dtGiven)
        loaded.project.physics.dtS = static_cast<float>(args.dtS);
    // After --dt: the preset fits its substeps into the step actually taken.
    applyPresetOption(args.preset, loaded.project);
    if (auto steps = core::simulationSteps(args.seconds, loaded.project.physics.dtS, "--seconds");
        !steps)
        return steps.error();
    return {};
}

// The scene and its physics; their notes are printed once both are built.
Result<SimField> growField(const core::LoadedProject& loaded) {
    auto scene = core::buildScene(loaded, nullptr, {}, buildProgressNotes());
    if (!scene)
        return scene.error();
    auto physics = core::buildScenePhysics(loaded, scene->groundOrigin);
    if (!physics)
        return physics.error();
    printNotes(scene->notes);
    printNotes(physics->notes);
    return SimField{std::move(*scene), std::move(*physics)};
}

Result<SimDevice> openDevice(const SimArgs& args) {
    SimDevice device;
    if (args.backend != "gpu")
        return device;
    auto created = gl::HeadlessContext::create(args.glDebug);
    if (!created)
        return created.error();
    device.backend = SimBackend::Gpu;
    device.context = std::move(*created);
    device.description = gl::rendererDescription();
    // The compute shader's work groups (core/util/blade_pass_group.h): a bad GRASS_COMPUTE_GROUP
    // ends the run here, before its first step.
    const Result<std::uint32_t> group = core::bladePassGroupSizeFromEnvironment();
    if (!group)
        return group.error();
    device.description += ", compute groups of " + std::to_string(*group);
    return device;
}

double bladeStepsPerS(const core::Scene& scene, const SimRun& run) {
    return run.wallMs > 0.0 ? static_cast<double>(scene.totalBlades()) *
                                  static_cast<double>(run.steps) / (run.wallMs / 1000.0)
                            : 0.0;
}

// Blade 64 B read + 64 B written, η 4 + 4 B, rest tip 12 B (docs/physics.md, bench_physics).
constexpr std::size_t CPU_BYTES_PER_BLADE_STEP = 148;

// "simd AVX2 × 8" or "scalar reference".
std::string cpuPathLabel(const SimArgs& args) {
    if (args.cpuPath == "scalar")
        return "scalar reference";
    return "simd " + core::physicsSimdTarget() + " x " + std::to_string(core::physicsSimdLanes());
}

void printSummary(const SimArgs& args, const core::LoadedProject& loaded, const SimField& field,
                  const SimDevice& device, unsigned threads, const SimRun& run) {
    const core::PhysicsParams& params = field.physics.params;
    const core::FieldHealth& health = run.health;
    std::printf("simulated %.3f s of %s: %zu steps of %.4g s (%u substeps each)\n",
                static_cast<double>(run.steps) * params.dtS, loaded.project.name.c_str(), run.steps,
                static_cast<double>(params.dtS), core::substepCount(params));
    std::printf(
        "  scene      %zu blades in %zu layer(s), %zu wind source(s), %zu collider "
        "sphere(s)\n",
        health.blades, field.scene.layers.size(), field.physics.wind.size(),
        field.physics.colliders.size());
    std::printf("  backend    %s (%s%s)\n", args.backend.c_str(), device.description.c_str(),
                device.backend == SimBackend::Cpu
                    ? (", " + std::to_string(threads) + " threads, " + cpuPathLabel(args)).c_str()
                    : "");
    std::printf("  cost       %.3f ms/step, %.3g blade-steps/s\n", run.msPerStep,
                bladeStepsPerS(field.scene, run));
    // The roofline's memory side (docs/physics.md): every blade read and written once a step.
    if (device.backend == SimBackend::Cpu)
        std::printf("  memory     %.3g GB/s of traffic at %zu B a blade-step (the bound: the "
                    "machine's copy bandwidth, docs/physics.md)\n",
                    bladeStepsPerS(field.scene, run) * double(CPU_BYTES_PER_BLADE_STEP) * 1e-9,
                    CPU_BYTES_PER_BLADE_STEP);
    std::printf("  health     max rel length error %.3g, nonfinite %zu, below ground %zu\n",
                health.maxRelLengthError, health.nonfinite, health.belowGround);
    std::printf("  tips       mean displacement %.4g m, max %.4g m, crushed %.2f %%\n",
                health.meanTipDisplacementM(), health.maxTipDisplacementM,
                100.0 * health.crushedShare());
}

nlohmann::ordered_json reportJson(const SimArgs& args, const SimField& field, const SimRun& run,
                                  const std::string& device, unsigned threads) {
    const core::FieldHealth& health = run.health;
    const core::ScenePhysics& physics = field.physics;
    nlohmann::ordered_json out;
    out["project"] = args.project;
    out["blades"] = health.blades;
    out["layers"] = field.scene.layers.size();
    out["steps"] = run.steps;
    out["dt"] = physics.params.dtS;
    out["substeps"] = core::substepCount(physics.params);
    out["seconds"] = static_cast<double>(run.steps) * physics.params.dtS;
    out["backend"] = args.backend;
    out["device"] = device;
    out["threads"] = threads;
    out["cpu_path"] = args.cpuPath;
    out["simd_target"] = core::physicsSimdTarget();
    out["simd_lanes"] = core::physicsSimdLanes();
    out["wind_sources"] = physics.wind.size();
    out["collider_spheres"] = physics.colliders.size();
    out["ms_per_step"] = run.msPerStep;
    out["blade_steps_per_s"] = bladeStepsPerS(field.scene, run);
    out["bytes_per_blade_step"] = CPU_BYTES_PER_BLADE_STEP;
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
    if (const auto exitCode = parseSimArgs(argv, args))
        return *exitCode;
    if (auto writable = checkOutputWritable(args.report, "--report", "report.json"); !writable)
        return reportFailure("sim", writable.error(), EXIT_USAGE);

    auto loaded = core::loadProject(args.project);
    if (!loaded)
        return reportFailure("sim", loaded.error(), EXIT_FAILED);
    if (auto applied = applyArgs(args, *loaded); !applied)
        return reportFailure("sim", applied.error(), EXIT_USAGE);
    auto field = growField(*loaded);
    if (!field)
        return reportFailure("sim", field.error(), EXIT_FAILED);
    auto device = openDevice(args);
    if (!device)
        return reportFailure("sim", device.error(), EXIT_FAILED);

    const unsigned threads = cpuThreads(args.threads);
    core::SceneSimulation simulation(field->scene, field->physics, threads);
    simulation.setCpuPhysics(args.cpuPath == "scalar" ? core::CpuPhysics::Scalar
                                                      : core::CpuPhysics::Simd);
    // Ctrl+C ends the run before its next step: the steps run are summed up and saved.
    const core::InterruptStop interrupt;
    auto run = runSimulation(field->scene, simulation, args.seconds, device->backend, "sim",
                             interrupt.token());
    if (!run)
        return reportFailure("sim", run.error(), EXIT_FAILED);
    if (run->stopped)
        std::fprintf(stderr, "sim: stopped after %zu steps: the summary is of those\n", run->steps);

    printSummary(args, *loaded, *field, *device, threads, *run);
    const int exitCode = interrupt.exitCodeOr(0);
    if (args.report.empty())
        return exitCode;
    auto report = reportJson(args, *field, *run, device->description, threads);
    report["stopped"] = run->stopped;
    if (auto written = writeOutputFile(args.report, report.dump(2) + "\n"); !written)
        return reportFailure("sim", written.error(), EXIT_FAILED);
    return exitCode;
}

}  // namespace grass::cli
