// SceneRenderer's opaque pass: the terrain and the props, plain or as the snow surface, and the
// snow depth map they cast (SPEC §11).
#include "render/scene_renderer.h"

#include "scene/sun_shadow.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>
#include <utility>

#include "gl/texture.h"
#include "scene/scene_snow.h"
#include "util/assert.h"

namespace grass::render {

// Snow: only a frame where snow lies (on, amount > 0) runs the depth pass and the snow
// variants of the opaque and cull programs; any other frame runs exactly the snow-free ones.
void SceneRenderer::runSnowPass(const RenderOptions& options, int width, int height) {
    mSnowTimer.begin();
    const float snowAmountM = core::snowAmountAt(options.snow, options.timeS);
    mSnowLies = options.snow.enabled != 0u && snowAmountM > 0.0f;
    if (mSnowLies) {
        // A map kept from an earlier frame (nothing it shows moved) is named apart.
        mPasses.push_back(renderSnowMap(options) ? "snow_depth" : "snow_depth_kept");
        // The surfaces whiten and rise; the cull buries short blades and whitens the tips.
        if (mSnow->bind(options.snow, snowAmountM))
            mPasses.push_back("snow_drift");
        const gl::Program& snowMesh = opaqueProgram(snowVariant(options), options.sun.shadows);
        snowMesh.set("uSnowCoverageView", options.snowCoverageView ? 1 : 0);
        snowMesh.set("uViewportPixels", glm::vec2(float(width), float(height)));
        snowMesh.set("uSnowTessPixels", std::max(options.snowTessPixels, 1.0f));
        snowMesh.set("uSnowTessMax", float(std::clamp(options.snowTessMax, 1, 64)));
    }
    mSnowTimer.end();
}

void SceneRenderer::drawOpaquePass(const glm::mat4& viewProj, const RenderOptions& options) {
    mMeshTimer.begin();
    // The textures' lookups only where the terrain has one: software GL runs both sides of a
    // uniform branch, and two unused lookups a fragment cost projects/nature's opaque pass about
    // 5 ms of 35 on llvmpipe at 4× MSAA (docs/rendering.md).
    const bool textured = mSurfaceTexture.id() != 0 || mMapOverlay.id() != 0;
    const Opaque lit = textured ? Opaque::LitTextured : Opaque::Lit;
    const gl::Program& opaque =
        opaqueProgram(mSnowLies ? snowVariant(options) : lit, options.sun.shadows);
    opaque.use();
    opaque.set("uViewProj", viewProj);
    opaque.set("uAlbedoView", options.albedoView ? 1 : 0);
    drawOpaque(opaque, options, true, mSnowLies);
    mPasses.push_back(mSnowLies ? "opaque_snow" : "opaque");
    mMeshTimer.end();
}

// The depth map along the snowfall over the terrain and the props where they stand now: the
// view covers both, so a ball above the ground shelters what lies under it.
bool SceneRenderer::renderSnowMap(const RenderOptions& options) {
    if (!mSnow) {
        auto pass = SnowPass::create();
        GRASS_ASSERT(pass.ok());  // the shader ships with the program; a load failure is a bug
        mSnow = std::make_unique<SnowPass>(std::move(*pass));
    }
    const core::OrthoSnowView view = core::sceneSnowView(*mScene, options.snow, options.timeS);
    return mSnow->run(view, options.snow.mapResolution, occluders(options.timeS),
                      [&](const gl::Program& program) { drawOccluders(program, options.timeS); });
}

Occluders SceneRenderer::occluders(float timeS) const {
    Occluders now{mOccluderGeometry, {}};
    for (std::size_t i = 0; i < mProps.size(); ++i)
        now.models.push_back(mScene->props[i].modelAt(timeS));
    return now;
}

// The terrain and the props where they stand at timeS, each with the program's uModel set.
void SceneRenderer::drawOccluders(const gl::Program& program, float timeS) {
    program.set("uModel", glm::mat4(1.0f));
    mMesh->draw();
    for (std::size_t i = 0; i < mProps.size(); ++i) {
        program.set("uModel", mScene->props[i].modelAt(timeS));
        mProps[i].draw();
    }
}

// The sun's depth map (core/scene/sun_shadow.h): the snow's depth pass pointed along the light,
// over the same casters; bound on SUN_SHADOW_UNIT and announced in `block`. Nothing is made or
// run while the project's shadows are off.
void SceneRenderer::runSunShadowPass(const RenderOptions& options, LightingBlock& block) {
    if (!options.sun.shadows)
        return;
    if (!mSunShadow) {
        auto pass = SnowPass::create();
        GRASS_ASSERT(pass.ok());  // the shader ships with the program; a load failure is a bug
        mSunShadow = std::make_unique<SnowPass>(std::move(*pass));
    }
    const int resolution = std::clamp(options.sun.shadowResolution, 1, 16384);
    const core::OrthoSnowView view = core::sceneSunView(*mScene, options.sun, options.timeS);
    const bool drawn =
        mSunShadow->run(view, resolution, occluders(options.timeS),
                        [&](const gl::Program& program) { drawOccluders(program, options.timeS); });
    glBindTextureUnit(SUN_SHADOW_UNIT, mSunShadow->depthTexture().id());
    core::enableSunShadows(block, view, resolution);
    mPasses.push_back(drawn ? "sun_shadow" : "sun_shadow_kept");
}

// Under snow the surfaces are tessellated and displaced (mesh_snow.*) and whitened (mesh.frag
// with GRASS_SNOW); the depth-only variant shades nothing.
Result<gl::Program> SceneRenderer::loadOpaqueProgram(Opaque variant, bool sunShadows) {
    std::vector<std::string> defines;
    if (sunShadows)
        defines.emplace_back("GRASS_SUN_SHADOWS");
    switch (variant) {
    case Opaque::Lit:
        return gl::Program::load(
            {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}},
            sunShadows ? "mesh (sun shadows)" : "mesh", defines);
    case Opaque::LitTextured:
        defines.emplace_back("GRASS_MESH_TEXTURES");
        return gl::Program::load(
            {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}},
            sunShadows ? "mesh textured (sun shadows)" : "mesh textured", defines);
    case Opaque::DepthOnly:
        return gl::Program::load(
            {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "depth_only.frag"}},
            "mesh (depth only)");
    default:
        break;
    }
    // The snow surface keeps the textures' lookups (a snowy textured glTF, the overlay while
    // painting under snow); its exposure and noise cost far more.
    defines.emplace_back("GRASS_SNOW");
    defines.emplace_back("GRASS_MESH_TEXTURES");
    if (variant == Opaque::SnowExposurePerVertex)
        defines.emplace_back("GRASS_SNOW_EXPOSURE_PER_VERTEX");
    return gl::Program::load({{GL_VERTEX_SHADER, "mesh_snow.vert"},
                              {GL_TESS_CONTROL_SHADER, "mesh_snow.tesc"},
                              {GL_TESS_EVALUATION_SHADER, "mesh_snow.tese"},
                              {GL_FRAGMENT_SHADER, "mesh.frag"}},
                             "mesh under snow", defines);
}

const gl::Program& SceneRenderer::opaqueProgram(Opaque variant, bool sunShadows) {
    return gl::loadOnFirstUse(mOpaquePrograms[sunShadows][static_cast<int>(variant)],
                              [variant, sunShadows] { return loadOpaqueProgram(variant, sunShadows); });
}

// The terrain, then each prop where its path puts it at options.timeS, with `program` (bound by
// the caller; a snow variant of opaqueProgram when snowSurface, which takes patches). `shaded`
// sets the albedo (the cull's depth pre-pass needs none).
void SceneRenderer::drawOpaque(const gl::Program& program, const RenderOptions& options,
                               bool shaded, bool snowSurface) {
    const auto draw = [snowSurface](const MeshGpu& mesh) {
        snowSurface ? mesh.drawPatches() : mesh.draw();
    };
    program.set("uModel", glm::mat4(1.0f));
    const bool textured = shaded && mSurfaceTexture.id() != 0;
    if (shaded) {
        // A glTF surface keeps its material's colour; others take the project's ground colour.
        program.set("uAlbedo", mScene->look.baseColor.value_or(options.groundColor));
        program.set("uHasBaseTexture", textured ? 1 : 0);
    }
    if (textured)
        glBindTextureUnit(SURFACE_TEXTURE_UNIT, mSurfaceTexture.id());
    const bool overlaid = shaded && mMapOverlay.id() != 0;
    if (shaded)
        program.set("uHasMapOverlay", overlaid ? 1 : 0);
    if (overlaid)
        glBindTextureUnit(MAP_OVERLAY_UNIT, mMapOverlay.id());
    draw(*mMesh);
    if (shaded) {
        program.set("uHasBaseTexture", 0);  // the props have neither
        program.set("uHasMapOverlay", 0);
    }
    for (std::size_t i = 0; i < mProps.size(); ++i) {
        const core::SceneProp& prop = mScene->props[i];
        program.set("uModel", prop.modelAt(options.timeS));
        if (shaded)
            program.set("uAlbedo", prop.albedo);
        draw(mProps[i]);
    }
}

void SceneRenderer::setMapOverlay(const core::MapImage* map) {
    ++mContentGeneration;
    if (!map) {
        mMapOverlay = {};
        mMapOverlaySize = glm::ivec2(0);
        return;
    }
    const bool empty = map->texels.empty() || map->width <= 0 || map->height <= 0;
    const glm::ivec2 size = empty ? glm::ivec2(1) : glm::ivec2(map->width, map->height);
    // 8 bits a texel: the overlay is a picture of the map, and 1/255 is finer than its colours
    // tell apart.
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size.x) * std::size_t(size.y), 255);
    if (!empty)
        for (std::size_t i = 0; i < bytes.size(); ++i)
            bytes[i] = static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(map->texels[i], 0.0f, 1.0f)));
    if (mMapOverlay.id() == 0 || size != mMapOverlaySize) {
        mMapOverlay = gl::makeTexture2D(GL_R8, size.x, size.y, 1, "map overlay");
        gl::setClampedFiltering(mMapOverlay, GL_LINEAR, GL_LINEAR);
        mMapOverlaySize = size;
    }
    gl::uploadTexture2D(mMapOverlay, size.x, size.y, GL_RED, bytes.data());
}

}  // namespace grass::render
