#include "render/scene_renderer.h"

#include <algorithm>
#include <utility>

#include "scene/scene_snow.h"
#include "util/assert.h"

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
    options.snow = project.snow;
    options.cull.lodDistanceM = settings.lodDistanceM;
    options.cull.distance = settings.thinningDistanceM > 0.0f;
    if (options.cull.distance)
        options.cull.maxDistanceM = settings.thinningDistanceM;
    // Tessellation is what snow costs most on a software rasterizer (docs/snow.md: 8 px edges
    // 1.3–2.2 s a frame on llvmpipe, 16 px 0.6–1.4 s); GPUs tessellate in hardware.
    options.snowTessPixels = softwareRenderer ? 16.0f : 8.0f;
    return options;
}

const char* geometryPathLabel(GeometryPath path) {
    return path == GeometryPath::Tessellation ? "tess" : "strips";
}

// The billboards and stem sets stand for the blades: they take the blades' mean AO.
static float meanFieldAo(const core::Scene& scene) {
    double aoSum = 0.0;
    std::size_t aoCount = 0;
    for (const auto& layer : scene.layers)
        for (std::size_t i = 0; i < layer.shading.size(); ++i)
            if (layer.patched.blades[i].h() > 0.0f) {
                aoSum += layer.shading[i].ao();
                ++aoCount;
            }
    return aoCount > 0 ? static_cast<float>(aoSum / static_cast<double>(aoCount)) : 1.0f;
}

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(const core::Scene& scene) {
    std::unique_ptr<SceneRenderer> renderer(new SceneRenderer());
    renderer->mScene = &scene;
    auto mesh = gl::Program::load(
        {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}}, "mesh");
    if (!mesh)
        return mesh.error();
    auto strips = gl::Program::load(
        {{GL_VERTEX_SHADER, "blade_strip.vert"}, {GL_FRAGMENT_SHADER, "blade.frag"}},
        "blade strips");
    if (!strips)
        return strips.error();
    auto tess = gl::Program::load({{GL_VERTEX_SHADER, "blade_tess.vert"},
                                   {GL_TESS_CONTROL_SHADER, "blade.tesc"},
                                   {GL_TESS_EVALUATION_SHADER, "blade.tese"},
                                   {GL_FRAGMENT_SHADER, "blade.frag"}},
                                  "blade tessellation");
    if (!tess)
        return tess.error();
    auto stemSets = loadStemSetProgram();
    if (!stemSets)
        return stemSets.error();
    renderer->mStemSetProgram = std::move(*stemSets);
    auto cull = CullPass::create();
    if (!cull)
        return cull.error();
    renderer->mCull = std::make_unique<CullPass>(std::move(*cull));
    renderer->mFieldAo = meanFieldAo(scene);
    renderer->mMeshProgram = std::move(*mesh);
    renderer->mStripProgram = std::move(*strips);
    renderer->mTessProgram = std::move(*tess);
    renderer->mMesh = std::make_unique<MeshGpu>(scene.mesh);
    renderer->mProps.reserve(scene.props.size());
    for (const auto& prop : scene.props)
        renderer->mProps.emplace_back(prop.mesh);
    renderer->mFields.reserve(scene.layers.size());
    for (const auto& layer : scene.layers)
        renderer->mFields.emplace_back(layer);
    return renderer;
}

void SceneRenderer::render(const core::OrbitCamera& camera, int width, int height,
                           gl::FramebufferRef framebuffer, const RenderOptions& options) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // blades and open meshes are two-sided
    glEnable(GL_MULTISAMPLE);
    glClearColor(options.skyColor.r, options.skyColor.g, options.skyColor.b, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // The image stays opaque: alpha-to-coverage (hybrid blades, billboards) turns fragment
    // alpha into coverage, and writing it too would leave see-through pixels in saved images.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);

    const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
    const glm::mat4 projection = camera.projection(aspect);
    const glm::mat4 viewProj = projection * camera.view();
    // Every program that lights a surface reads this one upload.
    mLighting.upload(
        lightingBlock(options.lighting, options.sun, options.skyColor, options.groundColor));

    // Snow: only a frame where snow lies (on, amount > 0) runs the depth pass and the snow
    // variants of the opaque and cull programs; any other frame runs exactly the snow-free ones.
    mPasses.clear();
    mSnowTimer.begin();
    const float snowAmountM = core::snowAmountAt(options.snow, options.timeS);
    mSnowLies = options.snow.enabled != 0u && snowAmountM > 0.0f;
    if (mSnowLies) {
        renderSnowMap(options);
        mPasses.push_back("snow_depth");
        // The surfaces whiten and rise; the cull buries short blades and whitens the tips.
        mSnow->bind(options.snow, snowAmountM);
        const gl::Program& snowMesh = snowMeshProgram();
        snowMesh.set("uSnowCoverageView", options.snowCoverageView ? 1 : 0);
        snowMesh.set("uViewportPixels", glm::vec2(float(width), float(height)));
        snowMesh.set("uSnowTessPixels", std::max(options.snowTessPixels, 1.0f));
        snowMesh.set("uSnowTessMax", float(std::clamp(options.snowTessMax, 1, 64)));
    }
    mSnowTimer.end();

    mMeshTimer.begin();
    const gl::Program& opaque = mSnowLies ? snowMeshProgram() : mMeshProgram;
    opaque.use();
    opaque.set("uViewProj", viewProj);
    drawOpaque(options, true);
    mPasses.push_back(mSnowLies ? "opaque_snow" : "opaque");
    mMeshTimer.end();

    // Timers run every frame, empty where a technique skips a pass, so readings are never stale.
    const bool blades = options.technique == core::GrassTechnique::Blades ||
                        options.technique == core::GrassTechnique::Hybrid;
    const bool billboards = options.technique == core::GrassTechnique::Billboards ||
                            options.technique == core::GrassTechnique::Hybrid;
    if (blades) {
        drawBlades(camera, projection, width, height, options);
    } else {
        mCullTimer.begin();
        mCullTimer.end();
        mGrassTimer.begin();
        mGrassTimer.end();
        mStatsFrame = false;
        mBladesDrawn = 0;
    }
    mBillboardTimer.begin();
    if (billboards && billboardField() != nullptr) {
        drawBillboards(camera, viewProj, options);
        mPasses.push_back("billboards");
    } else
        mBillboardsDrawn = mBillboardDrawCalls = 0;
    mBillboardTimer.end();
    mStemSetTimer.begin();
    mStemSetsDrawn = 0;
    if (options.technique == core::GrassTechnique::Growth) {
        drawStemSets(camera, viewProj);
        mPasses.push_back("stem_sets");
    }
    mStemSetTimer.end();
    glBindVertexArray(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// The cull pass, then every layer through its visible lists. In the hybrid, blades end at the
// far edge of the cross-fade (culled there, so the far field costs nothing) and fade out over
// it by alpha-to-coverage, dissolving sample by sample as the billboards fade in.
void SceneRenderer::drawBlades(const core::OrbitCamera& camera, const glm::mat4& projection,
                               int width, int height, const RenderOptions& options) {
    const bool hybrid = options.technique == core::GrassTechnique::Hybrid;
    const glm::mat4 viewProj = projection * camera.view();
    const int segments = std::max(options.stripSegments, 1);
    CullSettings cull = options.cull;
    if (hybrid)
        cull.cutoffDistanceM = options.billboards.crossFadeM.y;
    mCullTimer.begin();
    const CullView cullView{camera.view(), projection, camera.position(), width, height, segments};
    if (mSnowLies)
        for (FieldGpu& field : mFields)
            field.enableTipSnow();
    cull.snow = mSnowLies;
    mCull->run(mFields, cullView, cull, [this, &options] {
        (mSnowLies ? snowMeshProgram() : mMeshProgram).use();
        drawOpaque(options, false);
    });
    mCullTimer.end();
    if (cull.occlusion)
        mPasses.push_back("occlusion_prepass");
    mPasses.push_back(mSnowLies ? "cull_snow" : "cull");
    mStatsFrame = options.cull.collectStats;

    mGrassTimer.begin();
    const bool tessellate = options.geometry == GeometryPath::Tessellation;
    const gl::Program& program = tessellate ? mTessProgram : mStripProgram;
    program.use();
    program.set("uViewProj", viewProj);
    // Pixels that a length of 1 at view depth 1 covers, for the width correction (SPEC §7).
    program.set("uPixelScale", options.widthCorrection
                                   ? projection[1][1] * 0.5f * static_cast<float>(height)
                                   : 0.0f);
    program.set("uTessLevel", static_cast<float>(std::max(options.tessLevel, 1)));
    program.set("uCameraPosition", camera.position());
    program.set("uLodDistance", std::max(options.cull.lodDistanceM, 0.0f));
    program.set("uFadeOut", hybrid ? options.billboards.crossFadeM : glm::vec2(0.0f));
    program.set("uLightPerVertex", options.lightPerVertex ? 1 : 0);
    program.set("uSnowTips", mSnowLies ? 1 : 0);
    program.set("uSnowTipColor", options.snow.snowColor);
    if (hybrid)
        glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    mBladesDrawn = 0;
    for (auto& field : mFields) {
        program.set("uRootColor", field.field().rootColor);
        program.set("uTipColor", field.field().tipColor);
        program.set("uPoorRootColor", field.field().poorRootColor);
        program.set("uPoorTipColor", field.field().poorTipColor);
        const core::BladeShape shape = options.shape.value_or(field.field().shape);
        program.set("uShape", static_cast<int>(shape));
        program.set("uTipStart", field.field().tipStart);
        if (tessellate)
            field.drawTessellated(program);
        else
            field.drawStrips(program, segments);
        mBladesDrawn += field.field().liveBlades;
    }
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    mPasses.push_back("blades");
    mGrassTimer.end();
}

// The billboard clusters, uploaded on the first frame that draws them: a scene drawn by blades
// alone allocates none. Null when the scene has no billboards (scenes assembled by hand).
BillboardField* SceneRenderer::billboardField() {
    if (!mBillboards && !mScene->billboards.objects.empty()) {
        auto billboards =
            BillboardField::create(mScene->billboards.objects, mScene->billboards.texture);
        GRASS_ASSERT(billboards.ok());  // the shaders ship with the program; a failure is a bug
        mBillboards = std::make_unique<BillboardField>(std::move(*billboards));
    }
    return mBillboards.get();
}

void SceneRenderer::drawBillboards(const core::OrbitCamera& camera, const glm::mat4& viewProj,
                                   const RenderOptions& options) {
    BillboardDrawParams params;
    params.viewProj = viewProj;
    params.cameraPosWorld = camera.position();
    params.timeS = options.timeS;
    params.mode = options.billboards.animation;
    params.wind = options.billboards.wind;
    if (options.technique == core::GrassTechnique::Hybrid)
        params.fade = {options.billboards.crossFadeM.x, options.billboards.crossFadeM.y, 1.0e30f,
                       1.0e30f};
    const gl::Program& program = mBillboards->program();
    program.set("uCameraPosition", camera.position());
    program.set("uFieldAo", mFieldAo);
    mBillboards->draw(params);
    mBillboardsDrawn = mBillboards->drawnObjects();
    mBillboardDrawCalls = mBillboards->drawCalls();
}

void SceneRenderer::drawStemSets(const core::OrbitCamera& camera, const glm::mat4& viewProj) {
    // Uploaded on first use: a scene drawn by another technique pays nothing for them.
    if (mStemSets.empty())
        for (const auto& layer : mScene->layers)
            mStemSets.emplace_back(layer.stemSets, "stem sets " + layer.name);
    const gl::Program& program = mStemSetProgram;
    program.use();
    program.set("uViewProj", viewProj);
    program.set("uCameraPosition", camera.position());
    program.set("uFieldAo", mFieldAo);
    for (std::size_t i = 0; i < mStemSets.size(); ++i) {
        const core::LayerField& layer = mScene->layers[i];
        setStemSetColours(program, StemSetColours{layer.rootColor, layer.tipColor,
                                                  layer.poorRootColor, layer.poorTipColor});
        mStemSets[i].draw(program, layer.source.stemLevels);
        // Null sets (slots without a blade) are instanced too but collapse in the vertex shader.
        mStemSetsDrawn += static_cast<std::size_t>(std::count_if(
            layer.stemSets.begin(), layer.stemSets.end(),
            [](const core::StemSetInstance& set) { return set.rootMetresPerUnit.w > 0.0f; }));
    }
}

void SceneRenderer::uploadRegrown(std::size_t layer, const core::RegrowReport& report) {
    if (layer >= mFields.size())
        return;
    mFields[layer].uploadPatches(report.patches, false);
    mFields[layer].uploadPatches(report.shadedPatches, true);
    mFieldAo = meanFieldAo(*mScene);
    if (layer < mStemSets.size()) {
        const core::LayerField& field = mScene->layers[layer];
        for (std::uint32_t p : report.patches) {
            const auto [first, end] = core::patchStemSets(field, p);
            mStemSets[layer].update(first, std::span(field.stemSets).subspan(first, end - first));
        }
    }
}

// The depth map along the snowfall over the terrain and the props where they stand now: the
// view covers both, so a ball above the ground shelters what lies under it.
void SceneRenderer::renderSnowMap(const RenderOptions& options) {
    if (!mSnow) {
        auto pass = SnowPass::create();
        GRASS_ASSERT(pass.ok());  // the shader ships with the program; a load failure is a bug
        mSnow = std::make_unique<SnowPass>(std::move(*pass));
    }
    const core::OrthoSnowView view = core::sceneSnowView(*mScene, options.snow, options.timeS);
    mSnow->run(view, options.snow.mapResolution, [&](const gl::Program& program) {
        program.set("uModel", glm::mat4(1.0f));
        mMesh->draw();
        for (std::size_t i = 0; i < mProps.size(); ++i) {
            program.set("uModel", mScene->props[i].modelAt(options.timeS));
            mProps[i].draw();
        }
    });
}

// The program of the snow surface (tessellated, displaced, whitened), compiled on the first
// frame with snow.
const gl::Program& SceneRenderer::snowMeshProgram() {
    if (mSnowMeshProgram.id() == 0) {
        auto program = gl::Program::load({{GL_VERTEX_SHADER, "mesh_snow.vert"},
                                          {GL_TESS_CONTROL_SHADER, "mesh_snow.tesc"},
                                          {GL_TESS_EVALUATION_SHADER, "mesh_snow.tese"},
                                          {GL_FRAGMENT_SHADER, "mesh.frag"}},
                                         "mesh under snow", {"GRASS_SNOW"});
        GRASS_ASSERT(program.ok());  // the shaders ship with the program; a failure is a bug
        mSnowMeshProgram = std::move(*program);
    }
    return mSnowMeshProgram;
}

// The terrain, then each prop where its path puts it at options.timeS, with the opaque program
// of this frame (bound by the caller). `shaded` sets the albedo (the cull's depth pre-pass
// needs none).
void SceneRenderer::drawOpaque(const RenderOptions& options, bool shaded) {
    const gl::Program& program = mSnowLies ? snowMeshProgram() : mMeshProgram;
    const auto draw = [this](const MeshGpu& mesh) { mSnowLies ? mesh.drawPatches() : mesh.draw(); };
    program.set("uModel", glm::mat4(1.0f));
    if (shaded)
        program.set("uAlbedo", options.groundColor);
    draw(*mMesh);
    for (std::size_t i = 0; i < mProps.size(); ++i) {
        const core::SceneProp& prop = mScene->props[i];
        program.set("uModel", prop.modelAt(options.timeS));
        if (shaded)
            program.set("uAlbedo", prop.albedo);
        draw(mProps[i]);
    }
}

std::vector<gl::BufferRef> SceneRenderer::bladeBuffers() const {
    std::vector<gl::BufferRef> buffers;
    for (const FieldGpu& field : mFields)
        buffers.push_back(field.bladeBuffer());
    return buffers;
}

FrameTimings SceneRenderer::lastTimings() const {
    FrameTimings timings;
    timings.meshMs = mMeshTimer.milliseconds();
    timings.grassMs = mGrassTimer.milliseconds();
    timings.cullMs = mCullTimer.milliseconds();
    timings.billboardMs = mBillboardTimer.milliseconds();
    timings.billboardsDrawn = mBillboardsDrawn;
    timings.billboardDrawCalls = mBillboardDrawCalls;
    timings.bladesDrawn = mBladesDrawn;
    timings.stemSetsDrawn = mStemSetsDrawn;
    timings.stemSetMs = mStemSetTimer.milliseconds();
    // A frame without snow ran no snow pass: 0, not the timer's reading of an empty range.
    timings.snowMs = mSnowLies ? mSnowTimer.milliseconds() : 0.0;
    if (mStatsFrame)
        timings.cull = mCull->readStats(mFields);
    timings.passes = mPasses;
    if (mSnow)
        timings.allocated.push_back("snow_map");
    if (mSnowMeshProgram.id() != 0)
        timings.allocated.push_back("snow_programs");
    if (std::any_of(mFields.begin(), mFields.end(),
                    [](const FieldGpu& field) { return field.hasTipSnow(); }))
        timings.allocated.push_back("tip_snow");
    if (mBillboards)
        timings.allocated.push_back("billboards");
    if (!mStemSets.empty())
        timings.allocated.push_back("stem_sets");
    return timings;
}

}  // namespace grass::render
