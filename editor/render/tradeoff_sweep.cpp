#include "tradeoff_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <tuple>

#include "framebuffer.h"
#include "headless_context.h"
#include "offscreen_render.h"
#include "scene_physics_gpu.h"
#include "scene_renderer.h"
#include "timer_query.h"
#include "util/color_difference.h"
#include "util/pareto.h"

namespace grass::render {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

Spread spreadOf(const std::vector<double>& values) {
    if (values.empty())
        return {};
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    return {median(values), *low, *high};
}

// A channel differing by more than this from the feature-free frame marks a pixel as touched by
// the feature: 8-bit rounding of the same colour never moves a channel by more than 1.
constexpr int MASK_THRESHOLD = 2;
// The reference has converged when refining it changes the result by less than a tenth of what
// a user can see: a tenth of a just-noticeable difference (ΔE76 2.3) in the image, a thousandth
// of a blade height at the tips (a tenth of the balanced preset's bound).
constexpr double CONVERGED_DELTA_E = 0.23;
constexpr double CONVERGED_TIP_ERROR = 0.001;
// It also resolves every swept error when the check differs from it by less than this share of
// the smallest one: then each swept error is known to within a factor of 2 and their order
// holds. Strip segments on meadow do not (a floor of ~0.15–0.19 ΔE from 16 to 128 segments,
// isolated pixels spread over the field), so settings below ~0.4 ΔE are not told apart there.
constexpr double RESOLVED_SHARE = 0.5;

void markTouched(const gl::Rgba8Image& image, const gl::Rgba8Image& background,
                 std::vector<std::uint8_t>& mask) {
    for (std::size_t i = 0; i < mask.size(); ++i)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(int(image.pixels[4 * i + c]) - int(background.pixels[4 * i + c])) >
                MASK_THRESHOLD)
                mask[i] = 1;
}

std::string fraction(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "1/%.0f s", 1.0 / seconds);
    return text;
}

std::string metres(double m) {
    char text[32];
    std::snprintf(text, sizeof text, "%g m", m);
    return text;
}

struct Frame {
    gl::Rgba8Image image;
    SettingResult timing;
};

// Everything the image knobs share: the scene at the sweep's time, drawn with grass and without.
struct ImageBench {
    SceneRenderer& renderer;
    SceneRenderer& noGrass;
    core::OrbitCamera camera;
    gl::Framebuffer framebuffer;
    RenderOptions base;
    const TradeoffOptions& options;

    Frame draw(SceneRenderer& target, const RenderOptions& render, const std::string& what) {
        Frame frame;
        std::vector<double> wall, mesh, cull, grass, billboard, snow;
        for (int i = 0; i <= options.frames; ++i) {
            if (options.progress && i > 0)
                options.progress(what + ": frame " + std::to_string(i) + "/" +
                                 std::to_string(options.frames));
            const auto start = Clock::now();
            target.render(camera, options.width, options.height, framebuffer.id(), render);
            glFinish();
            const double ms = msSince(start);
            // Frame 0 pays for shader compiles and first allocations (a new snow map size).
            if (i == 0)
                continue;
            const FrameTimings t = target.lastTimings();
            wall.push_back(ms);
            mesh.push_back(t.meshMs);
            cull.push_back(t.cullMs);
            grass.push_back(t.grassMs);
            billboard.push_back(t.billboardMs);
            snow.push_back(t.snowMs);
            frame.timing.bladesDrawn = t.bladesDrawn;
        }
        frame.timing.costMs = spreadOf(wall);
        frame.timing.meshMs = median(mesh);
        frame.timing.cullMs = median(cull);
        frame.timing.grassMs = median(grass);
        frame.timing.billboardMs = median(billboard);
        frame.timing.snowMs = median(snow);
        frame.image = framebuffer.readPixels();
        return frame;
    }
};

struct ImageSetting {
    std::string label;
    double value = 0.0;
    RenderOptions options;
};

// The settings, the reference and (optionally) the check; background: the frame without the
// feature, whose difference marks the pixels the error is taken over.
struct ImageKnob {
    std::vector<ImageSetting> settings;
    ImageSetting reference;
    std::optional<ImageSetting> check;
    RenderOptions background;
    bool backgroundWithoutGrass = true;
};

void finishKnob(KnobResult& knob) {
    std::vector<core::CostError> points;
    for (const SettingResult& s : knob.settings)
        points.push_back(s.check ? core::CostError{NAN, NAN}
                                 : core::CostError{s.costMs.median, s.error});
    const std::vector<bool> front = core::paretoFront(points);
    double smallest = INFINITY;
    for (std::size_t i = 0; i < knob.settings.size(); ++i) {
        knob.settings[i].pareto = front[i];
        if (!knob.settings[i].reference && !knob.settings[i].check)
            smallest = std::min(smallest, knob.settings[i].error);
    }
    if (!knob.checkLabel.empty()) {
        knob.convergedBelow =
            knob.name == "physics_step" ? CONVERGED_TIP_ERROR : CONVERGED_DELTA_E;
        knob.referenceConverged = knob.referenceCheckError < knob.convergedBelow;
        knob.referenceResolvesSweep = knob.referenceCheckError < RESOLVED_SHARE * smallest;
    }
}

KnobResult measureImageKnob(ImageBench& bench, const ImageKnob& spec, KnobResult knob,
                            const std::string& prefix) {
    knob.errorMetric = "mean CIELAB ΔE76 over the pixels the feature touches in either image";
    knob.costMetric = "frame wall ms (median of the timed frames, glFinish included)";
    SceneRenderer& backgroundRenderer =
        spec.backgroundWithoutGrass ? bench.noGrass : bench.renderer;
    const gl::Rgba8Image background =
        bench.draw(backgroundRenderer, spec.background, prefix + " background").image;
    const Frame reference = bench.draw(bench.renderer, spec.reference.options,
                                       prefix + " reference " + spec.reference.label);
    const auto compare = [&](const Frame& frame, SettingResult& result) {
        std::vector<std::uint8_t> mask(
            bench.framebuffer.width() * std::size_t(bench.framebuffer.height()), 0);
        markTouched(frame.image, background, mask);
        markTouched(reference.image, background, mask);
        const core::MaskedDeltaE e =
            core::maskedDeltaE76(frame.image.pixels, reference.image.pixels, mask);
        result.error = e.meanDeltaE;
        result.errorMax = e.maxDeltaE;
        result.pixels = e.pixels;
    };
    for (const ImageSetting& setting : spec.settings) {
        const Frame frame =
            bench.draw(bench.renderer, setting.options, prefix + " " + setting.label);
        SettingResult result = frame.timing;
        result.label = setting.label;
        result.value = setting.value;
        compare(frame, result);
        knob.settings.push_back(result);
    }
    SettingResult ref = reference.timing;
    ref.label = spec.reference.label;
    ref.value = spec.reference.value;
    ref.reference = true;
    compare(reference, ref);
    knob.settings.push_back(ref);
    if (spec.check) {
        const Frame frame =
            bench.draw(bench.renderer, spec.check->options, prefix + " check " + spec.check->label);
        SettingResult result = frame.timing;
        result.label = spec.check->label;
        result.value = spec.check->value;
        result.check = true;
        compare(frame, result);
        knob.checkLabel = spec.check->label;
        knob.referenceCheckError = result.error;
        knob.settings.push_back(result);
    }
    finishKnob(knob);
    return knob;
}

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

// The AO bake (SPEC §10): neighbours summed per cluster in cells of `cellSigmas` σ, against
// the exact sums. Cost is the bake's CPU wall time (it runs when the scene is built or painted);
// the error is the grass's ΔE76 in the frame drawn with that bake.
Result<KnobResult> measureAoKnob(ImageBench& bench, const core::Scene& scene,
                                 const core::GrassLightingDesc& lighting, const std::string& prefix) {
    KnobResult knob;
    knob.name = "ao_kernel";
    knob.description = "AO and normal-blur bake: cluster cell side in kernel σ (exact: every "
                       "neighbour on its own)";
    knob.errorMetric = "mean CIELAB ΔE76 over the pixels the grass touches in either image";
    knob.costMetric = "bake wall ms over all layers (CPU, every core; median of the bakes)";
    const gl::Rgba8Image background =
        bench.draw(bench.noGrass, bench.base, prefix + " background").image;
    const auto bakeAndDraw = [&](float cellSigmas,
                                 const std::string& label) -> Result<std::pair<Frame, Spread>> {
        core::Scene baked = scene;
        core::BladeShadingParams params = core::bladeShadingParams(lighting);
        params.cellSigmas = cellSigmas;
        std::vector<double> bakeMs;
        const int bakes = std::clamp(bench.options.frames, 1, 3);
        for (int b = 0; b < bakes; ++b) {
            double ms = 0.0;
            for (core::LayerField& layer : baked.layers) {
                const auto start = Clock::now();
                auto shading = core::bakeBladeShading(layer.patched.blades, params, layer.seed);
                if (!shading)
                    return shading.error();
                ms += msSince(start);
                // Only the AO and the blurred normal change; water, age and wilt stay.
                for (std::size_t i = 0; i < shading->size() && i < layer.shading.size(); ++i)
                    (*shading)[i].waterAge = layer.shading[i].waterAge;
                layer.shading = std::move(*shading);
            }
            bakeMs.push_back(ms);
        }
        auto renderer = SceneRenderer::create(baked);
        if (!renderer)
            return renderer.error();
        Frame frame = bench.draw(**renderer, bench.base, prefix + " " + label);
        return std::pair{std::move(frame), spreadOf(bakeMs)};
    };
    auto reference = bakeAndDraw(0.0f, "reference exact");
    if (!reference)
        return reference.error();
    const auto result = [&](const std::pair<Frame, Spread>& run, const std::string& label,
                            double value) {
        SettingResult s = run.first.timing;
        s.label = label;
        s.value = value;
        s.costMs = run.second;
        std::vector<std::uint8_t> mask(
            bench.framebuffer.width() * std::size_t(bench.framebuffer.height()), 0);
        markTouched(run.first.image, background, mask);
        markTouched(reference->first.image, background, mask);
        const core::MaskedDeltaE e =
            core::maskedDeltaE76(run.first.image.pixels, reference->first.image.pixels, mask);
        s.error = e.meanDeltaE;
        s.errorMax = e.maxDeltaE;
        s.pixels = e.pixels;
        return s;
    };
    for (const float cell : {2.0f, 1.0f, 0.5f, 0.25f}) {
        char label[32];
        std::snprintf(label, sizeof label, "%g σ", static_cast<double>(cell));
        auto run = bakeAndDraw(cell, label);
        if (!run)
            return run.error();
        knob.settings.push_back(result(*run, label, cell));
    }
    SettingResult ref = result(*reference, "exact", 0.0);
    ref.reference = true;
    knob.settings.push_back(ref);
    finishKnob(knob);
    return knob;
}

// Distance thinning keeps ceil(n·(1 − d/dmax))/n of the blades at distance d (cull.comp): n
// classes approximate the continuous falloff 1 − d/dmax from above. Which blades a class count
// keeps differs with n (index mod n), so images of two counts differ blade by blade and pixel
// ΔE cannot rank them; the error is the density's instead: the mean excess kept share over the
// live blades within dmax, from the blades' distances as the cull pass measures them. Cost is
// the frame.
KnobResult measureClassesKnob(ImageBench& bench, const core::Scene& scene,
                              const std::string& prefix) {
    KnobResult knob;
    knob.name = "distance_classes";
    char description[96];
    std::snprintf(description, sizeof description,
                  "distance thinning classes at the project's thinning distance (%g m)",
                  static_cast<double>(bench.base.cull.maxDistanceM));
    knob.description = description;
    knob.errorMetric = "mean kept share above the continuous 1 − d/dmax over the blades within "
                       "dmax (density error)";
    knob.costMetric = "frame wall ms (median of the timed frames, glFinish included)";
    const glm::vec3 eye = bench.camera.position();
    const float dmax = bench.base.cull.maxDistanceM;
    std::vector<float> falloff;  // 1 − d/dmax of every live blade within dmax
    for (const core::LayerField& layer : scene.layers)
        for (const core::Blade& blade : layer.patched.blades) {
            if (!(blade.h() > 0.0f))
                continue;
            const glm::vec3 up = glm::normalize(blade.up());
            const glm::vec3 toBlade = blade.v0() - eye;
            const float d = glm::length(toBlade - up * glm::dot(toBlade, up));
            if (d < dmax)
                falloff.push_back(1.0f - d / dmax);
        }
    const auto densityError = [&](int n) {
        double sum = 0.0;
        for (const float f : falloff)
            sum += std::ceil(double(n) * f) / n - f;
        return falloff.empty() ? 0.0 : sum / double(falloff.size());
    };
    const auto measure = [&](int n, const std::string& what) {
        RenderOptions options = bench.base;
        options.cull.distanceClasses = n;
        SettingResult s = bench.draw(bench.renderer, options, prefix + " " + what).timing;
        s.label = std::to_string(n);
        s.value = n;
        s.error = densityError(n);
        s.errorMax = 1.0 / n;  // a class's share: the largest excess at any distance
        s.pixels = falloff.size();
        return s;
    };
    for (const int n : {2, 4, 8, 16})
        knob.settings.push_back(measure(n, std::to_string(n)));
    // The reference is the continuous falloff, against which every error above is exact; 64
    // classes stand in for it in the frame (its own small error is listed, not zeroed).
    SettingResult reference = measure(64, "reference 64");
    reference.label = "64 (≈ continuous)";
    reference.reference = true;
    knob.settings.push_back(reference);
    finishKnob(knob);
    return knob;
}

KnobResult skippedKnob(const std::string& name, const std::string& why) {
    KnobResult knob;
    knob.name = name;
    knob.skipped = why;
    return knob;
}

}  // namespace

std::vector<std::string> tradeoffKnobNames() {
    return {"physics_step", "geometry_detail", "lod_distance",   "cull_distance",
            "distance_classes", "snow_map",  "billboard_fade", "ao_kernel"};
}

Result<TradeoffReport> runTradeoffSweep(const core::LoadedProject& loaded,
                                        const TradeoffOptions& options) {
    const std::vector<std::string> all = tradeoffKnobNames();
    std::vector<std::string> knobs = options.knobs.empty() ? all : options.knobs;
    for (const std::string& name : knobs)
        if (std::find(all.begin(), all.end(), name) == all.end())
            return makeError("--knobs", "unknown knob \"" + name + "\"");
    const auto sweepStart = Clock::now();
    const core::Project& project = loaded.project;
    auto grown = core::buildScene(loaded);
    if (!grown)
        return grown.error();
    auto physics = core::buildScenePhysics(loaded);
    if (!physics)
        return physics.error();
    auto camera = projectCamera(project, options.camera);
    if (!camera)
        return camera.error();

    TradeoffReport report;
    report.project = project.name;
    report.device = gl::rendererDescription();
    report.width = options.width;
    report.height = options.height;
    report.frames = options.frames;
    report.msaaSamples = options.msaaSamples;
    report.sceneTimeS = options.sceneTimeS;
    report.physicsSeconds = options.physicsSeconds;
    report.blades = grown->totalBlades();

    // The images show the field as the project's own physics leaves it at sceneTimeS.
    core::Scene scene = *grown;
    {
        core::SceneSimulation simulation(scene, *physics, 1);
        auto gpu = ScenePhysicsGpu::create(scene);
        if (!gpu)
            return gpu.error();
        const auto steps =
            static_cast<std::size_t>(std::llround(options.sceneTimeS / physics->params.dtS));
        for (std::size_t i = 0; i < steps; ++i) {
            gpu->step(simulation.physics(), simulation.timeS());
            simulation.advanceClock();
        }
        gpu->readBack(scene, simulation);
    }
    core::Scene bare = scene;
    bare.layers.clear();
    auto renderer = SceneRenderer::create(scene);
    if (!renderer)
        return renderer.error();
    auto noGrass = SceneRenderer::create(bare);
    if (!noGrass)
        return noGrass.error();
    RenderOptions base = renderOptionsFor(project, gl::isSoftwareRenderer());
    base.timeS = options.sceneTimeS;
    report.geometry = geometryPathLabel(base.geometry);
    ImageBench bench{
        **renderer, **noGrass,
        *camera,    gl::Framebuffer(options.width, options.height, options.msaaSamples),
        base,       options};

    for (std::size_t k = 0; k < knobs.size(); ++k) {
        const std::string& name = knobs[k];
        const std::string prefix =
            "knob " + std::to_string(k + 1) + "/" + std::to_string(knobs.size()) + " " + name;
        if (options.progress)
            options.progress(prefix);
        if (name == "physics_step") {
            auto knob = measurePhysicsKnob(*grown, *physics, options, prefix);
            if (!knob)
                return knob.error();
            report.knobs.push_back(std::move(*knob));
            continue;
        }
        if (name == "distance_classes") {
            if (!base.cull.distance)
                report.knobs.push_back(
                    skippedKnob(name, "the project does not thin (thinning_distance 0)"));
            else
                report.knobs.push_back(measureClassesKnob(bench, scene, prefix));
            continue;
        }
        if (name == "ao_kernel") {
            if (project.lighting.model != core::LightingModel::Grass ||
                project.lighting.aoRadiusM <= 0.0f) {
                report.knobs.push_back(skippedKnob(name, "the project's lighting has no AO"));
                continue;
            }
            auto knob = measureAoKnob(bench, scene, project.lighting, prefix);
            if (!knob)
                return knob.error();
            report.knobs.push_back(std::move(*knob));
            continue;
        }
        ImageKnob spec;
        spec.background = base;
        KnobResult knob;
        knob.name = name;
        const auto setting = [&](const std::string& label, double value, auto change) {
            ImageSetting s{label, value, base};
            change(s.options);
            return s;
        };
        if (name == "geometry_detail") {
            const bool tess = base.geometry == GeometryPath::Tessellation;
            knob.description = tess ? "tessellation level along the blade (LOD off)"
                                    : "strip segments per blade (LOD off)";
            const auto detail = [&](int n) {
                return setting(std::to_string(n), n, [tess, n](RenderOptions& o) {
                    (tess ? o.tessLevel : o.stripSegments) = n;
                    o.cull.lodDistanceM = 0.0f;
                });
            };
            for (const int n : {2, 4, 8, 16})
                spec.settings.push_back(detail(n));
            spec.reference = detail(32);
            spec.check = detail(64);
        } else if (name == "lod_distance") {
            knob.description = "LOD distance: full segments up to d, half to 3d, a quarter beyond";
            for (const double d : {2.0, 4.0, 8.0, 16.0})
                spec.settings.push_back(setting(metres(d), d, [d](RenderOptions& o) {
                    o.cull.lodDistanceM = static_cast<float>(d);
                }));
            spec.reference = setting("off", 0.0, [](RenderOptions& o) { o.cull.lodDistanceM = 0; });
        } else if (name == "cull_distance") {
            knob.description = "distance thinning: max distance (8 classes)";
            for (const double d : {10.0, 20.0, 40.0, 80.0, 160.0})
                spec.settings.push_back(setting(metres(d), d, [d](RenderOptions& o) {
                    o.cull.distance = true;
                    o.cull.maxDistanceM = static_cast<float>(d);
                }));
            spec.reference = setting("off", 0.0, [](RenderOptions& o) { o.cull.distance = false; });
        } else if (name == "snow_map") {
            if (project.snow.enabled == 0u) {
                report.knobs.push_back(skippedKnob(name, "the project has no snow (snow off)"));
                continue;
            }
            knob.description = "snow depth map resolution × samples per lookup";
            const auto snowSetting = [&](int resolution, int samples) {
                return setting(std::to_string(resolution) + "² × " + std::to_string(samples),
                               resolution * 100 + samples, [=](RenderOptions& o) {
                                   o.snow.mapResolution = static_cast<std::uint32_t>(resolution);
                                   o.snow.samples = static_cast<std::uint32_t>(samples);
                               });
            };
            for (const int resolution : {512, 1024, 2048})
                for (const int samples : {1, 4, 8, 16})
                    spec.settings.push_back(snowSetting(resolution, samples));
            spec.reference = snowSetting(2048, 32);
            spec.check = snowSetting(4096, 32);
            spec.background.snow.enabled = 0u;
            spec.backgroundWithoutGrass = false;
        } else if (name == "billboard_fade") {
            if (project.render.technique != core::GrassTechnique::Hybrid) {
                report.knobs.push_back(
                    skippedKnob(name, "the project draws no billboards (technique not hybrid)"));
                continue;
            }
            knob.description = "hybrid cross-fade start (end = 1.6 × start)";
            const auto fade = [&](double start) {
                return setting(metres(start), start, [start](RenderOptions& o) {
                    o.billboards.crossFadeM = {start, 1.6 * start};
                });
            };
            for (const double d : {4.0, 8.0, 16.0, 32.0})
                spec.settings.push_back(fade(d));
            spec.reference = fade(1000.0);
            // Without layers the blades draw nothing; blades technique: no billboards either.
            spec.background.technique = core::GrassTechnique::Blades;
        }
        report.knobs.push_back(measureImageKnob(bench, spec, std::move(knob), prefix));
    }
    report.wallS = msSince(sweepStart) / 1000.0;
    return report;
}

}  // namespace grass::render
