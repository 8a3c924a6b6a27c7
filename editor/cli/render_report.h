// What `grass render` reports of a render: the summary lines on stdout (image, scene, renderer,
// frame times, GPU stages, culling, detail) and the --stats JSON of the last frame.
#pragma once

#include <string>

#include "render/offscreen_render.h"
#include "scene/scene.h"
#include "util/result.h"

namespace grass::cli {

// The summary printed after the image is written. Frames' wall times come from `rendered`.
void printRenderSummary(const std::string& out, const core::Scene& scene, double buildMs,
                        const render::OffscreenRequest& request,
                        const render::OffscreenResult& rendered);

// Writes the --stats file of a frame (its cull counts and pass timings, the physics ms per step
// of --time and where it ran — "cpu", "gpu" or "none" —, the frame's wall ms) atomically and
// says so.
Result<void> writeStats(const std::string& file, const render::FrameTimings& frame,
                        double physicsMs, double wallMs, const std::string& physicsDevice = "none");

}  // namespace grass::cli
