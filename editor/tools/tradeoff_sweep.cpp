#include "tools/tradeoff_sweep.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "gl/headless_context.h"
#include "physics/step_count.h"
#include "render/offscreen_render.h"
#include "render/scene_physics_gpu.h"
#include "tools/tradeoff_bench.h"

namespace grass::render {

namespace {

using namespace tradeoff;

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
        setImageError(bench, frame.image, reference.image, background, result);
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

KnobResult skippedKnob(const std::string& name, const std::string& why) {
    KnobResult knob;
    knob.name = name;
    knob.skipped = why;
    return knob;
}

// An image knob whose background is the sweep's base frame (without grass, as
// backgroundWithoutGrass says); its settings come after.
ImageKnob imageKnobOn(const RenderOptions& base) {
    ImageKnob spec;
    spec.background = base;
    return spec;
}

// One setting of an image knob: the sweep's base options as `change` leaves them.
template <class Change>
ImageSetting imageSetting(const RenderOptions& base, const std::string& label, double value,
                          Change change) {
    ImageSetting s{label, value, base};
    change(s.options);
    return s;
}

ImageKnob geometryDetailKnob(const RenderOptions& base, KnobResult& knob) {
    ImageKnob spec = imageKnobOn(base);
    const bool tess = base.geometry == GeometryPath::Tessellation;
    knob.description = tess ? "tessellation level along the blade (LOD off)"
                            : "strip segments per blade (LOD off)";
    const auto detail = [&](int n) {
        return imageSetting(base, std::to_string(n), n, [tess, n](RenderOptions& o) {
            (tess ? o.tessLevel : o.stripSegments) = n;
            o.cull.lodDistanceM = 0.0f;
        });
    };
    for (const int n : {2, 4, 8, 16})
        spec.settings.push_back(detail(n));
    spec.reference = detail(32);
    spec.check = detail(64);
    return spec;
}

ImageKnob lodDistanceKnob(const RenderOptions& base, KnobResult& knob) {
    ImageKnob spec = imageKnobOn(base);
    knob.description = "LOD distance: full segments up to d, half to 3d, a quarter beyond";
    for (const double d : {2.0, 4.0, 8.0, 16.0})
        spec.settings.push_back(imageSetting(base, metres(d), d, [d](RenderOptions& o) {
            o.cull.lodDistanceM = static_cast<float>(d);
        }));
    spec.reference =
        imageSetting(base, "off", 0.0, [](RenderOptions& o) { o.cull.lodDistanceM = 0; });
    return spec;
}

ImageKnob cullDistanceKnob(const RenderOptions& base, KnobResult& knob) {
    ImageKnob spec = imageKnobOn(base);
    knob.description = "distance thinning: max distance (8 classes)";
    for (const double d : {10.0, 20.0, 40.0, 80.0, 160.0})
        spec.settings.push_back(imageSetting(base, metres(d), d, [d](RenderOptions& o) {
            o.cull.distance = true;
            o.cull.maxDistanceM = static_cast<float>(d);
        }));
    spec.reference =
        imageSetting(base, "off", 0.0, [](RenderOptions& o) { o.cull.distance = false; });
    return spec;
}

// The snow's error is taken over the pixels snow changes: the background is the grass without
// snow, not the mesh without grass.
ImageKnob snowMapKnob(const RenderOptions& base, KnobResult& knob) {
    ImageKnob spec = imageKnobOn(base);
    knob.description = "snow depth map resolution × samples per lookup";
    const auto snowSetting = [&](int resolution, int samples) {
        return imageSetting(base, std::to_string(resolution) + "² × " + std::to_string(samples),
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
    return spec;
}

ImageKnob billboardFadeKnob(const RenderOptions& base, KnobResult& knob) {
    ImageKnob spec = imageKnobOn(base);
    knob.description = "hybrid cross-fade start (end = 1.6 × start)";
    const auto fade = [&](double start) {
        return imageSetting(base, metres(start), start, [start](RenderOptions& o) {
            o.billboards.crossFadeM = {start, 1.6 * start};
        });
    };
    for (const double d : {4.0, 8.0, 16.0, 32.0})
        spec.settings.push_back(fade(d));
    spec.reference = fade(1000.0);
    // Without layers the blades draw nothing; blades technique: no billboards either.
    spec.background.technique = core::GrassTechnique::Blades;
    return spec;
}

// Why the project cannot sweep the knob ("": it can).
std::string whySkipped(const std::string& name, const core::Project& project,
                       const RenderOptions& base) {
    if (name == "distance_classes" && !base.cull.distance)
        return "the project does not thin (thinning_distance 0)";
    if (name == "ao_kernel" && (project.lighting.model != core::LightingModel::Grass ||
                                project.lighting.aoRadiusM <= 0.0f))
        return "the project's lighting has no AO";
    if (name == "snow_map" && project.snow.enabled == 0u)
        return "the project has no snow (snow off)";
    if (name == "billboard_fade" && project.render.technique != core::GrassTechnique::Hybrid)
        return "the project draws no billboards (technique not hybrid)";
    return "";
}

// What every knob of the sweep measures with.
struct Sweep {
    const core::Project& project;
    const core::Scene& grown;  // at rest: the physics knob steps it itself
    const core::ScenePhysics& physics;
    const core::Scene& scene;  // at the sweep's scene time: what the image knobs draw
    const TradeoffOptions& options;
    const RenderOptions& base;
    ImageBench& bench;
};

// The image knob named `name`: its settings, drawn and compared with its reference.
KnobResult measureImageKnobNamed(const std::string& name, const Sweep& sweep,
                                 const std::string& prefix) {
    KnobResult knob;
    knob.name = name;
    ImageKnob spec = imageKnobOn(sweep.base);
    if (name == "geometry_detail")
        spec = geometryDetailKnob(sweep.base, knob);
    else if (name == "lod_distance")
        spec = lodDistanceKnob(sweep.base, knob);
    else if (name == "cull_distance")
        spec = cullDistanceKnob(sweep.base, knob);
    else if (name == "snow_map")
        spec = snowMapKnob(sweep.base, knob);
    else if (name == "billboard_fade")
        spec = billboardFadeKnob(sweep.base, knob);
    return measureImageKnob(sweep.bench, spec, std::move(knob), prefix);
}

Result<KnobResult> measureKnob(const std::string& name, const Sweep& sweep,
                               const std::string& prefix) {
    if (const std::string why = whySkipped(name, sweep.project, sweep.base); !why.empty())
        return skippedKnob(name, why);
    if (name == "physics_step")
        return measurePhysicsKnob(sweep.grown, sweep.physics, sweep.options, prefix);
    if (name == "distance_classes")
        return measureClassesKnob(sweep.bench, sweep.scene, prefix);
    if (name == "ao_kernel")
        return measureAoKnob(sweep.bench, sweep.scene, sweep.project.lighting, prefix);
    return measureImageKnobNamed(name, sweep, prefix);
}

// The figures of the whole sweep; the knobs and the geometry are added as they are known.
TradeoffReport startReport(const core::Project& project, const TradeoffOptions& options,
                           std::size_t blades) {
    TradeoffReport report;
    report.project = project.name;
    report.device = gl::rendererDescription();
    report.width = options.width;
    report.height = options.height;
    report.frames = options.frames;
    report.msaaSamples = options.msaaSamples;
    report.sceneTimeS = options.sceneTimeS;
    report.physicsSeconds = options.physicsSeconds;
    report.blades = blades;
    return report;
}

// The images show the field as the project's own physics leaves it at sceneTimeS.
Result<core::Scene> sceneAtTime(const core::Scene& grown, const core::ScenePhysics& physics,
                                const TradeoffOptions& options) {
    core::Scene scene = grown;
    core::SceneSimulation simulation(scene, physics, 1);
    auto gpu = ScenePhysicsGpu::create(scene);
    if (!gpu)
        return gpu.error();
    const auto steps = core::simulationSteps(options.sceneTimeS, physics.params.dtS, "--time");
    if (!steps)
        return steps.error();
    for (std::size_t i = 0; i < *steps; ++i) {
        gpu->step(simulation.physics(), simulation.timeS());
        simulation.advanceClock();
    }
    gpu->readBack(scene, simulation);
    return scene;
}

// The knobs to sweep: options.knobs, or every knob when it is empty.
Result<std::vector<std::string>> knobsToSweep(const TradeoffOptions& options) {
    const std::vector<std::string> all = tradeoffKnobNames();
    std::vector<std::string> knobs = options.knobs.empty() ? all : options.knobs;
    for (const std::string& name : knobs)
        if (std::find(all.begin(), all.end(), name) == all.end())
            return makeError("--knobs", "unknown knob \"" + name + "\"");
    return knobs;
}

}  // namespace

std::vector<std::string> tradeoffKnobNames() {
    return {"physics_step",     "geometry_detail", "lod_distance",   "cull_distance",
            "distance_classes", "snow_map",        "billboard_fade", "ao_kernel"};
}

std::string tradeoffKnobList() {
    std::string out;
    for (const std::string& name : tradeoffKnobNames())
        out += (out.empty() ? "" : ",") + name;
    return out;
}

Result<TradeoffReport> runTradeoffSweep(const core::LoadedProject& loaded,
                                        const TradeoffOptions& options) {
    const auto knobs = knobsToSweep(options);
    if (!knobs)
        return knobs.error();
    const auto sweepStart = Clock::now();
    const core::Project& project = loaded.project;
    auto grown = core::buildScene(loaded);
    if (!grown)
        return grown.error();
    auto physics = core::buildScenePhysics(loaded, grown->groundOrigin);
    if (!physics)
        return physics.error();
    auto camera = projectCamera(project, options.camera);
    if (!camera)
        return camera.error();
    TradeoffReport report = startReport(project, options, grown->totalBlades());

    const auto scene = sceneAtTime(*grown, *physics, options);
    if (!scene)
        return scene.error();
    core::Scene bare = *scene;
    bare.layers.clear();
    auto renderer = SceneRenderer::create(*scene);
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
    const Sweep sweep{project, *grown, *physics, *scene, options, base, bench};

    for (std::size_t k = 0; k < knobs->size(); ++k) {
        if (options.stop.stop_requested()) {
            if (options.progress)
                options.progress("stopped after " + std::to_string(k) + " of " +
                                 std::to_string(knobs->size()) +
                                 " knob(s): the knobs measured follow");
            break;
        }
        const std::string& name = (*knobs)[k];
        const std::string prefix =
            "knob " + std::to_string(k + 1) + "/" + std::to_string(knobs->size()) + " " + name;
        if (options.progress)
            options.progress(prefix);
        auto knob = measureKnob(name, sweep, prefix);
        if (!knob)
            return knob.error();
        report.knobs.push_back(std::move(*knob));
    }
    report.wallS = msSince(sweepStart) / 1000.0;
    return report;
}

}  // namespace grass::render
