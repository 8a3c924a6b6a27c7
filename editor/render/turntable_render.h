// Turntable rendering (`grass render --turntable N`): N views orbiting the start camera's target
// (core/scene/turntable.h), drawn with one SceneRenderer and one framebuffer, so the scene is
// uploaded and the shaders compiled once, not once per view. The field does not move between
// views: every view draws the same blade buffers at the same options.timeS. The caller owns the
// GL context.
#pragma once

#include <functional>

#include "render/offscreen_render.h"

namespace grass::render {

// Called after each view with its index, image and GPU timings; an error stops the turn and
// is returned (e.g. a file that could not be written).
using TurntableFrameSink = std::function<Result<void>(int frame, const gl::Rgba8Image& image,
                                                      const FrameTimings& timings, double wallMs)>;

// Draws view k of frameCount with core::turntableCamera(start, k, frameCount), each once
// (request.frames is ignored: a turn is for looking, not timing). Precondition: frameCount ≥ 1.
Result<void> renderTurntable(const core::Scene& scene, const core::OrbitCamera& start,
                             const OffscreenRequest& request, int frameCount,
                             const TurntableFrameSink& sink);

}  // namespace grass::render
