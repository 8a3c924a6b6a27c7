#include "render/scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "gl/headless_context.h"
#include "util/assert.h"

namespace grass::render {

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

// A glTF surface's base-colour texture: sRGB storage (the file's colours are sRGB-encoded, the
// shading is linear), mipmapped, wrapped as its sampler says (glTF's wrap numbers are GL's).
static gl::TextureHandle uploadSurfaceTexture(const Rgba8Pixels& image, const core::SurfaceLook& look) {
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height))));
    gl::TextureHandle texture =
        gl::makeTexture2D(GL_SRGB8_ALPHA8, image.width, image.height, levels, "surface base colour");
    gl::uploadTexture2D(texture, image.width, image.height, GL_RGBA, image.pixels.data());
    glGenerateTextureMipmap(texture.id());
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(GL_LINEAR_MIPMAP_LINEAR));
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(GL_LINEAR));
    const auto wrap = [](int gltf) -> GLint {
        const bool known = gltf == static_cast<GLint>(GL_CLAMP_TO_EDGE) ||
                           gltf == static_cast<GLint>(GL_MIRRORED_REPEAT);
        return known ? gltf : static_cast<GLint>(GL_REPEAT);
    };
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, wrap(look.wrapS));
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, wrap(look.wrapT));
    return texture;
}

// The blade program of a variant (compile-time variants: software GL runs both sides of a
// uniform branch, so an unused path would still cost). Without the fade a blade lit per vertex
// hands its fragments one colour and nothing else: the fade's distance and its position varying
// cost llvmpipe 12 % of nature-100k's grass pass at 4× MSAA; the blend's extra evaluations cost
// it ~20 % more, so only the blades in a morph band are drawn with it; the tip snow's lookup
// runs only while snow lies; a program holds one lighting model (docs/rendering.md).
Result<gl::Program> SceneRenderer::loadBladeProgram(const BladeVariant& variant) {
    const std::vector<std::string> defines = variant.defines();
    const std::string label = variant.label();
    if (variant.tessellate)
        return gl::Program::load({{GL_VERTEX_SHADER, "blade_tess.vert"},
                                  {GL_TESS_CONTROL_SHADER, "blade.tesc"},
                                  {GL_TESS_EVALUATION_SHADER, "blade.tese"},
                                  {GL_FRAGMENT_SHADER, "blade.frag"}},
                                 label, defines);
    return gl::Program::load(
        {{GL_VERTEX_SHADER, "blade_strip.vert"}, {GL_FRAGMENT_SHADER, "blade.frag"}}, label,
        defines);
}

const gl::Program& SceneRenderer::bladeProgram(const BladeVariant& variant) {
    return gl::loadOnFirstUse(mBladePrograms[variant.index()],
                              [&] { return loadBladeProgram(variant); });
}

SceneRenderer::~SceneRenderer() {
    mPlacingStop.request_stop();
    if (mPlacing.valid())
        mPlacing.wait();
}

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(const core::Scene& scene,
                                                             const SceneRenderer* sameSurface) {
    std::unique_ptr<SceneRenderer> renderer(new SceneRenderer());
    renderer->mScene = &scene;
    renderer->mSoftwareGl = gl::isSoftwareRenderer();
    auto mesh = loadOpaqueProgram(Opaque::Lit, false);
    if (!mesh)
        return mesh.error();
    for (const bool tessellate : {false, true}) {
        const BladeVariant plain{.tessellate = tessellate};
        if (auto loaded = loadBladeProgram(plain); loaded)
            renderer->mBladePrograms[plain.index()] = std::move(*loaded);
        else
            return loaded.error();
    }
    auto stemSets = loadStemSetProgram();
    if (!stemSets)
        return stemSets.error();
    renderer->mStemSetPrograms[0] = std::move(*stemSets);
    auto cull = CullPass::create();
    if (!cull)
        return cull.error();
    renderer->mCull = std::make_unique<CullPass>(std::move(*cull));
    renderer->mFieldAo = meanFieldAo(scene);
    renderer->mOpaquePrograms[0][static_cast<int>(Opaque::Lit)] = std::move(*mesh);
    renderer->mMesh =
        sameSurface != nullptr ? sameSurface->mMesh : std::make_shared<const MeshGpu>(scene.mesh);
    if (const Rgba8Pixels& image = scene.look.baseTexture; !image.pixels.empty())
        renderer->mSurfaceTexture = uploadSurfaceTexture(image, scene.look);
    renderer->reloadProps();
    renderer->mFields.reserve(scene.layers.size());
    for (const auto& layer : scene.layers)
        renderer->mFields.emplace_back(layer);
    return renderer;
}

// The frame's target cleared to the sky, with the state every pass of the frame starts from.
static void beginFrame(gl::FramebufferRef framebuffer, int width, int height, glm::vec3 sky) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // blades and open meshes are two-sided
    glEnable(GL_MULTISAMPLE);
    glClearColor(sky.r, sky.g, sky.b, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // The image stays opaque: alpha-to-coverage (hybrid blades, billboards) turns fragment
    // alpha into coverage, and writing it too would leave see-through pixels in saved images.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
}

// `framebuffer` when it has a 32-bit float depth attachment (gl::Framebuffer's, which the cull's
// occlusion texture can be resolved from: a blit needs equal depth formats), else 0.
GLuint SceneRenderer::floatDepthOf(GLuint framebuffer) {
    if (framebuffer == 0)
        return 0;  // the window's: its depth format is the driver's
    GLint type = GL_NONE, bits = 0;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_DEPTH_ATTACHMENT,
                                               GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_DEPTH_ATTACHMENT,
                                               GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    return type == GL_FLOAT && bits == 32 ? framebuffer : 0;
}

void SceneRenderer::render(const core::OrbitCamera& camera, int width, int height,
                           gl::FramebufferRef framebuffer, const RenderOptions& options) {
    const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
    const glm::mat4 projection = camera.projection(aspect);
    mPasses.clear();
    // Every program that lights a surface reads this one upload, the sun's shadows included.
    LightingBlock lighting =
        lightingBlock(options.lighting, options.sun, options.skyColor, options.groundColor);
    runSunShadowPass(options, lighting);  // before the frame's target is bound and cleared
    beginFrame(framebuffer, width, height, options.skyColor);
    mLighting.upload(lighting);
    // Figures a frame's caller reads are timed exactly on software GL (gl/timer_query.h).
    const bool synchronous =
        mSoftwareGl && (options.cull.collectStats || options.exactStageTimings);
    for (gl::GpuTimer* timer : {&mMeshTimer, &mGrassTimer, &mCullTimer, &mBillboardTimer,
                                &mStemSetTimer, &mSnowTimer})
        timer->setSynchronous(synchronous);
    runSnowPass(options, width, height);
    mFrameDepth = floatDepthOf(framebuffer.id());
    drawOpaquePass(projection * camera.view(), options);
    drawGrass(camera, projection, width, height, options);
    glBindVertexArray(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void SceneRenderer::uploadBlades(std::size_t layer, std::span<const core::Blade> blades) {
    ++mContentGeneration;
    if (layer < mFields.size())
        mFields[layer].uploadBlades(blades);
}

void SceneRenderer::uploadRegrown(std::size_t layer, const core::RegrowReport& report) {
    ++mContentGeneration;
    if (layer >= mFields.size())
        return;
    mFields[layer].uploadPatches(report.patches, false);
    mFields[layer].uploadPatches(report.shadedPatches, true);
    mFieldAo = meanFieldAo(*mScene);
    // The maps changed: the billboards follow them when next drawn (a field drawn by blades
    // alone pays nothing).
    mBillboardsStale = true;
    if (layer < mStemSets.size()) {
        const core::LayerField& field = mScene->layers[layer];
        for (std::uint32_t p : report.patches) {
            const auto [first, end] = core::patchStemSets(field, p);
            mStemSets[layer].update(first, std::span(field.stemSets).subspan(first, end - first));
        }
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
    if (mSnow && mSnow->driftCells() > 0)
        timings.allocated.push_back("snow_drift");
    if (std::any_of(std::begin(mOpaquePrograms), std::end(mOpaquePrograms), [](const auto& shadows) {
            return shadows[static_cast<int>(Opaque::Snow)].id() != 0 ||
                   shadows[static_cast<int>(Opaque::SnowExposurePerVertex)].id() != 0;
        }))
        timings.allocated.push_back("snow_programs");
    if (std::any_of(mFields.begin(), mFields.end(),
                    [](const FieldGpu& field) { return field.hasTipSnow(); }))
        timings.allocated.push_back("tip_snow");
    if (mBillboards)
        timings.allocated.push_back("billboards");
    if (!mStemSets.empty())
        timings.allocated.push_back("stem_sets");
    if (mSunShadow)
        timings.allocated.push_back("sun_shadow_map");
    return timings;
}

void SceneRenderer::reloadProps() {
    ++mOccluderGeometry;
    mProps.clear();
    mProps.reserve(mScene->props.size());
    for (const auto& prop : mScene->props)
        mProps.emplace_back(prop.mesh);
}

}  // namespace grass::render
