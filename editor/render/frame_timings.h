// FrameTimings: what the last SceneRenderer frame cost on the GPU, per pass, and what it drew,
// ran and allocated (issue 5: read a frame late, so the frame loop never waits on a query).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "render/cull_pass.h"

namespace grass::render {

struct FrameTimings {
    double meshMs = 0.0;       // GPU time of the opaque pass
    double grassMs = 0.0;      // GPU time of all blade draws
    double cullMs = 0.0;       // GPU time of the occlusion depth pre-pass and the cull dispatches
    double billboardMs = 0.0;  // GPU time of the billboard draws (techniques billboards, hybrid)
    std::size_t billboardsDrawn = 0;  // objects in the clusters drawn
    std::size_t billboardDrawCalls = 0;
    // Technique growth: stem sets drawn (one instanced draw per layer, no culling) and GPU time.
    std::size_t stemSetsDrawn = 0;
    double stemSetMs = 0.0;
    // Snow: GPU time of the depth pass along the snowfall (0 with snow off; the snow shading
    // itself is part of the opaque pass).
    double snowMs = 0.0;
    // Live blades handed to the cull pass; what survived it is cull.drawn.
    std::size_t bladesDrawn = 0;
    // Per-test counts, filled only when the frame ran with RenderOptions::cull.collectStats.
    CullStats cull;
    // The passes the frame ran, in order (issue 10: a pass a scene does not use does not run):
    // sun_shadow (or sun_shadow_kept: the map of an earlier frame, nothing it shows moved),
    // snow_depth (or snow_depth_kept), snow_drift, opaque (or opaque_snow: tessellated under
    // snow), occlusion_depth (the frame's depth resolved for the occlusion test) or
    // occlusion_prepass (the opaque scene drawn again for it: under snow, or into a framebuffer
    // whose depth cannot be resolved), cull (or cull_snow), blades, billboards, stem_sets.
    std::vector<std::string> passes;
    // What the renderer holds on the GPU beyond the terrain, props and blades, allocated on
    // first use: snow_map, snow_programs, tip_snow, billboards, stem_sets.
    std::vector<std::string> allocated;
};

}  // namespace grass::render
