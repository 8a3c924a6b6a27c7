// Drawing a glTF as a stock viewer would (core/mesh/gltf_view.h): the check that an export looks
// like the field (tests/gl/export_stock_gl_test.cpp) and `grass view`'s picture. Lit by the
// frame's sun and sky like `grass render`, with Lambert instead of the grass lighting, and the
// values written as they are (no sRGB encoding, as the renderer does).
#pragma once

#include "gl/framebuffer.h"
#include "mesh/gltf_view.h"
#include "render/render_options.h"
#include "scene/camera.h"
#include "util/result.h"

namespace grass::render {

struct GltfViewRequest {
    int width = 1280;
    int height = 720;
    int msaaSamples = 4;
};

// Needs a current GL 4.5 context. Errors: the shaders failed to build.
Result<gl::Rgba8Image> renderGltfView(const core::GltfView& view, const core::OrbitCamera& camera,
                                      const GltfViewRequest& request, const RenderOptions& options);

}  // namespace grass::render
