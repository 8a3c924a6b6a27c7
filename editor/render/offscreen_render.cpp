#include "render/offscreen_render.h"

#include <chrono>

namespace grass::render {

Result<OffscreenResult> renderOffscreen(const core::Scene& scene, const core::OrbitCamera& camera,
                                        const OffscreenRequest& request) {
    auto renderer = SceneRenderer::create(scene);
    if (!renderer)
        return renderer.error();
    gl::Framebuffer framebuffer(request.width, request.height, request.msaaSamples);
    OffscreenResult result;
    for (int frame = 0; frame < std::max(request.frames, 1); ++frame) {
        const auto start = std::chrono::steady_clock::now();
        (*renderer)->render(camera, request.width, request.height, framebuffer, request.options);
        glFinish();
        const std::chrono::duration<double, std::milli> elapsed =
            std::chrono::steady_clock::now() - start;
        result.frameWallMs.push_back(elapsed.count());
    }
    result.lastFrame = (*renderer)->lastTimings();
    result.image = framebuffer.readPixels();
    return result;
}

Result<core::OrbitCamera> projectCamera(const core::Project& project, const std::string& name) {
    std::string names;
    for (const auto& camera : project.cameras) {
        if (name.empty() || camera.name == name)
            return core::OrbitCamera::lookAt(camera.position, camera.target,
                                             glm::radians(camera.fovYDeg));
        names += (names.empty() ? "" : ", ") + camera.name;
    }
    if (project.cameras.empty())
        return makeError("--camera", "the project has no camera");
    return makeError("--camera",
                     "no camera named \"" + name + "\" (the project has: " + names + ")");
}

}  // namespace grass::render
