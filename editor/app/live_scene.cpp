#include "app/live_scene.h"

#include <cstdio>

namespace grass::editor {

// `prepare` runs on the grown scene before the GPU sees it (painted maps carried over).
Result<Live> buildLive(const core::LoadedProject& loaded, bool withPhysics,
                       const std::function<Result<void>(core::Scene&)>& prepare) {
    auto scene = core::buildScene(loaded);
    if (!scene)
        return scene.error();
    for (const auto& note : scene->notes)
        std::fprintf(stderr, "note: %s\n", note.c_str());
    if (prepare)
        if (auto prepared = prepare(*scene); !prepared)
            return prepared.error();
    Live live;
    live.scene = std::make_unique<core::Scene>(std::move(*scene));
    live.tools = std::make_unique<SceneTools>(*live.scene, loaded.project.lighting);
    auto renderer = render::SceneRenderer::create(*live.scene);
    if (!renderer)
        return renderer.error();
    live.renderer = std::move(*renderer);
    if (withPhysics) {
        auto built = core::buildScenePhysics(loaded);
        if (!built)
            return built.error();
        for (const auto& note : built->notes)
            std::fprintf(stderr, "note: %s\n", note.c_str());
        auto gpu = render::ScenePhysicsGpu::createOn(*live.scene, live.renderer->bladeBuffers());
        if (!gpu)
            return gpu.error();
        live.physics.emplace(LivePhysics{std::move(*built), std::move(*gpu)});
    }
    return live;
}

// Puts every layer's blades back at rest on the GPU and restarts the simulation from there
// (keeping its step count).
Result<void> resetPhysics(Live& live) {
    for (std::size_t layer = 0; layer < live.scene->layers.size(); ++layer) {
        core::RegrowReport all;
        for (std::uint32_t p = 0; p < live.scene->layers[layer].patched.patches.size(); ++p)
            all.patches.push_back(p);
        live.renderer->uploadRegrown(layer, all);
    }
    auto gpu = render::ScenePhysicsGpu::createOn(*live.scene, live.renderer->bladeBuffers());
    if (!gpu)
        return gpu.error();
    live.physics->gpu = std::move(*gpu);
    return {};
}

}  // namespace grass::editor
