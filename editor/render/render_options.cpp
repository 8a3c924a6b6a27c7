#include "render/render_options.h"

#include <utility>
#include <vector>

#include "snow/snow_drift.h"

namespace grass::render {

GeometryPath resolveGeometryPath(core::GeometryPath path, bool softwareRenderer) {
    switch (path) {
        case core::GeometryPath::Tessellation:
            return GeometryPath::Tessellation;
        case core::GeometryPath::Strips:
            return GeometryPath::Strips;
        case core::GeometryPath::Auto:
            break;
    }
    return softwareRenderer ? GeometryPath::Strips : GeometryPath::Tessellation;
}

RenderOptions renderOptionsFor(const core::Project& project, bool softwareRenderer) {
    const core::RenderSettings& settings = project.render;
    RenderOptions options;
    options.geometry = resolveGeometryPath(settings.geometry, softwareRenderer);
    options.tessLevel = settings.tessLevel;
    options.stripSegments = settings.stripSegments;
    options.sun = project.sun;
    options.lighting = project.lighting;
    options.skyColor = settings.skyColor;
    options.groundColor = settings.groundColor;
    options.technique = settings.technique;
    options.billboards = project.billboards;
    std::vector<core::WindSource> wind;
    for (const core::WindDesc& source : project.wind)
        wind.push_back(source.source);
    // The drift follows the winds the project has now (the editor rebuilds these every frame).
    options.snow = core::snowWithWindDrift(project.snow, wind);
    options.wind = std::move(wind);
    options.cull.lodDistanceM = settings.lodDistanceM;
    options.cull.distance = settings.thinningDistanceM > 0.0f;
    if (options.cull.distance)
        options.cull.maxDistanceM = settings.thinningDistanceM;
    // Tessellation is what snow costs most on a software rasterizer (docs/snow.md: 8 px edges
    // 1.3–2.2 s a frame on llvmpipe, 16 px 0.6–1.4 s); GPUs tessellate in hardware.
    options.snowTessPixels = softwareRenderer ? 16.0f : 8.0f;
    options.snowExposurePerVertex = softwareRenderer;
    return options;
}

const char* geometryPathLabel(GeometryPath path) {
    return path == GeometryPath::Tessellation ? "tess" : "strips";
}

}  // namespace grass::render
