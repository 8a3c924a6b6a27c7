// SceneRenderer's grass passes, by technique: the cull and the blades, the billboards, the stem
// sets.
#include "render/scene_renderer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "util/assert.h"

namespace grass::render {

// The grass of the frame's technique. Timers run every frame, empty where a technique skips a
// pass, so readings are never stale.
void SceneRenderer::drawGrass(const core::OrbitCamera& camera, const glm::mat4& projection,
                              int width, int height, const RenderOptions& options) {
    const glm::mat4 viewProj = projection * camera.view();
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
        drawStemSets(camera, viewProj, options.cull, options.sun.shadows);
        mPasses.push_back("stem_sets");
    }
    mStemSetTimer.end();
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
    cull.lodBlend = options.lodBlend;  // the cull sorts the blending blades out for their draw
    if (hybrid)
        cull.cutoffDistanceM = options.billboards.crossFadeM.y;
    mCullTimer.begin();
    const CullView cullView{camera.view(), projection, camera.position(), width, height, segments};
    if (mSnowLies)
        for (FieldGpu& field : mFields)
            field.enableTipSnow();
    cull.snow = mSnowLies;
    // The occlusion depth is the frame's own after its opaque pass, which drew the same surfaces:
    // drawing them again cost as much as the opaque pass (an 8.4-million-triangle ground: 254 of
    // a 515 ms frame). Under snow a pre-pass draws the surfaces without their snow. The ground
    // lies under the snow, so its depth is never nearer than the snow surface's: no blade in
    // sight is culled, a few behind drifts are drawn and hidden by the depth test (winter-100k:
    // 6 % more blades drawn), and the snow surface is not tessellated a second time (it cost
    // winter's cull 110-170 ms).
    const GLuint depthSource = mSnowLies ? 0 : mFrameDepth;
    mCull->run(
        mFields, cullView, cull,
        [this, &options, &viewProj] {
            const gl::Program& depthOnly = opaqueProgram(Opaque::DepthOnly);
            depthOnly.use();
            depthOnly.set("uViewProj", viewProj);
            drawOpaque(depthOnly, options, false, false);
        },
        depthSource);
    mCullTimer.end();
    if (cull.occlusion)
        mPasses.push_back(depthSource != 0 ? "occlusion_depth" : "occlusion_prepass");
    mPasses.push_back(mSnowLies ? "cull_snow" : "cull");
    mStatsFrame = options.cull.collectStats;

    mGrassTimer.begin();
    const bool tessellate = options.geometry == GeometryPath::Tessellation;
    // Each LOD's program: lit per pixel up to options.pixelLitLods, per vertex beyond.
    GLint samples = 0;  // of the framebuffer the frame draws into
    glGetIntegerv(GL_SAMPLES, &samples);
    const int pixelLitLods = options.pixelLitLods >= 0
                                 ? options.pixelLitLods
                                 : core::defaultPixelLitLods(mSoftwareGl, samples);
    // The blades in a LOD's morph band get the blending variant; none blend without LODs or
    // a band, nor at the last LOD, whose slots then share the plain programs (no compile).
    const bool blends = options.lodBlend > 0.0f && cull.lodDistanceM > 0.0f;
    BladePrograms programs{};
    for (const bool blending : {false, true})
        for (int lod = 0; lod < LOD_COUNT; ++lod)
            programs[std::size_t(blending * LOD_COUNT + lod)] =
                &bladeProgram({.tessellate = tessellate,
                               .lightPerVertex = options.lightPerVertex || lod >= pixelLitLods,
                               .sunShadows = options.sun.shadows,
                               .fadeOut = hybrid,
                               .lodBlend = blending && blends && lod < LOD_COUNT - 1,
                               .snowTips = mSnowLies,
                               .simpleLighting =
                                   options.lighting.model == core::LightingModel::Simple});
    const auto setAll = [&programs](const char* name, const auto& value) {
        for (std::size_t i = 0; i < programs.size(); ++i)
            if (std::find(programs.begin(), programs.begin() + std::ptrdiff_t(i), programs[i]) ==
                programs.begin() + std::ptrdiff_t(i))
                programs[i]->set(name, value);
    };
    setAll("uViewProj", viewProj);
    // Pixels that a length of 1 at view depth 1 covers, for the width correction (SPEC §7).
    setAll("uPixelScale", options.widthCorrection
                              ? projection[1][1] * 0.5f * static_cast<float>(height)
                              : 0.0f);
    setAll("uTessLevel", static_cast<float>(std::max(options.tessLevel, 1)));
    setAll("uWidthScale", options.widthScale);
    setAll("uCameraPosition", camera.position());
    setAll("uLodDistance", std::max(options.cull.lodDistanceM, 0.0f));
    setAll("uLodBlend", options.lodBlend);
    setAll("uFadeOut", hybrid ? options.billboards.crossFadeM : glm::vec2(0.0f));
    setAll("uAlbedoView", options.albedoView ? 1 : 0);
    setAll("uSnowTipColor", options.snow.snowColor);
    if (hybrid)
        glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    mBladesDrawn = 0;
    for (auto& field : mFields) {
        setAll("uRootColor", field.field().rootColor);
        setAll("uTipColor", field.field().tipColor);
        setAll("uPoorRootColor", field.field().poorRootColor);
        setAll("uPoorTipColor", field.field().poorTipColor);
        const core::BladeShape shape = options.shape.value_or(field.field().shape);
        setAll("uShape", static_cast<int>(shape));
        setAll("uTipStart", field.field().tipStart);
        if (tessellate)
            field.drawTessellated(programs);
        else
            field.drawStrips(programs);
        mBladesDrawn += field.field().liveBlades;
    }
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    mPasses.push_back("blades");
    mGrassTimer.end();
}

// The scene's billboards; placed here, once, when the scene kept them unplaced (its project's
// technique drew none: core::placedBillboards), or on a worker (placeBillboardsInBackground).
// Null when they cannot be placed (too many: said once on stderr), or not yet.
const core::BillboardLayer* SceneRenderer::billboardLayer() {
    if (!mScene->billboards.unplaced)
        return &mScene->billboards;
    if (!mPlacedHere && !mBillboardsRefused) {
        // The placing reads what painting does not change, so a worker may do it; the objects
        // that follow the painted maps are made here, once it is done.
        if (mPlaceInBackground && !mPlacing.valid())
            mPlacing =
                std::async(std::launch::async, [scene = mScene, stop = mPlacingStop.get_token()] {
                    return core::placedBillboardsUnfollowed(*scene, stop);
                });
        if (mPlacing.valid() &&
            mPlacing.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
            return nullptr;
        auto placed = mPlacing.valid() ? mPlacing.get() : core::placedBillboardsUnfollowed(*mScene);
        if (placed)
            placed->objects = core::followLayers(placed->placed, placed->follow, mScene->layers);
        if (placed) {
            mPlacedHere = std::make_unique<core::BillboardLayer>(std::move(*placed));
        } else {
            mBillboardsRefused = true;
            mNotes.push_back("billboards not drawn: " + placed.error().str());
            std::fprintf(stderr, "note: %s\n", mNotes.back().c_str());
        }
    }
    return mPlacedHere.get();
}

// The billboard clusters, uploaded on the first frame that draws them: a scene drawn by blades
// alone allocates none. Null when the scene has no billboards (scenes assembled by hand). After a
// repaint they follow the layers' maps again (core/scene/billboard_follow.h) before they draw.
BillboardField* SceneRenderer::billboardField() {
    const core::BillboardLayer* layer = billboardLayer();
    if (!layer)
        return nullptr;
    const core::BillboardLayer& billboards = *layer;
    if (!mBillboards && !billboards.placed.empty()) {
        auto made = BillboardField::create(billboards.objects, billboards.texture);
        GRASS_ASSERT(made.ok());  // the shaders ship with the program; a failure is a bug
        mBillboards = std::make_unique<BillboardField>(std::move(*made));
        mBillboardsStale = false;
    }
    if (mBillboards && mBillboardsStale) {
        mBillboards->setObjects(
            core::followLayers(billboards.placed, billboards.follow, mScene->layers));
        mBillboardsStale = false;
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
    params.sceneWind = options.wind;
    const core::BillboardLayer* layer = billboardLayer();
    params.stiffness = layer ? layer->follow.stiffness : mScene->billboards.follow.stiffness;
    params.sunShadows = options.sun.shadows;
    // The editor's reduced picture thins and widens billboards as it does blades.
    params.keepEvery = static_cast<std::uint32_t>(std::max(options.cull.keepEvery, 1));
    params.widthScale = options.widthScale;
    if (options.technique == core::GrassTechnique::Hybrid)
        params.fade = {options.billboards.crossFadeM.x, options.billboards.crossFadeM.y, 1.0e30f,
                       1.0e30f};
    const gl::Program& program = mBillboards->program(params.sunShadows);
    program.set("uCameraPosition", camera.position());
    program.set("uFieldAo", mFieldAo);
    mBillboards->draw(params);
    mBillboardsDrawn = mBillboards->drawnObjects();
    mBillboardDrawCalls = mBillboards->drawCalls();
}

void SceneRenderer::drawStemSets(const core::OrbitCamera& camera, const glm::mat4& viewProj,
                                 const CullSettings& cull, bool sunShadows) {
    // Uploaded on first use: a scene drawn by another technique pays nothing for them.
    if (mStemSets.empty())
        for (const auto& layer : mScene->layers)
            mStemSets.emplace_back(layer.stemSets, "stem sets " + layer.name);
    // Culled and thinned as the blades are, by the same switches (core/growth/stem_set_cull.h).
    core::StemSetCullSettings settings;
    settings.frustum = cull.frustum;
    settings.distance = cull.distance;
    settings.distanceClasses = cull.distanceClasses;
    settings.maxDistanceM = cull.maxDistanceM;
    settings.lodDistanceM = cull.lodDistanceM;
    settings.keepEvery = cull.keepEvery;
    const gl::Program& program = gl::loadOnFirstUse(mStemSetPrograms[sunShadows], [&] {
        return loadStemSetProgram(sunShadows ? std::vector<std::string>{"GRASS_SUN_SHADOWS"}
                                             : std::vector<std::string>{});
    });
    program.use();
    program.set("uViewProj", viewProj);
    program.set("uCameraPosition", camera.position());
    program.set("uFieldAo", mFieldAo);
    for (std::size_t i = 0; i < mStemSets.size(); ++i) {
        const core::LayerField& layer = mScene->layers[i];
        core::cullStemSets(layer.stemSets, layer.source.stemLevels, viewProj, camera.position(),
                           settings, mStemSetCull);
        setStemSetColours(program, StemSetColours{layer.rootColor, layer.tipColor,
                                                  layer.poorRootColor, layer.poorTipColor});
        mStemSets[i].draw(program, layer.source.stemLevels, mStemSetCull);
        mStemSetsDrawn += mStemSetCull.drawn();
    }
}

}  // namespace grass::render
