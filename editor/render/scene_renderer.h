// SceneRenderer: draws a Scene (opaque mesh first, the cull pass, then every grass layer by the
// chosen geometry path through the visible lists) into a framebuffer, timing each pass with GL
// timer queries. The headless CLI
// and the editor's viewport both draw through it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/gl_ref.h"
#include "gl/program.h"
#include "gl/timer_query.h"
#include "gl/uniform_block.h"
#include "project/project.h"
#include "render/billboard_gpu.h"
#include "render/cull_pass.h"
#include "render/field_gpu.h"
#include "render/lighting_block.h"
#include "render/mesh_gpu.h"
#include "render/snow_pass.h"
#include "render/stem_set_gpu.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace grass::render {

struct RenderOptions {
    GeometryPath geometry = GeometryPath::Strips;
    int tessLevel = 8;
    int stripSegments = 8;
    core::SunDesc sun;
    // Grass lighting (SPEC §10); model Simple draws the foundation's wrapped Lambert.
    core::GrassLightingDesc lighting;
    // Light the blades per vertex (the article's choice) instead of per pixel (docs/rendering.md
    // compares cost and look).
    bool lightPerVertex = false;
    glm::vec3 skyColor{0.55f, 0.70f, 0.90f};
    glm::vec3 groundColor{0.30f, 0.24f, 0.16f};
    // Per-blade culling (SPEC §6); all tests off draws every blade.
    CullSettings cull;
    // Draws every layer with this shape instead of its own (`grass render --shape`).
    std::optional<core::BladeShape> shape;
    // Blades, star billboards alone, or blades cross-faded into billboards by distance; the
    // billboards' animation mode, wind and cross-fade distances.
    core::GrassTechnique technique = core::GrassTechnique::Blades;
    core::BillboardDesc billboards;
    // Scene time in seconds: where the props (colliders) stand on their paths.
    float timeS = 0.0f;
    // Snow (SPEC §11); off by default. Its depth pass runs, and its map exists, only when on.
    core::SnowParams snow;
    // Draw the opaque surfaces as (Fp, Fe, Fi) in (R, G, B), unlit, to measure the snow mask.
    bool snowCoverageView = false;
    // The snow surface is tessellated so that its edges span about snowTessPixels on screen,
    // cut at most snowTessMax times (shaders/mesh_snow.tesc); renderOptionsFor doubles it on
    // software rasterizers.
    float snowTessPixels = 8.0f;
    int snowTessMax = 16;
    // Far blades blend towards the quad below 1 px of projected width (SPEC §7); off only for
    // tests that measure a shape alone.
    bool widthCorrection = true;
};

// Project settings → options; Auto picks strips on software rasterizers (SPEC §7 figures).
// Culling: every test on (thinning only with a thinning distance), the project's LOD and
// thinning distances, statistics off.
RenderOptions renderOptionsFor(const core::Project& project, bool softwareRenderer);
GeometryPath resolveGeometryPath(core::GeometryPath path, bool softwareRenderer);
const char* geometryPathLabel(GeometryPath path);

struct FrameTimings {
    double meshMs = 0.0;   // GPU time of the opaque pass
    double grassMs = 0.0;  // GPU time of all blade draws
    double cullMs = 0.0;   // GPU time of the occlusion depth pre-pass and the cull dispatches
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
    // snow_depth, opaque (or opaque_snow: tessellated under snow), occlusion_prepass, cull (or
    // cull_snow), blades, billboards, stem_sets.
    std::vector<std::string> passes;
    // What the renderer holds on the GPU beyond the terrain, props and blades, allocated on
    // first use: snow_map, snow_programs, tip_snow, billboards, stem_sets.
    std::vector<std::string> allocated;
};

class SceneRenderer {
public:
    // Compiles the programs; the error names the shader file and line.
    static Result<std::unique_ptr<SceneRenderer>> create(const core::Scene& scene);

    // Draws into `framebuffer` (a gl::Framebuffer, or 0 = the window's), viewport width × height.
    void render(const core::OrbitCamera& camera, int width, int height,
                gl::FramebufferRef framebuffer, const RenderOptions& options);
    // Waits for the timer queries of the last render().
    FrameTimings lastTimings() const;
    // The blade buffer of each layer (SSBO layout of core::Blade), for physics to step in place.
    std::vector<gl::BufferRef> bladeBuffers() const;
    // After core::regrowLayerRegion changed layer `layer` of the scene: re-uploads the regrown
    // patches' blades and stem sets and the re-baked shading; nothing else moves.
    void uploadRegrown(std::size_t layer, const core::RegrowReport& report);
    // Snow read-backs for tests and tools (wait for the GPU): the depth pass of the last frame
    // with snow (null before one), and the tip whiteness the cull wrote for layer `layer`.
    const SnowPass* snowPass() const { return mSnow.get(); }
    std::vector<float> readTipSnow(std::size_t layer) const {
        return layer < mFields.size() ? mFields[layer].readTipSnow() : std::vector<float>{};
    }

private:
    SceneRenderer() = default;
    const core::Scene* mScene = nullptr;
    // The frame's lighting, uploaded once at the start of render().
    gl::UniformBlock<LightingBlock> mLighting{"lighting"};
    gl::Program mMeshProgram, mStripProgram, mTessProgram, mStemSetProgram;
    gl::Program mSnowMeshProgram;  // compiled on the first frame with snow
    const gl::Program& snowMeshProgram();
    void drawOpaque(const RenderOptions& options, bool shaded);
    void drawBlades(const core::OrbitCamera& camera, const glm::mat4& projection, int width,
                    int height, const RenderOptions& options);
    void drawBillboards(const core::OrbitCamera& camera, const glm::mat4& viewProj,
                        const RenderOptions& options);
    // Technique growth: Kim & Cho's stem sets, uploaded on first use (a scene that never draws
    // them pays nothing).
    void drawStemSets(const core::OrbitCamera& camera, const glm::mat4& viewProj);
    std::unique_ptr<MeshGpu> mMesh;
    std::vector<MeshGpu> mProps;
    std::vector<FieldGpu> mFields;
    std::unique_ptr<CullPass> mCull;
    // Made on the first frame with snow on: a snow-free scene allocates no map.
    std::unique_ptr<SnowPass> mSnow;
    bool mSnowLies = false;  // this frame: snow on with an amount > 0
    void renderSnowMap(const RenderOptions& options);
    std::unique_ptr<BillboardField> mBillboards;
    BillboardField* billboardField();
    std::vector<StemSetField> mStemSets;
    std::size_t mStemSetsDrawn = 0;
    gl::GpuTimer mMeshTimer, mGrassTimer, mCullTimer, mBillboardTimer, mStemSetTimer, mSnowTimer;
    std::size_t mBladesDrawn = 0;
    std::size_t mBillboardsDrawn = 0;
    float mFieldAo = 1.0f;
    std::size_t mBillboardDrawCalls = 0;
    bool mStatsFrame = false;
    std::vector<std::string> mPasses;
};

}  // namespace grass::render
