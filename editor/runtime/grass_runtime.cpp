#include "runtime/grass_runtime.h"

#include <algorithm>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "blade/blade_draw_commands.h"
#include "blade/blade_program_variant.h"
#include "blade/strip_batch.h"
#include "physics/physics_step_inputs.h"
#include "runtime/runtime_gl.h"
#include "util/dispatch_grid.h"
#include "util/software_renderer.h"

namespace grass::runtime {

namespace {

// SSBO and uniform-block bindings of the shaders (blade.glsl, cull.comp, physics.glsl,
// lighting_block.glsl); the draws read through texel views (blade_texels.glsl).
constexpr GLuint BLADES = 0, PATCH_BOUNDS = 1, VISIBLE = 5, COMMANDS = 6, COUNTERS = 7;
constexpr GLuint PHYSICS_PARAMS = 1, ETA = 2, REST_TIPS = 3, WIND_SOURCES = 4, WIND_CENTRES = 5,
                 COLLIDERS = 6, SUBSTEPS = 7, COLLIDER_GROUPS = 8;
// The group size of cull.comp and physics.comp as loaded here, without their GROUP_RUNS or
// GROUP_SIZE define (core/util/blade_pass_group.h: the editor's GRASS_COMPUTE_GROUP knob).
constexpr GLuint WORK_GROUP = 32;
constexpr int MAX_STEPS_PER_UPDATE = 8;

using core::LOD_COUNT;
using Commands = core::BladeCommandBuffer;

bool isSoftwareRenderer() {
    return core::isSoftwareRendererName(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
}

struct LayerGpu {
    GlBuffer blades, shading, patchBounds, visible, commands, eta, restTips;
    GlTexelView bladeTexels, shadingTexels, visibleTexels, commandTexels;
    std::size_t slots = 0;
};

struct MeshGpu {
    GLuint vertexArray = 0;
    GlBuffer vertices, indices;
    GLsizei indexCount = 0;
};

}  // namespace

struct Field::State {
    ExportData data;
    GlProgram cull, mesh, physics;
    // [lit per vertex][blending towards the next LOD]: LODs from core::defaultPixelLitLods on
    // use [1][..], as the editor does; the blades in a LOD's morph band are drawn with [..][1]
    // (core::lodBlending). Only the geometry path in use is compiled: the other path's four
    // programs (half the start-up's compiling) wait for setGeometry.
    GlProgram strips[2][2], tess[2][2];
    std::vector<LayerGpu> layers;
    std::vector<MeshGpu> meshes;
    GlBuffer lighting, counters;
    GlBuffer params, substeps, windSources, windCentres, colliders, colliderGroups;
    GLuint emptyVertexArray = 0;  // no attributes; the strip batches' element buffer
    GlBuffer stripElements;       // core::stripBatchElements(stripElementSegments)
    int stripElementSegments = 0;
    GeometryPath geometry = GeometryPath::Strips;
    bool softwareGl = false;  // the context's renderer, read once at load
    std::vector<std::optional<glm::vec3>> colliderOverride;
    std::uint64_t steps = 0;
    float timeS = 0.0f;
    float carryS = 0.0f;

    ~State() {
        for (MeshGpu& gpuMesh : meshes)
            glDeleteVertexArrays(1, &gpuMesh.vertexArray);
        if (emptyVertexArray != 0)
            glDeleteVertexArrays(1, &emptyVertexArray);
    }

    // The spheres as the physics sees them now: a collider the host moved carries its spheres
    // with it (each keeps its offset from the collider's origin) and leaves its path.
    std::vector<core::SphereCollider> currentSpheres() const {
        std::vector<core::SphereCollider> spheres = data.spheres;
        for (std::size_t i = 0; i < data.colliders.size(); ++i) {
            if (!colliderOverride[i])
                continue;
            const ColliderData& collider = data.colliders[i];
            for (std::size_t s = collider.firstSphere;
                 s < collider.firstSphere + collider.sphereCount; ++s) {
                spheres[s].centre =
                    *colliderOverride[i] + (data.spheres[s].centre - collider.origin);
                spheres[s].path.clear();
            }
        }
        return spheres;
    }

    GlProgram (*bladePrograms(GeometryPath path))[2] {
        return path == GeometryPath::Tessellation ? tess : strips;
    }

    // The four blade programs of `path`, compiled unless they are already; false (with the
    // driver's log in `error`) when one does not compile.
    bool compileBladePrograms(GeometryPath path, std::string& error) {
        GlProgram(*programs)[2] = bladePrograms(path);
        if (programs[0][0].id() != 0)
            return true;
        const std::vector<std::pair<GLenum, std::string>> stages =
            path == GeometryPath::Tessellation
                ? std::vector<std::pair<GLenum, std::string>>{{GL_VERTEX_SHADER, "blade_tess.vert"},
                                                              {GL_TESS_CONTROL_SHADER, "blade.tesc"},
                                                              {GL_TESS_EVALUATION_SHADER, "blade.tese"},
                                                              {GL_FRAGMENT_SHADER, "blade.frag"}}
                : std::vector<std::pair<GLenum, std::string>>{{GL_VERTEX_SHADER, "blade_strip.vert"},
                                                              {GL_FRAGMENT_SHADER, "blade.frag"}};
        GlProgram compiled[2][2];
        for (const bool perVertex : {false, true})
            for (const bool blend : {false, true}) {
                // The export's lighting model is fixed: its programs hold that one alone.
                const core::BladeProgramVariant variant{
                    .tessellate = path == GeometryPath::Tessellation,
                    .lightPerVertex = perVertex,
                    .lodBlend = blend,
                    .simpleLighting = data.lighting.grassLighting == 0};
                std::string log;
                compiled[perVertex][blend] = GlProgram(stages, variant.defines(), log);
                if (compiled[perVertex][blend].id() == 0) {
                    error = log;
                    return false;
                }
            }
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j)
                programs[i][j] = std::move(compiled[i][j]);
        return true;
    }
};

Field::Field() = default;
Field::~Field() = default;
Field::Field(Field&&) noexcept = default;
Field& Field::operator=(Field&&) noexcept = default;

View exportCameraView(const ExportData& data, int width, int height) {
    View view;
    view.width = std::max(width, 1);
    view.height = std::max(height, 1);
    view.cameraPosition = data.camera.position;
    view.view = glm::lookAt(data.camera.position, data.camera.target, glm::vec3(0.0f, 1.0f, 0.0f));
    view.projection =
        glm::perspective(glm::radians(data.camera.fovYDeg), float(view.width) / float(view.height),
                         data.camera.nearM, data.camera.farM);
    return view;
}

bool Field::load(const std::filesystem::path& folder, std::string& error) {
    ExportData data;
    return readExport(folder, data, error) && load(std::move(data), error);
}

bool Field::load(ExportData data, std::string& error) {
    auto state = std::make_unique<State>();
    state->data = std::move(data);
    State& s = *state;
    const auto program = [&](GlProgram& out, std::vector<std::pair<GLenum, std::string>> stages,
                             std::vector<std::string> defines = {}) {
        if (!error.empty())
            return;
        out = GlProgram(stages, defines, error);
    };
    const std::string& geometry = s.data.render.geometry;
    s.softwareGl = isSoftwareRenderer();
    s.geometry = geometry == "tessellation" ? GeometryPath::Tessellation
                 : geometry == "strips"     ? GeometryPath::Strips
                 : s.softwareGl             ? GeometryPath::Strips
                                            : GeometryPath::Tessellation;
    program(s.cull, {{GL_COMPUTE_SHADER, "cull.comp"}});
    program(s.physics, {{GL_COMPUTE_SHADER, "physics.comp"}});
    program(s.mesh, {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}});
    if (!error.empty() || !s.compileBladePrograms(s.geometry, error))
        return false;

    s.lighting = GlBuffer(std::as_bytes(std::span(&s.data.lighting, 1)));
    s.counters = GlBuffer::of(std::vector<std::uint32_t>(8, 0u));
    s.params = GlBuffer::of(std::vector<core::PhysicsParams>{s.data.physics});
    glCreateVertexArrays(1, &s.emptyVertexArray);
    for (const LayerData& layer : s.data.layers) {
        LayerGpu gpu;
        gpu.slots = layer.blades.size();
        gpu.blades = GlBuffer::of(layer.blades);
        gpu.shading = GlBuffer::of(layer.shading);
        gpu.patchBounds = GlBuffer::of(layer.patchBounds);
        gpu.visible = GlBuffer::of(
            std::vector<std::uint32_t>(LOD_COUNT * std::max<std::size_t>(gpu.slots, 1), 0u));
        const Commands commands = core::emptyBladeCommandBuffer(1);
        gpu.commands = GlBuffer(std::as_bytes(std::span(&commands, 1)));
        gpu.bladeTexels = GlTexelView(gpu.blades, GL_RGBA32F);
        gpu.shadingTexels = GlTexelView(gpu.shading, GL_RGBA32F);
        gpu.visibleTexels = GlTexelView(gpu.visible, GL_R32UI);
        gpu.commandTexels = GlTexelView(gpu.commands, GL_R32UI);
        // The physics starts as a grown field stands: at rest, η = 0 (core::restTipsAsGrown).
        std::vector<glm::vec4> tips;
        for (const glm::vec3 tip : core::restTipsAsGrown(layer.blades))
            tips.emplace_back(tip, 0.0f);
        gpu.restTips = GlBuffer::of(tips);
        gpu.eta = GlBuffer::of(std::vector<float>(gpu.slots, 0.0f));
        s.layers.push_back(std::move(gpu));
    }
    for (const MeshData& meshData : s.data.meshes) {
        MeshGpu mesh;
        mesh.vertices = GlBuffer::of(meshData.vertices);
        mesh.indices = GlBuffer::of(meshData.indices);
        mesh.indexCount = static_cast<GLsizei>(meshData.indices.size());
        glCreateVertexArrays(1, &mesh.vertexArray);
        glVertexArrayVertexBuffer(mesh.vertexArray, 0, mesh.vertices.id(), 0, 8 * sizeof(float));
        glVertexArrayElementBuffer(mesh.vertexArray, mesh.indices.id());
        const GLint sizes[] = {3, 3, 2};
        const GLuint offsets[] = {0, 3 * sizeof(float), 6 * sizeof(float)};
        for (GLuint a = 0; a < 3; ++a) {
            glEnableVertexArrayAttrib(mesh.vertexArray, a);
            glVertexArrayAttribFormat(mesh.vertexArray, a, sizes[a], GL_FLOAT, GL_FALSE,
                                      offsets[a]);
            glVertexArrayAttribBinding(mesh.vertexArray, a, 0);
        }
        s.meshes.push_back(std::move(mesh));
    }
    s.colliderOverride.assign(s.data.colliders.size(), std::nullopt);
    mState = std::move(state);
    return true;
}

const ExportData& Field::data() const {
    return mState->data;
}

float Field::timeS() const {
    return mState->timeS;
}

GeometryPath Field::geometry() const {
    return mState->geometry;
}

void Field::setGeometry(GeometryPath path) {
    std::string error;
    setGeometry(path, error);
}

bool Field::setGeometry(GeometryPath path, std::string& error) {
    if (!mState->compileBladePrograms(path, error))
        return false;
    mState->geometry = path;
    return true;
}

glm::vec3 Field::colliderOrigin(std::size_t i) const {
    const ColliderData& collider = mState->data.colliders.at(i);
    if (mState->colliderOverride.at(i))
        return *mState->colliderOverride[i];
    return core::samplePath(collider.path, mState->timeS, collider.origin);
}

void Field::moveCollider(std::size_t i, glm::vec3 origin) {
    mState->colliderOverride.at(i) = origin;
}

void Field::releaseCollider(std::size_t i) {
    mState->colliderOverride.at(i).reset();
}

void Field::update(float seconds) {
    State& s = *mState;
    const float stepS = s.data.physics.dtS;
    if (stepS <= 0.0f)
        return;
    s.carryS += std::max(seconds, 0.0f);
    int steps = 0;
    while (s.carryS >= stepS && steps < MAX_STEPS_PER_UPDATE) {
        step();
        s.carryS -= stepS;
        ++steps;
    }
    // A host slower than the physics drops the time it cannot catch up with.
    s.carryS = std::min(s.carryS, stepS);
}

// One step of every layer, exactly as the editor's PhysicsGpu runs it (the same inputs from
// core::physicsStepInputs, the same shader), then the clock as SceneSimulation keeps it.
void Field::step() {
    State& s = *mState;
    const std::vector<core::SphereCollider> spheres = s.currentSpheres();
    const core::PhysicsStepInputs inputs =
        core::physicsStepInputs(s.data.physics, s.data.wind, spheres, s.timeS);
    if (inputs.substepCount > 0) {
        s.substeps.assign(inputs.substeps);
        if (!s.data.wind.empty()) {
            s.windSources.assign(inputs.windSources);
            s.windCentres.assign(inputs.windCentres);
            s.windSources.bindStorage(WIND_SOURCES);
            s.windCentres.bindStorage(WIND_CENTRES);
        }
        if (!spheres.empty()) {
            s.colliders.assign(inputs.colliderSpheres);
            s.colliderGroups.assign(inputs.colliderGroups);
            s.colliders.bindStorage(COLLIDERS);
            s.colliderGroups.bindStorage(COLLIDER_GROUPS);
        }
        s.physics.use();
        s.physics.set("substepCount", inputs.substepCount);
        s.physics.set("windCount", unsigned(s.data.wind.size()));
        s.physics.set("colliderCount", unsigned(spheres.size()));
        s.physics.set("gravityLoadScale", 0.0f);
        s.params.bindStorage(PHYSICS_PARAMS);
        s.substeps.bindStorage(SUBSTEPS);
        for (LayerGpu& layer : s.layers) {
            if (layer.slots == 0)
                continue;
            layer.blades.bindStorage(BLADES);
            layer.eta.bindStorage(ETA);
            layer.restTips.bindStorage(REST_TIPS);
            s.physics.set("bladeCount", unsigned(layer.slots));
            const core::DispatchGrid grid = core::dispatchGrid(layer.slots, WORK_GROUP);
            glDispatchCompute(grid.x, grid.y, 1);
        }
        // The cull and the draws read the blades through texel views; read-backs as a buffer.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                        GL_TEXTURE_FETCH_BARRIER_BIT);
        glUseProgram(0);
    }
    ++s.steps;
    // From the step count, so the clock does not drift by a rounding per step.
    s.timeS = static_cast<float>(static_cast<double>(s.steps) * s.data.physics.dtS);
}

void Field::draw(const View& view) {
    State& s = *mState;
    const RenderData& render = s.data.render;
    const int segments = std::max(render.stripSegments, 1);
    const glm::mat4 viewProj = view.projection * view.view;
    glBindBufferBase(GL_UNIFORM_BUFFER, core::LIGHTING_BLOCK_BINDING, s.lighting.id());

    // The cull (SPEC §6): the editor's tests but occlusion, which needs the host's depth.
    const GlProgram& cull = s.cull;
    cull.use();
    cull.set("uViewProj", viewProj);
    cull.set("uCameraPosition", view.cameraPosition);
    cull.set("uProj22", view.projection[2][2]);
    cull.set("uProj32", view.projection[3][2]);
    cull.set("uTestPatch", 1);
    cull.set("uTestOrientation", 1);
    cull.set("uTestFrustum", 1);
    cull.set("uTestDistance", render.thinningDistanceM > 0.0f ? 1 : 0);
    cull.set("uTestOcclusion", 0);
    cull.set("uDistanceClasses", 8);
    cull.set("uMaxDistance", std::max(render.thinningDistanceM, 1e-3f));
    cull.set("uCutoffDistance", 0.0f);
    cull.set("uKeepEvery", 1);
    cull.set("uLodDistance", std::max(render.lodDistanceM, 0.0f));
    cull.set("uLodBlend", core::LOD_BLEND);
    cull.set("uCollectStats", 0);
    s.counters.bindStorage(COUNTERS);
    const Commands commands = core::emptyBladeCommandBuffer(segments);
    for (std::size_t i = 0; i < s.layers.size(); ++i) {
        const LayerGpu& layer = s.layers[i];
        glNamedBufferSubData(layer.commands.id(), 0, sizeof commands, &commands);
        if (layer.slots == 0)
            continue;
        layer.bladeTexels.bind(core::BLADE_TEXELS_UNIT);  // cull.comp reads the blades there
        layer.patchBounds.bindStorage(PATCH_BOUNDS);
        layer.visible.bindStorage(VISIBLE);
        layer.commands.bindStorage(COMMANDS);
        cull.set("uBladeCount", unsigned(layer.slots));
        cull.set("uPatchSize", std::max(s.data.layers[i].patchSize, 1u));
        const core::DispatchGrid grid = core::dispatchGrid(layer.slots, WORK_GROUP);
        glDispatchCompute(grid.x, grid.y, 1);
    }
    // The draws read the commands (indirect) and the visible lists (texel views).
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_SHADER_STORAGE_BARRIER_BIT);

    // The blades (SPEC §7, §10), one indirect draw per LOD and layer.
    const bool tessellate = s.geometry == GeometryPath::Tessellation;
    const GlProgram(*programs)[2] = s.bladePrograms(s.geometry);
    for (int variant = 0; variant < 4; ++variant) {
        const GlProgram& program = programs[variant / 2][variant % 2];
        program.set("uViewProj", viewProj);
        program.set("uPixelScale", view.projection[1][1] * 0.5f * static_cast<float>(view.height));
        program.set("uTessLevel", static_cast<float>(std::max(render.tessLevel, 1)));
        program.set("uWidthScale", 1.0f);
        program.set("uCameraPosition", view.cameraPosition);
        program.set("uLodDistance", std::max(render.lodDistanceM, 0.0f));
        program.set("uLodBlend", core::LOD_BLEND);
        program.set("uAlbedoView", 0);
    }
    GLint samples = 0;  // of the host's framebuffer
    glGetIntegerv(GL_SAMPLES, &samples);
    const int pixelLitLods = core::defaultPixelLitLods(s.softwareGl, samples);
    const GLboolean cullFace = glIsEnabled(GL_CULL_FACE);
    glDisable(GL_CULL_FACE);  // blades are two-sided
    if (!tessellate && segments != s.stripElementSegments) {
        // The strips are drawn in batches (core/blade/strip_batch.h) of these index lists.
        s.stripElements = GlBuffer::of(core::stripBatchElements(segments));
        glVertexArrayElementBuffer(s.emptyVertexArray, s.stripElements.id());
        s.stripElementSegments = segments;
    }
    glBindVertexArray(s.emptyVertexArray);
    if (tessellate)
        glPatchParameteri(GL_PATCH_VERTICES, 1);
    for (std::size_t i = 0; i < s.layers.size(); ++i) {
        const LayerGpu& layer = s.layers[i];
        const LayerData& data = s.data.layers[i];
        if (layer.slots == 0)
            continue;
        for (int variant = 0; variant < 4; ++variant) {
            const GlProgram& program = programs[variant / 2][variant % 2];
            program.set("uRootColor", data.rootColor);
            program.set("uTipColor", data.tipColor);
            program.set("uPoorRootColor", data.poorRootColor);
            program.set("uPoorTipColor", data.poorTipColor);
            program.set("uShape", data.shape);
            program.set("uTipStart", data.tipStart);
        }
        layer.bladeTexels.bind(core::BLADE_TEXELS_UNIT);
        layer.visibleTexels.bind(core::VISIBLE_TEXELS_UNIT);
        layer.commandTexels.bind(core::COMMAND_TEXELS_UNIT);
        layer.shadingTexels.bind(core::SHADING_TEXELS_UNIT);
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, layer.commands.id());
        // Each LOD's blades before its morph band, then those in it (listed from the end of
        // the LOD's list, backwards, by the cull).
        for (const bool blending : {false, true})
            for (int lod = 0; lod < LOD_COUNT; ++lod) {
                const GlProgram& program = programs[lod >= pixelLitLods ? 1 : 0][blending];
                program.use();
                program.set("uVisibleOffset",
                            unsigned(core::visibleListStart(lod, layer.slots, blending)));
                program.set("uVisibleBackwards", blending ? 1 : 0);
                program.set("uSurvivorWord", core::stripSurvivorWord(lod, blending));
                if (tessellate) {
                    glDrawArraysIndirect(GL_PATCHES, reinterpret_cast<const void*>(
                                                         core::patchCommandOffset(lod, blending)));
                } else {
                    program.set("uSegments", core::lodSegments(segments, lod));
                    program.set("uLod", lod);
                    glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                           reinterpret_cast<const void*>(
                                               core::stripBatchCommandOffset(lod, blending)));
                }
            }
    }
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(0);
    glUseProgram(0);
    if (cullFace)
        glEnable(GL_CULL_FACE);
}

void Field::drawMeshes(const View& view) {
    State& s = *mState;
    glBindBufferBase(GL_UNIFORM_BUFFER, core::LIGHTING_BLOCK_BINDING, s.lighting.id());
    const GlProgram& program = s.mesh;
    program.use();
    program.set("uViewProj", view.projection * view.view);
    program.set("uAlbedoView", 0);
    const auto drawMesh = [&](std::size_t index, const glm::mat4& model) {
        const MeshGpu& mesh = s.meshes[index];
        if (mesh.indexCount == 0)
            return;
        program.set("uModel", model);
        program.set("uAlbedo", s.data.meshes[index].albedo);
        glBindVertexArray(mesh.vertexArray);
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    };
    const GLboolean cullFace = glIsEnabled(GL_CULL_FACE);
    glDisable(GL_CULL_FACE);  // open meshes are seen from both sides
    drawMesh(0, glm::mat4(1.0f));
    // A prop stands where its collider is: translate(origin) · scale, as the editor draws it.
    for (std::size_t i = 0; i < s.data.colliders.size(); ++i)
        if (const int mesh = s.data.colliders[i].mesh; mesh > 0)
            drawMesh(std::size_t(mesh),
                     glm::scale(glm::translate(glm::mat4(1.0f), colliderOrigin(i)),
                                glm::vec3(s.data.colliders[i].scale)));
    glBindVertexArray(0);
    glUseProgram(0);
    if (cullFace)
        glEnable(GL_CULL_FACE);
}

DrawStats Field::readStats() const {
    DrawStats stats;
    for (const LayerGpu& layer : mState->layers) {
        core::BladeDrawCommands commands{};
        glGetNamedBufferSubData(layer.commands.id(), 0, sizeof commands, commands.data());
        for (int lod = 0; lod < LOD_COUNT; ++lod)
            stats.bladesDrawn += core::drawnAtLod(commands, lod);
    }
    return stats;
}

std::vector<core::Blade> Field::readBlades(std::size_t layer) const {
    const LayerGpu& gpu = mState->layers.at(layer);
    std::vector<core::Blade> blades(gpu.slots);
    if (!blades.empty())
        glGetNamedBufferSubData(gpu.blades.id(), 0, GLsizeiptr(blades.size() * sizeof(core::Blade)),
                                blades.data());
    return blades;
}

}  // namespace grass::runtime
