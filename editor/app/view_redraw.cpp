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

bool viewStillDrawn(const std::optional<ViewInputs>& drawn, const ViewInputs& now,
                    bool placingBillboards) {
    return drawn && !placingBillboards && *drawn == now;
}

}  // namespace grass::editor
