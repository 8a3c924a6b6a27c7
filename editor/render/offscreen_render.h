// Rendering a scene to pixels without a window: the path of `grass render` and the GL tests.
// The caller owns the GL context (HeadlessContext or a window's).
#pragma once

#include <vector>

#include "gl/framebuffer.h"
#include "render/scene_renderer.h"

namespace grass::render {

struct OffscreenRequest {
    int width = 1280;
    int height = 720;
    int msaaSamples = 4;
    int frames = 3;  // the first frame pays for shader/driver warm-up; timings report all
    RenderOptions options;
};

struct OffscreenResult {
    gl::Rgba8Image image;
    std::vector<double> frameWallMs;  // CPU wall time of each frame, glFinish included
    FrameTimings lastFrame;           // GPU timer queries of the last frame
};

Result<OffscreenResult> renderOffscreen(const core::Scene& scene, const core::OrbitCamera& camera,
                                        const OffscreenRequest& request);

// The project's camera by name ("" = the first); the error lists the names there are.
Result<core::OrbitCamera> projectCamera(const core::Project& project, const std::string& name);

}  // namespace grass::render
