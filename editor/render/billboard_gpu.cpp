#include "render/billboard_gpu.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>

#include "gl/scoped_capability.h"
#include "gl/texture.h"
#include "physics/physics_step_inputs.h"
#include "scene/frustum.h"

namespace grass::render {

namespace {

using gl::ScopedCapability;

// Alpha-to-coverage works on multisampled targets; without samples the fragment shader's cutoff
// alone decides, so it cuts at half coverage instead of discarding only the empty texels.
constexpr float ALPHA_CUTOFF_MULTISAMPLED = 0.02f;
constexpr float ALPHA_CUTOFF_SINGLE_SAMPLED = 0.5f;

// A cluster's objects among the instances one in `keepEvery` draws (all of them for 1).
core::KeptObjects clusterObjects(const core::StarCluster& cluster, std::uint32_t keepEvery) {
    return core::keptObjects(cluster.firstVertex / core::STAR_VERTICES_PER_OBJECT,
                             cluster.vertexCount / core::STAR_VERTICES_PER_OBJECT, keepEvery);
}

// glMultiDrawElementsIndirect's command (the GL's DrawElementsIndirectCommand).
struct DrawCommand {
    GLuint count = core::STAR_INDICES_PER_OBJECT;
    GLuint instanceCount = 0;
    GLuint firstIndex = 0;
    GLint baseVertex = 0;
    GLuint baseInstance = 0;
};

gl::TextureHandle uploadTexture(const Rgba8Pixels& image, std::string_view label) {
    const auto largest = static_cast<unsigned>(std::max({image.width, image.height, 1}));
    const auto levels = static_cast<int>(std::bit_width(largest));
    gl::TextureHandle texture =
        gl::makeTexture2D(GL_RGBA8, image.width, image.height, levels, label);
    // Row 0 (the image's top) goes to t = 0: the star vertices' v = 0 at their tops matches.
    gl::uploadTexture2D(texture, image.width, image.height, GL_RGBA, image.pixels.data());
    glGenerateTextureMipmap(texture.id());
    // Clamped: repeating would bleed the blade tips at the top into the roots at the bottom.
    gl::setClampedFiltering(texture, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    return texture;
}

Result<gl::Program> loadBillboardProgram(bool sunShadows) {
    return gl::Program::load(
        {{GL_VERTEX_SHADER, "billboard.vert"}, {GL_FRAGMENT_SHADER, "billboard.frag"}},
        sunShadows ? "billboards (sun shadows)" : "billboards",
        sunShadows ? std::vector<std::string>{"GRASS_SUN_SHADOWS"} : std::vector<std::string>{});
}

}  // namespace

const gl::Program& BillboardField::program(bool sunShadows) {
    return gl::loadOnFirstUse(mPrograms[sunShadows],
                              [sunShadows] { return loadBillboardProgram(sunShadows); });
}

Result<BillboardField> BillboardField::create(const std::vector<core::GrassObject>& objects,
                                              const Rgba8Pixels& texture, std::string_view label) {
    if (texture.width <= 0 || texture.height <= 0 ||
        texture.pixels.size() !=
            static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height) * 4)
        return makeError(std::string(label), "billboard texture size does not match its pixels");
    auto program = loadBillboardProgram(false);
    if (!program)
        return program.error();

    BillboardField field;
    field.mPrograms[0] = std::move(*program);
    field.mLabel = std::string(label);
    field.mTexture = uploadTexture(texture, field.mLabel + " texture");
    field.mVertexArray = gl::VertexArray(field.mLabel);
    const gl::VertexAttribute attributes[] = {
        {4, offsetof(core::StarInstance, centre)},
        {4, offsetof(core::StarInstance, up)},
        {4, offsetof(core::StarInstance, across0)},
        {4, offsetof(core::StarInstance, across90)},
    };
    field.mVertexArray.setAttributes(attributes);
    field.mVertexArray.setInstanceDivisor(1);
    field.mIndices =
        gl::Buffer::fromVector(core::starQuadIndices(1), field.mLabel + " star indices", 0);
    field.mVertexArray.setElementBuffer(field.mIndices);
    field.setObjects(objects);
    return field;
}

void BillboardField::setObjects(const std::vector<core::GrassObject>& objects) {
    const core::StarInstances stars = core::buildStarInstances(objects);
    mObjectCount = stars.stars.size();
    mClusters = stars.clusters;
    mTallestObjectM = 0.0f;
    for (const core::GrassObject& object : objects)
        mTallestObjectM = std::max(mTallestObjectM, object.height);
    mStars = gl::Buffer::fromVector(stars.stars, mLabel + " stars", 0);
    mDrawCommands =
        gl::Buffer::fromVector(std::vector<DrawCommand>(std::max<std::size_t>(mClusters.size(), 1)),
                               mLabel + " draw commands");
    mVertexArray.setVertexBuffer(mStars, sizeof(core::StarInstance));
}

// Clusters that may hold a visible object, back to front (ties by index, so the order is
// deterministic). Every object centre lies within the cluster's radius of its centre, and the
// fade is 0 outside [in start, out end]. The sway moves upper vertices by at most its amplitude
// (core::billboardWindOffset), the scene's wind by less than the object's height
// (core::billboardWindBend).
std::vector<std::uint32_t> BillboardField::visibleClusters(
    const BillboardDrawParams& params) const {
    const core::FrustumPlanes planes = core::frustumPlanes(params.viewProj);
    const float sway =
        std::abs(params.wind.amplitudeM) + (params.sceneWind.empty() ? 0.0f : mTallestObjectM);
    std::vector<std::pair<float, std::uint32_t>> byDistance;
    for (std::uint32_t c = 0; c < mClusters.size(); ++c) {
        const core::StarCluster& cluster = mClusters[c];
        if (cluster.vertexCount == 0)
            continue;
        const float d = glm::distance(params.cameraPosWorld, cluster.centre);
        if (d - cluster.radius > params.fade.outEndM || d + cluster.radius < params.fade.inStartM)
            continue;
        if (params.frustumCull && core::sphereOutside(planes, cluster.centre, cluster.radius + sway))
            continue;
        byDistance.emplace_back(d, c);
    }
    std::sort(byDistance.begin(), byDistance.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    std::vector<std::uint32_t> order;
    order.reserve(byDistance.size());
    for (const auto& entry : byDistance)
        order.push_back(entry.second);
    return order;
}

// The scene's wind sources as the shader reads them (billboard_wind.glsl), each centre on its path
// at the draw's time.
void BillboardField::uploadSceneWind(const BillboardDrawParams& params) {
    const core::WindSourcesAt wind = core::packWindSourcesAt(params.sceneWind, params.timeS);
    const std::size_t bytes = wind.sources.size() * sizeof(core::WindSourceGpu);
    if (mWindSources.size() < bytes) {
        mWindSources = gl::Buffer::fromVector(wind.sources, mLabel + " wind sources");
        mWindCentres = gl::Buffer::fromVector(wind.centres, mLabel + " wind centres");
    } else {
        mWindSources.update(std::as_bytes(std::span(wind.sources)));
        mWindCentres.update(std::as_bytes(std::span(wind.centres)));
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BILLBOARD_WIND_SOURCE_BINDING, mWindSources.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BILLBOARD_WIND_CENTRE_BINDING, mWindCentres.id());
}

// Binds the program with the uniforms of `params`, the texture and the vertex array.
void BillboardField::bindForDraw(const BillboardDrawParams& params, bool multisampled) {
    const gl::Program& program = this->program(params.sunShadows);
    program.use();
    program.set("uViewProj", params.viewProj);
    program.set("uCameraPos", params.cameraPosWorld);
    program.set("uTime", params.timeS);
    program.set("uWindMode", static_cast<int>(params.mode));
    program.set("uWindDirection", params.wind.directionXZ);
    program.set("uWindAmplitude", params.wind.amplitudeM);
    program.set("uWindFrequency", params.wind.frequencyHz);
    program.set("uClusterOffset", glm::vec3(0.0f));
    program.set("uClusterWind", glm::vec3(0.0f));
    program.set("uStiffness", params.stiffness);
    program.set("uWindSourceCount", static_cast<int>(params.sceneWind.size()));
    if (!params.sceneWind.empty())
        uploadSceneWind(params);
    program.set("uFade", glm::vec4(params.fade.inStartM, params.fade.inEndM, params.fade.outStartM,
                                    params.fade.outEndM));
    program.set("uAlphaCutoff",
                 multisampled ? ALPHA_CUTOFF_MULTISAMPLED : ALPHA_CUTOFF_SINGLE_SAMPLED);
    program.set("uWidthScale", params.widthScale);
    glBindTextureUnit(BILLBOARD_TEXTURE_UNIT, mTexture.id());
    // One star in keepEvery: instance j reads star j·keepEvery.
    mVertexArray.setVertexBuffer(mStars,
                                 sizeof(core::StarInstance) * std::max(params.keepEvery, 1u));
    mVertexArray.bind();
}

// Per-cluster wind: one draw per cluster, each with the sway and the scene's wind the CPU
// computed at its centre.
void BillboardField::drawEachCluster(const std::vector<std::uint32_t>& order,
                                     const BillboardDrawParams& params) {
    const gl::Program& program = this->program(params.sunShadows);
    for (const std::uint32_t c : order) {
        const core::StarCluster& cluster = mClusters[c];
        program.set("uClusterOffset",
                     core::billboardWindOffset(cluster.centre, params.timeS, params.wind));
        if (!params.sceneWind.empty())
            program.set("uClusterWind",
                         core::windAt(params.sceneWind, cluster.centre, params.timeS));
        const core::KeptObjects kept = clusterObjects(cluster, params.keepEvery);
        if (kept.count == 0)
            continue;
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES, core::STAR_INDICES_PER_OBJECT,
                                            GL_UNSIGNED_INT, nullptr, GLsizei(kept.count),
                                            kept.first);
        ++mDrawCalls;
    }
}

// Wind in the vertex shader: every cluster in one glMultiDrawElementsIndirect, in `order`.
void BillboardField::drawClustersAtOnce(const std::vector<std::uint32_t>& order,
                                        std::uint32_t keepEvery) {
    std::vector<DrawCommand> commands;
    commands.reserve(order.size());
    for (const std::uint32_t c : order) {
        const core::KeptObjects kept = clusterObjects(mClusters[c], keepEvery);
        if (kept.count > 0)
            commands.push_back({.instanceCount = kept.count, .baseInstance = kept.first});
    }
    if (commands.empty())
        return;
    mDrawCommands.update(std::as_bytes(std::span<const DrawCommand>(commands)));
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mDrawCommands.id());
    glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr,
                                static_cast<GLsizei>(commands.size()), 0);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    ++mDrawCalls;
}

void BillboardField::draw(const BillboardDrawParams& params) {
    mDrawnObjects = 0;
    mDrawCalls = 0;
    const std::vector<std::uint32_t> order = visibleClusters(params);
    if (order.empty())
        return;

    GLint sampleBuffers = 0;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    const ScopedCapability alphaToCoverage(GL_SAMPLE_ALPHA_TO_COVERAGE, true);
    const ScopedCapability depthTest(GL_DEPTH_TEST, true);
    const ScopedCapability cullFace(GL_CULL_FACE, false);
    GLboolean depthMask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    glDepthMask(GL_TRUE);

    bindForDraw(params, sampleBuffers > 0);
    for (const std::uint32_t c : order)
        mDrawnObjects += clusterObjects(mClusters[c], params.keepEvery).count;
    if (params.mode == BillboardWindMode::PerCluster)
        drawEachCluster(order, params);
    else
        drawClustersAtOnce(order, params.keepEvery);
    glBindVertexArray(0);
    glDepthMask(depthMask);
}

}  // namespace grass::render
