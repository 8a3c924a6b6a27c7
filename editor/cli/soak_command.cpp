// grass soak: a long run of a project's physics, checked for drift and leaks (issue 11).
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/output_files.h"
#include "cli/parse_arguments.h"
#include "cli/soak_run.h"
#include "cli/soak_verdict.h"
#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "physics/path_loop.h"
#include "physics/step_count.h"
#include "project/project_inputs.h"
#include "util/arg_parser.h"
#include "util/interrupt_stop.h"

namespace grass::cli {

namespace {

struct SoakArgs {
    std::string project, report, backend = "both";
    double seconds = 3600.0;
    double dtS = 1.0 / 60.0;
    double sampleEveryS = 0.0;
    double densityScale = 1.0;
    int threads = 0;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
};

// What every backend's run shares: the project, its physics and the threads of the CPU one.
struct SoakSetup {
    const SoakArgs& args;
    const core::LoadedProject& loaded;
    const core::ScenePhysics& physics;
    unsigned threads;
    std::stop_token stop;  // Ctrl+C
};

std::optional<int> parseSoakArgs(const std::vector<std::string>& argv, SoakArgs& args) {
    ArgParser parser(
        "grass soak <project-dir|project.json> [--seconds S] [--dt DT] [--backend cpu|gpu|both] "
        "[--sample-every S] [--density-scale F] [--report FILE]",
        "Runs the project's physics for a long span (default: one hour of game time at 60 Hz) with "
        "its wind and colliders kept moving: paths are held at their last key in a project, so "
        "soak drives every path forth and back (period: twice its span). Every --sample-every "
        "seconds it records the field's length error, NaN/Inf count, the resident memory (RSS) "
        "and, for the GPU, the live GL objects, and prints a table and a verdict. It fails (exit "
        "1) when a blade's length error |L - h| exceeds the tolerance validation states "
        "(docs/physics.md: 1e-4*h + 4*eps*(max|v0| + h)), a NaN/Inf appears, RSS grows more "
        "than 16 MiB after the first interval, or GL objects are left over (more at the end than "
        "after the first step, or after tear-down than before set-up). Ctrl+C ends the run under "
        "way at its next step: what ran is judged, printed and saved (exit 130).");
    addProjectArgument(parser, &args.project, true);
    parser.number("--seconds", "S", "simulated time", &args.seconds, 1e-3, 864000.0, "3600");
    parser.number("--dt", "DT", "step length in seconds", &args.dtS, 1e-4, 1.0, "1/60");
    parser.choice("--backend", {"both", "cpu", "gpu"},
                  "cpu: the C++ reference; gpu: the compute shader; both: cpu, then gpu",
                  &args.backend);
    parser.number("--sample-every", "S", "simulated seconds between samples", &args.sampleEveryS,
                  1e-4, 864000.0, "S/60");
    // Thins the field (every layer's density times F) so a long soak of a big project fits a
    // slow machine: every blade runs the same physics, so drift per blade is what it would be at
    // full density; the step cost falls with the blade count.
    parser.number("--density-scale", "F", "grow every layer at F times its density",
                  &args.densityScale, 1e-6, 1.0, "1");
    parser.integer("--threads", "CPU threads for the cpu backend (0: all cores, at most 8)",
                   &args.threads, 0, 256);
    parser.text("--report", "FILE", "write the samples and verdicts as JSON to FILE", &args.report);
    parser.flag("--gl-debug", "print GL debug output (gpu backend)", &args.glDebug);
    if (const auto exitCode = parseArguments(parser, argv, "soak"))
        return exitCode;
    if (!parser.given("--sample-every"))
        args.sampleEveryS = args.seconds / 60.0;
    return std::nullopt;
}

// The command line over the loaded project, checked against it before anything is grown.
Result<void> applyArgs(const SoakArgs& args, core::LoadedProject& loaded) {
    if (!args.report.empty())
        if (auto refused = core::refuseOverwritingInput(loaded, args.report, "--report"); !refused)
            return refused;
    loaded.project.physics.dtS = static_cast<float>(args.dtS);
    for (const auto& [option, seconds] :
         {std::pair{"--seconds", args.seconds}, {"--sample-every", args.sampleEveryS}})
        if (auto steps = core::simulationSteps(seconds, args.dtS, option); !steps)
            return steps.error();
    for (core::GrassLayer& layer : loaded.project.layers)
        layer.scatter.density *= static_cast<float>(args.densityScale);
    return {};
}

// How the soak keeps the field moving, in words for the header line and the report.
std::string describeMotion(const core::ScenePhysics& physics) {
    const core::PathLooper looper(physics.wind, physics.colliders);
    if (physics.wind.empty() && physics.colliders.empty())
        return "no wind and no colliders: the field stands still";
    if (looper.loopingPaths() == 0)
        return "no paths to loop (wind moves with time only)";
    char text[160];
    std::snprintf(text, sizeof text, "%zu path(s) driven forth and back (longest period %.4g s)",
                  looper.loopingPaths(), static_cast<double>(looper.longestPeriodS()));
    return text;
}

std::vector<SimBackend> chosenBackends(const SoakArgs& args) {
    std::vector<SimBackend> backends;
    if (args.backend != "gpu")
        backends.push_back(SimBackend::Cpu);
    if (args.backend != "cpu")
        backends.push_back(SimBackend::Gpu);
    return backends;
}

// The report's figures of the whole soak; the runs are added as they finish.
nlohmann::ordered_json reportHeader(const SoakArgs& args, const std::string& motion) {
    nlohmann::ordered_json report;
    report["project"] = args.project;
    report["dt"] = args.dtS;
    report["seconds"] = args.seconds;
    report["sample_every_s"] = args.sampleEveryS;
    report["density_scale"] = args.densityScale;
    report["rss_growth_bound_mib"] = RSS_GROWTH_BOUND_MIB;
    report["length_tolerance"] = "1e-4*h + 4*eps*(max|v0| + h)";
    report["motion"] = motion;
    report["runs"] = nlohmann::ordered_json::array();
    return report;
}

void printHeader(const SoakSetup& setup, const std::string& motion) {
    const SoakArgs& args = setup.args;
    std::printf(
        "soak of %s: %.3f s at dt %.4g s (%zu steps), wind %zu source(s), %zu collider "
        "sphere(s), %s\n",
        setup.loaded.project.name.c_str(), args.seconds, args.dtS,
        stepsFor(args.seconds, static_cast<float>(args.dtS)), setup.physics.wind.size(),
        setup.physics.colliders.size(), motion.c_str());
}

// A backend's verdict and its entry of the report.
struct BackendSoak {
    bool passed = false;
    bool stopped = false;
    nlohmann::ordered_json json;
};

// One backend's soak: a fresh field, so each starts from rest, stepped, judged and printed with
// its failures. The GPU makes the GL context on its first run and keeps it for the command.
Result<BackendSoak> soakOn(SimBackend backend, const SoakSetup& setup,
                           std::unique_ptr<gl::HeadlessContext>& context) {
    auto scene = core::buildScene(setup.loaded);
    if (!scene)
        return scene.error();
    std::string device = "CPU reference, " + std::to_string(setup.threads) +
                         (setup.threads == 1 ? " thread" : " threads");
    if (backend == SimBackend::Gpu) {
        if (!context) {
            auto created = gl::HeadlessContext::create(setup.args.glDebug);
            if (!created)
                return created.error();
            context = std::move(*created);
        }
        device = gl::rendererDescription();
    }
    const char* name = backend == SimBackend::Gpu ? "gpu" : "cpu";
    core::SceneSimulation simulation(*scene, setup.physics, setup.threads);
    // The soak watches the reference the SIMD execution is tested against (its label says so).
    simulation.setCpuPhysics(core::CpuPhysics::Scalar);
    auto run =
        soakSimulation(*scene, simulation, backend,
                       {setup.args.seconds, setup.args.sampleEveryS, name, setup.stop}, stderr);
    if (!run)
        return run.error();
    if (run->stopped)
        std::fprintf(stderr, "soak: %s: stopped after %.1f of %.1f s of game time: judged as run\n",
                     name, run->samples.back().simulatedS, setup.args.seconds);
    const SoakVerdict verdict = judgeSoakRun(*run, backend);
    printSoakRun(name, device, scene->totalBlades(), *run, verdict, backend);
    for (const std::string& failure : verdict.failures)
        printError("soak", std::string(name) + ": " + failure);
    nlohmann::ordered_json json =
        soakRunJson(name, device, scene->totalBlades(), *run, verdict, backend);
    json["stopped"] = run->stopped;
    return BackendSoak{verdict.failures.empty(), run->stopped, std::move(json)};
}

}  // namespace

int runSoak(const std::vector<std::string>& argv) {
    SoakArgs args;
    if (const auto exitCode = parseSoakArgs(argv, args))
        return *exitCode;
    if (auto writable = checkOutputWritable(args.report, "--report", "soak.json"); !writable)
        return reportFailure("soak", writable.error(), EXIT_USAGE);

    auto loaded = core::loadProject(args.project);
    if (!loaded)
        return reportFailure("soak", loaded.error(), EXIT_FAILED);
    if (auto applied = applyArgs(args, *loaded); !applied)
        return reportFailure("soak", applied.error(), EXIT_USAGE);
    auto physics = core::buildScenePhysics(*loaded, core::groundOriginOf(*loaded));
    if (!physics)
        return reportFailure("soak", physics.error(), EXIT_FAILED);
    printNotes(physics->notes);

    // Ctrl+C ends the run under way at its next step: what ran is judged, printed and saved.
    const core::InterruptStop interrupt;
    const SoakSetup setup{args, *loaded, *physics, cpuThreads(args.threads), interrupt.token()};
    const std::string motion = describeMotion(*physics);
    nlohmann::ordered_json report = reportHeader(args, motion);
    printHeader(setup, motion);
    std::unique_ptr<gl::HeadlessContext> context;
    bool passed = true;
    for (const SimBackend backend : chosenBackends(args)) {
        auto run = soakOn(backend, setup, context);
        if (!run)
            return reportFailure("soak", run.error(), EXIT_FAILED);
        report["runs"].push_back(std::move(run->json));
        passed = passed && run->passed;
        if (run->stopped)
            break;
    }
    report["passed"] = passed;
    report["stopped"] = interrupt.signal() != 0;
    if (auto written = writeOutputFile(args.report, report.dump(2) + "\n"); !written)
        return reportFailure("soak", written.error(), EXIT_FAILED);
    if (interrupt.signal() != 0) {
        std::printf("soak stopped: %s so far\n", passed ? "passed" : "FAILED");
        return interrupt.exitCode();
    }
    std::printf("soak %s\n", passed ? "passed" : "FAILED");
    return passed ? 0 : EXIT_FAILED;
}

}  // namespace grass::cli
