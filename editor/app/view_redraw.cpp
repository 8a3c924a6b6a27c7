#include "app/view_redraw.h"

namespace grass::editor {

ViewInputs viewInputsOf(const render::SceneRenderer& renderer, std::uint64_t liveGeneration,
                        std::size_t physicsSteps, const core::OrbitCamera& camera,
                        ViewTarget target, const render::RenderOptions& options,
                        const core::Project& project, const core::Scene& scene) {
    ViewInputs inputs;
    inputs.renderer = &renderer;
    inputs.rendererGeneration = renderer.contentGeneration();
    inputs.liveGeneration = liveGeneration;
    inputs.physicsSteps = physicsSteps;
    inputs.camera = camera;
    inputs.width = target.width;
    inputs.height = target.height;
    inputs.samples = target.samples;
    inputs.options = options;
    // What a frame measures, not what it draws: statistics every half second, exact timings.
    inputs.options.cull.collectStats = false;
    inputs.options.exactStageTimings = false;
    if (!timeChangesThePicture(scene, options))
        inputs.options.timeS = 0.0f;
    inputs.project = project;
    // Names are drawn by the panels, not in the picture: typing one draws nothing again.
    inputs.project.name.clear();
    for (core::GrassLayer& layer : inputs.project.layers)
        layer.name.clear();
    inputs.layers.reserve(scene.layers.size());
    for (const core::LayerField& layer : scene.layers)
        inputs.layers.push_back({layer.rootColor, layer.tipColor, layer.poorRootColor,
                                 layer.poorTipColor, layer.shape, layer.tipStart,
                                 layer.liveBlades});
    return inputs;
}

bool timeChangesThePicture(const core::Scene& scene, const render::RenderOptions& options) {
    if (options.technique != core::GrassTechnique::Blades)
        return true;  // billboards sway with their own wind model
    for (const core::SceneProp& prop : scene.props)
        if (prop.path.size() > 1)
            return true;
    return options.snow.enabled != 0u && options.snow.accumulationRate != options.snow.meltRate;
}

bool viewStillDrawn(const std::optional<ViewInputs>& drawn, const ViewInputs& now,
                    bool placingBillboards) {
    return drawn && !placingBillboards && *drawn == now;
}

}  // namespace grass::editor
