#include "scene_renderer.h"

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
    return options;
}

const char* geometryPathLabel(GeometryPath path) {
    return path == GeometryPath::Tessellation ? "tess" : "strips";
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
    auto cull = CullPass::create();
    if (!cull)
        return cull.error();
    renderer->mCull = std::make_unique<CullPass>(std::move(*cull));
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

static void setLighting(const gl::Program& program, const RenderOptions& options) {
    const glm::vec3 direction = glm::length(options.sun.direction) > 0.0f
                                    ? glm::normalize(options.sun.direction)
                                    : glm::vec3(0, -1, 0);
    program.set("uSunDirection", direction);
    program.set("uSunColor", options.sun.color * options.sun.intensity);
    program.set("uSkyColor", options.skyColor);
    program.set("uGroundColor", options.groundColor);
}

static void setGrassLighting(const gl::Program& program, const core::GrassLightingDesc& lighting) {
    program.set("uGrassLighting", lighting.model == core::LightingModel::Grass ? 1 : 0);
    program.set("uDiffuseLow", lighting.diffuseLow);
    program.set("uDiffuseMid", lighting.diffuseMid);
    program.set("uDiffuseHigh", lighting.diffuseHigh);
    program.set("uTerrainNormalWeight", lighting.terrainNormalWeight);
    program.set("uSpecular", lighting.specular);
    program.set("uSpecularFade", lighting.specularFadeM);
    program.set("uTransmission", lighting.transmission);
    program.set("uTransmissionDistortion", lighting.transmissionDistortion);
    program.set("uTransmissionPower", lighting.transmissionPower);
    program.set("uSss", lighting.sss);
    program.set("uSssIntensity", lighting.sssIntensity);
}

void SceneRenderer::render(const core::OrbitCamera& camera, int width, int height,
                           GLuint framebuffer, const RenderOptions& options) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);  // blades and open meshes are two-sided
    glEnable(GL_MULTISAMPLE);
    glClearColor(options.skyColor.r, options.skyColor.g, options.skyColor.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
    const glm::mat4 projection = camera.projection(aspect);
    const glm::mat4 viewProj = projection * camera.view();

    mMeshTimer.begin();
    mMeshProgram.use();
    mMeshProgram.set("uViewProj", viewProj);
    setLighting(mMeshProgram, options);
    drawOpaque(options, true);
    mMeshTimer.end();

    const int segments = std::max(options.stripSegments, 1);
    mCullTimer.begin();
    const CullView cullView{camera.view(), projection, camera.position(), width, height, segments};
    mCull->run(mFields, cullView, options.cull, [this, &options] {
        mMeshProgram.use();
        drawOpaque(options, false);
    });
    mCullTimer.end();
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
    setLighting(program, options);
    setGrassLighting(program, options.lighting);
    mBladesDrawn = 0;
    for (auto& field : mFields) {
        program.set("uRootColor", field.field().rootColor);
        program.set("uTipColor", field.field().tipColor);
        const core::BladeShape shape = options.shape.value_or(field.field().shape);
        program.set("uShape", static_cast<int>(shape));
        program.set("uTipStart", field.field().tipStart);
        if (tessellate)
            field.drawTessellated(program);
        else
            field.drawStrips(program, segments);
        mBladesDrawn += field.field().liveBlades;
    }
    mGrassTimer.end();
    glBindVertexArray(0);
}

// The terrain, then each prop where its path puts it at options.timeS. `shaded` sets the albedo
// (the depth pre-pass of the cull needs none).
void SceneRenderer::drawOpaque(const RenderOptions& options, bool shaded) const {
    mMeshProgram.set("uModel", glm::mat4(1.0f));
    if (shaded)
        mMeshProgram.set("uAlbedo", options.groundColor);
    mMesh->draw();
    for (std::size_t i = 0; i < mProps.size(); ++i) {
        const core::SceneProp& prop = mScene->props[i];
        mMeshProgram.set("uModel", prop.modelAt(options.timeS));
        if (shaded)
            mMeshProgram.set("uAlbedo", prop.albedo);
        mProps[i].draw();
    }
}

std::vector<GLuint> SceneRenderer::bladeBuffers() const {
    std::vector<GLuint> ids;
    for (const FieldGpu& field : mFields)
        ids.push_back(field.bladeBuffer());
    return ids;
}

FrameTimings SceneRenderer::lastTimings() const {
    FrameTimings timings;
    timings.meshMs = mMeshTimer.milliseconds();
    timings.grassMs = mGrassTimer.milliseconds();
    timings.cullMs = mCullTimer.milliseconds();
    timings.bladesDrawn = mBladesDrawn;
    if (mStatsFrame)
        timings.cull = mCull->readStats(mFields);
    return timings;
}

}  // namespace grass::render
