// grass tradeoff's physics_step knob: the GPU physics at several steps against a fine reference,
// tips compared every sampleEveryS (tradeoff_sweep.h).
#include <cmath>
#include <tuple>

#include "render/scene_physics_gpu.h"
#include "gl/timer_query.h"
#include "tools/tradeoff_bench.h"

namespace grass::render::tradeoff {

namespace {

// One physics run of the sweep: tips sampled every sampleEveryS, cost of the steps alone.
struct PhysicsRun {
    std::vector<std::vector<glm::vec3>> tips;  // per sample: every slot's v2 (layer-major)
    std::vector<float> heights;
    double wallMs = 0.0, gpuMs = 0.0;
};

Result<PhysicsRun> runPhysics(const core::Scene& grown, const core::ScenePhysics& physics,
                              float stepS, const TradeoffOptions& options,
                              const std::string& what) {
    core::Scene scene = grown;
    core::ScenePhysics params = physics;
    params.params.dtS = stepS;
    params.params.maxSubstepS = stepS;
    params.params.maxSubsteps = 1;
    core::SceneSimulation simulation(scene, params, 1);
    auto gpu = ScenePhysicsGpu::create(scene);
    if (!gpu)
        return gpu.error();
    const auto stepsPerSample =
        static_cast<std::size_t>(std::llround(options.sampleEveryS / stepS));
    const auto samples =
        static_cast<std::size_t>(std::llround(options.physicsSeconds / options.sampleEveryS));
    PhysicsRun run;
    for (const core::LayerField& layer : scene.layers)
        for (const core::Blade& blade : layer.patched.blades)
            run.heights.push_back(blade.h());
    gl::GpuTimer timer;
    glFinish();
    for (std::size_t sample = 0; sample < samples; ++sample) {
        if (options.progress && sample % 10 == 9)
            options.progress(what + ": sample " + std::to_string(sample + 1) + "/" +
                             std::to_string(samples));
        const auto start = Clock::now();
        timer.begin();
        for (std::size_t i = 0; i < stepsPerSample; ++i) {
            gpu->step(simulation.physics(), simulation.timeS());
            simulation.advanceClock();
        }
        timer.end();
        glFinish();
        run.wallMs += msSince(start);
        run.gpuMs += timer.milliseconds();
        gpu->readBack(scene, simulation);
        std::vector<glm::vec3> tips;
        tips.reserve(run.heights.size());
        for (const core::LayerField& layer : scene.layers)
            for (const core::Blade& blade : layer.patched.blades)
                tips.push_back(blade.v2());
        run.tips.push_back(std::move(tips));
    }
    return run;
}

// Max and mean |v2 − v2_ref| / h over every live blade and sample.
std::pair<double, double> tipError(const PhysicsRun& run, const PhysicsRun& reference) {
    double sum = 0.0, worst = 0.0;
    std::size_t count = 0;
    for (std::size_t s = 0; s < run.tips.size() && s < reference.tips.size(); ++s)
        for (std::size_t i = 0; i < run.heights.size(); ++i) {
            if (!(run.heights[i] > 1e-6f))
                continue;
            const double e = glm::distance(run.tips[s][i], reference.tips[s][i]) / run.heights[i];
            sum += e;
            worst = std::max(worst, e);
            ++count;
        }
    return {worst, count > 0 ? sum / static_cast<double>(count) : 0.0};
}

}  // namespace

Result<KnobResult> measurePhysicsKnob(const core::Scene& grown, const core::ScenePhysics& physics,
                                      const TradeoffOptions& options, const std::string& prefix) {
    KnobResult knob;
    knob.name = "physics_step";
    knob.description = "physics integration step (one substep per step; dtS = maxSubstepS)";
    knob.errorMetric =
        "mean tip error |v2 − v2_ref| / h over all blades and samples (blade heights)";
    knob.costMetric = "physics wall ms per 1/60 s of simulated time (GPU compute, glFinish)";
    const std::vector<double> steps = {1.0 / 30.0, 1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0};
    const double referenceStep = 1.0 / 960.0, checkStep = 1.0 / 1920.0;
    auto reference = runPhysics(grown, physics, static_cast<float>(referenceStep), options,
                                prefix + " reference " + fraction(referenceStep));
    if (!reference)
        return reference.error();
    const auto result = [&](const PhysicsRun& run, double step) {
        SettingResult s;
        s.label = fraction(step);
        s.value = step;
        const double frames60 = options.physicsSeconds * 60.0;
        s.costMs = {run.wallMs / frames60, run.wallMs / frames60, run.wallMs / frames60};
        s.physicsGpuMs = run.gpuMs / frames60;
        std::tie(s.errorMax, s.error) = tipError(run, *reference);
        return s;
    };
    for (const double step : steps) {
        auto run = runPhysics(grown, physics, static_cast<float>(step), options,
                              prefix + " " + fraction(step));
        if (!run)
            return run.error();
        knob.settings.push_back(result(*run, step));
    }
    SettingResult ref = result(*reference, referenceStep);
    ref.reference = true;
    knob.settings.push_back(ref);
    auto check = runPhysics(grown, physics, static_cast<float>(checkStep), options,
                            prefix + " check " + fraction(checkStep));
    if (!check)
        return check.error();
    SettingResult checked = result(*check, checkStep);
    checked.check = true;
    knob.checkLabel = checked.label;
    knob.referenceCheckError = checked.error;
    knob.settings.push_back(checked);
    finishKnob(knob);
    return knob;
}

}  // namespace grass::render::tradeoff
