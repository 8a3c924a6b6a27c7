// RenderOptions: how SceneRenderer draws a frame (geometry path, lighting, culling, technique,
// snow), and how a project's settings turn into them. World space, metres, seconds; colours
// linear RGB.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "blade/blade_draw_commands.h"
#include "project/project.h"
#include "render/cull_pass.h"
#include "render/field_gpu.h"

namespace grass::render {

struct RenderOptions {
    GeometryPath geometry = GeometryPath::Strips;
    int tessLevel = 8;
    int stripSegments = 8;
    core::SunDesc sun;
    // Grass lighting (SPEC §10); model Simple draws the foundation's wrapped Lambert.
    core::GrassLightingDesc lighting;
    // Light the blades per vertex (the article's choice) instead of per pixel (docs/rendering.md
    // compares cost and look): every level of detail when lightPerVertex, else the LODs from
    // pixelLitLods on. -1: as the renderer suits (core::defaultPixelLitLods: the half- and
    // quarter-segment blades beyond lodDistanceM; every blade on software GL with MSAA);
    // LOD_COUNT lights every blade per pixel.
    bool lightPerVertex = false;
    int pixelLitLods = -1;
    glm::vec3 skyColor{0.55f, 0.70f, 0.90f};
    glm::vec3 groundColor{0.30f, 0.24f, 0.16f};
    // Per-blade culling (SPEC §6); all tests off draws every blade.
    CullSettings cull;
    // Time every pass exactly on software GL (gl/timer_query.h: finish the GL work around each
    // pass and read the clock), as frames that collect statistics do, without the statistics'
    // atomics. The stalls cost the overlap of the app's thread with the rasterizer's, so
    // `grass bench` times its frames' wall clock in frames without them.
    bool exactStageTimings = false;
    // Draws every layer with this shape instead of its own (`grass render --shape`).
    std::optional<core::BladeShape> shape;
    // Blades, star billboards alone, or blades cross-faded into billboards by distance; the
    // billboards' animation mode, wind and cross-fade distances.
    core::GrassTechnique technique = core::GrassTechnique::Blades;
    core::BillboardDesc billboards;
    // Scene time in seconds: where the props (colliders) stand on their paths.
    float timeS = 0.0f;
    // The scene's wind sources: the billboards bend with them (the blades' physics has its own
    // copy); renderOptionsFor takes the project's.
    std::vector<core::WindSource> wind;
    // Snow (SPEC §11); off by default. Its depth pass runs, and its map exists, only when on.
    core::SnowParams snow;
    // Draw the opaque surfaces as (Fp, Fe, Fi) in (R, G, B), unlit, to measure the snow mask.
    bool snowCoverageView = false;
    // Draw the blades and the opaque surfaces in their unlit colour (albedo): how an export's
    // geometry and colours are compared with a stock viewer's (tests/gl/export_stock_gl_test.cpp)
    // without the two lighting models in the way.
    bool albedoView = false;
    // The snow surface is tessellated so that its edges span about snowTessPixels on screen,
    // cut at most snowTessMax times (shaders/mesh_snow.tesc); renderOptionsFor doubles it on
    // software rasterizers.
    float snowTessPixels = 8.0f;
    int snowTessMax = 16;
    // The snow surface's exposure Fe (eq. 1, `samples` lookups of the snow map) per vertex of the
    // tessellated surface, interpolated, instead of per pixel: renderOptionsFor picks it on
    // software rasterizers, where the per-pixel lookups were the dearest part of the surface
    // (docs/snow.md measures the cost and the error).
    bool snowExposurePerVertex = false;
    // Far blades blend towards the quad below 1 px of projected width (SPEC §7); off only for
    // tests that measure a shape alone.
    bool widthCorrection = true;
    // Continuous level of detail: the share of each LOD's distance range over which its blades
    // morph into the next LOD's shape (lod.glsl's lodMorph); 0 switches LODs hard, as before.
    float lodBlend = core::LOD_BLEND;
    // Blade widths × this: 1, except in the editor's thinned picture while the user interacts,
    // where fewer, wider blades keep the field's coverage (core/quality/interaction_quality.h).
    float widthScale = 1.0f;
    bool operator==(const RenderOptions&) const = default;
};

// Project settings → options; Auto picks strips on software rasterizers (SPEC §7 figures).
// Culling: every test on (thinning only with a thinning distance), the project's LOD and
// thinning distances, statistics off.
RenderOptions renderOptionsFor(const core::Project& project, bool softwareRenderer);
GeometryPath resolveGeometryPath(core::GeometryPath path, bool softwareRenderer);
const char* geometryPathLabel(GeometryPath path);

}  // namespace grass::render
