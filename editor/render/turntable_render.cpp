#include "render/turntable_render.h"

#include <chrono>

#include "scene/turntable.h"

namespace grass::render {

Result<void> renderTurntable(const core::Scene& scene, const core::OrbitCamera& start,
                             const OffscreenRequest& request, int frameCount,
                             const TurntableFrameSink& sink) {
    auto renderer = SceneRenderer::create(scene);
    if (!renderer)
        return renderer.error();
    gl::Framebuffer framebuffer(request.width, request.height, request.msaaSamples);
    for (int frame = 0; frame < frameCount; ++frame) {
        const auto begin = std::chrono::steady_clock::now();
        (*renderer)->render(core::turntableCamera(start, frame, frameCount), request.width,
                            request.height, framebuffer, request.options);
        glFinish();
        const std::chrono::duration<double, std::milli> elapsed =
            std::chrono::steady_clock::now() - begin;
        const gl::Rgba8Image image = framebuffer.readPixels();
        if (auto taken = sink(frame, image, (*renderer)->lastTimings(), elapsed.count()); !taken)
            return taken.error();
    }
    return {};
}

}  // namespace grass::render
