#include "cli/render_report.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "cli/output_files.h"
#include "gl/headless_context.h"
#include "util/blade_pass_group.h"

namespace grass::cli {

namespace {

std::string statsJson(const render::FrameTimings& frame, double physicsMs, double wallMs,
                      const std::string& physicsDevice) {
    const render::CullStats& c = frame.cull;
    // The grass stage is everything that draws grass: blades, billboards and stem sets.
    const double grassMs = frame.grassMs + frame.billboardMs + frame.stemSetMs;
    const double total = physicsMs + frame.cullMs + frame.meshMs + grassMs;
    char text[1024];
    std::snprintf(text, sizeof text,
                  "{\n  \"blades_in\": %zu,\n  \"culled\": {\"patch\": %zu, \"orientation\": %zu, "
                  "\"frustum\": %zu, \"distance\": %zu, \"occlusion\": %zu, \"snow\": %zu},\n"
                  "  \"drawn\": %zu,\n"
                  "  \"ms\": {\"physics\": %.4f, \"cull\": %.4f, \"opaque\": %.4f, \"grass\": "
                  "%.4f, \"total\": %.4f, \"frame_wall\": %.4f},\n"
                  "  \"drawn_per_lod\": [%zu, %zu, %zu],\n"
                  "  \"billboards\": {\"drawn\": %zu, \"draw_calls\": %zu, \"ms\": %.4f},\n"
                  "  \"stem_sets\": {\"drawn\": %zu, \"ms\": %.4f},\n"
                  "  \"snow\": {\"depth_pass_ms\": %.4f},\n",
                  c.bladesIn, c.culledPatch, c.culledOrientation, c.culledFrustum, c.culledDistance,
                  c.culledOcclusion, c.culledSnow, c.drawn, physicsMs, frame.cullMs, frame.meshMs,
                  grassMs, total, wallMs, c.drawnPerLod[0], c.drawnPerLod[1], c.drawnPerLod[2],
                  frame.billboardsDrawn, frame.billboardDrawCalls, frame.billboardMs,
                  frame.stemSetsDrawn, frame.stemSetMs, frame.snowMs);
    const auto list = [](const std::vector<std::string>& names) {
        std::string out = "[";
        for (const std::string& name : names)
            out += (out.size() > 1 ? ", \"" : "\"") + name + "\"";
        return out + "]";
    };
    // Which passes ran and what the renderer allocated: a feature a scene does not use shows in
    // neither (issue 10).
    return std::string(text) + "  \"physics_device\": \"" + physicsDevice + "\",\n" +
           "  \"passes\": " + list(frame.passes) +
           ",\n  \"allocated\": " + list(frame.allocated) + "\n}\n";
}

void printCulling(const render::FrameTimings& frame, const render::OffscreenRequest& request) {
    const render::CullStats& cull = frame.cull;
    const double inBlades = static_cast<double>(std::max<std::size_t>(cull.bladesIn, 1));
    std::printf(
        "  culling    %zu in, %zu drawn (%.1f %%); culled: patch %zu, orientation %zu, "
        "frustum %zu, distance %zu, occlusion %zu, snow %zu; cull %.2f ms\n",
        cull.bladesIn, cull.drawn, 100.0 * static_cast<double>(cull.drawn) / inBlades,
        cull.culledPatch, cull.culledOrientation, cull.culledFrustum, cull.culledDistance,
        cull.culledOcclusion, cull.culledSnow, frame.cullMs);
    std::printf(
        "  detail     drawn per LOD %zu / %zu / %zu (full, half, quarter segments; "
        "--lod-distance %.3g m)\n",
        cull.drawnPerLod[0], cull.drawnPerLod[1], cull.drawnPerLod[2],
        static_cast<double>(request.options.cull.lodDistanceM));
}

}  // namespace

void printRenderSummary(const std::string& out, const core::Scene& scene, double buildMs,
                        const render::OffscreenRequest& request,
                        const render::OffscreenResult& rendered) {
    std::vector<double> frames = rendered.frameWallMs;
    std::sort(frames.begin(), frames.end());
    const render::FrameTimings& last = rendered.lastFrame;
    std::printf("wrote %s (%dx%d)\n", out.c_str(), request.width, request.height);
    std::printf("  scene      %zu triangles, %zu blades in %zu layer(s), built in %.1f ms\n",
                scene.mesh->n_faces(), scene.totalBlades(), scene.layers.size(), buildMs);
    // The renderer has loaded the passes, so the group size is one that was accepted.
    const Result<std::uint32_t> group = core::bladePassGroupSizeFromEnvironment();
    std::printf("  renderer   %s, geometry %s, %dx MSAA, compute groups of %u\n",
                gl::rendererDescription().c_str(),
                render::geometryPathLabel(request.options.geometry), request.msaaSamples,
                group ? *group : 0u);
    std::printf("  frames     %zu, wall ms: first %.1f, median %.1f, min %.1f\n",
                rendered.frameWallMs.size(), rendered.frameWallMs.front(),
                frames[frames.size() / 2], frames.front());
    std::printf(
        "  gpu ms     mesh %.2f, grass %.2f, billboards %.2f, stem sets %.2f, snow map "
        "%.2f (last frame, timer queries)\n",
        last.meshMs, last.grassMs, last.billboardMs, last.stemSetMs, last.snowMs);
    std::printf("  technique  %s; billboards drawn %zu in %zu draw call(s); stem sets drawn %zu\n",
                std::string(core::grassTechniqueName(request.options.technique)).c_str(),
                last.billboardsDrawn, last.billboardDrawCalls, last.stemSetsDrawn);
    printCulling(last, request);
}

Result<void> writeStats(const std::string& file, const render::FrameTimings& frame,
                        double physicsMs, double wallMs, const std::string& physicsDevice) {
    return writeOutputFile(file, statsJson(frame, physicsMs, wallMs, physicsDevice));
}

}  // namespace grass::cli
