#include "render/stem_set_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "gl/scoped_capability.h"
#include "util/assert.h"

namespace grass::render {

namespace {

using gl::ScopedCapability;

int clampedLevels(int levels) {
    return std::clamp(levels, 1, core::MAX_STEM_LEVELS);
}

int clampedSamples(int samplesPerLevel) {
    return std::clamp(samplesPerLevel, 2, core::STEM_SAMPLES_PER_LEVEL);
}

int samplesPerStem(int levels, int samplesPerLevel) {
    return clampedSamples(samplesPerLevel) * clampedLevels(levels);
}

// Two triangles per pair of consecutive samples of each stem; vertex numbers as in the header.
std::vector<std::uint32_t> templateIndices(int levels, int samplesPerLevel) {
    const int samples = samplesPerStem(levels, samplesPerLevel);
    std::vector<std::uint32_t> indices;
    indices.reserve(static_cast<std::size_t>(stemSetIndexCount(levels, samplesPerLevel)));
    for (int k = 0; k < core::STEMS_PER_SET; ++k)
        for (int i = 0; i + 1 < samples; ++i) {
            const auto left = static_cast<std::uint32_t>(2 * (k * samples + i));
            const std::uint32_t right = left + 1, nextLeft = left + 2, nextRight = left + 3;
            indices.insert(indices.end(), {left, right, nextLeft, nextLeft, right, nextRight});
        }
    return indices;
}

// The index buffer holds, for each LOD's samples per level in core::STEM_SET_LOD_SAMPLES'
// order, the lists of levels 1..4. Byte offset of one list.
std::size_t indexOffsetBytes(int levels, int samplesPerLevel) {
    std::size_t before = 0;
    for (const int samples : core::STEM_SET_LOD_SAMPLES) {
        for (int l = 1; l <= core::MAX_STEM_LEVELS; ++l) {
            if (samples == clampedSamples(samplesPerLevel) && l == clampedLevels(levels))
                return before * sizeof(std::uint32_t);
            before += static_cast<std::size_t>(stemSetIndexCount(l, samples));
        }
    }
    GRASS_ASSERT(false && "samples per level not among core::STEM_SET_LOD_SAMPLES");
    return 0;
}

}  // namespace

int stemSetVertexCount(int levels, int samplesPerLevel) {
    return core::STEMS_PER_SET * 2 * samplesPerStem(levels, samplesPerLevel);
}

int stemSetIndexCount(int levels, int samplesPerLevel) {
    return core::STEMS_PER_SET * (samplesPerStem(levels, samplesPerLevel) - 1) * 6;
}

glm::mat3 stemSetFrame(glm::vec3 up, float yawRad) {
    const float length = glm::length(up);
    const glm::vec3 n = length > 1e-6f ? up / length : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 ref =
        std::abs(n.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t = glm::normalize(glm::cross(n, ref));
    const glm::vec3 b = glm::cross(t, n);
    // Yaw turns model x towards −z and model z towards +x (a right-handed turn about y), then
    // the tangent frame carries the turned axes onto the surface.
    const float c = std::cos(yawRad), s = std::sin(yawRad);
    return glm::mat3(c * t - s * b, n, s * t + c * b);
}

glm::vec3 stemSetWorldPosition(const core::StemSetInstance& instance, glm::vec3 modelPoint) {
    const glm::mat3 frame = stemSetFrame(glm::vec3(instance.upYaw), instance.upYaw.w);
    return glm::vec3(instance.rootMetresPerUnit) +
           instance.rootMetresPerUnit.w * (frame * modelPoint);
}

core::StemSetParams stemSetParams(const core::StemSetInstance& instance, int levels) {
    core::StemSetParams params;
    params.alpha = instance.alphaBetaThetaB.x;
    params.beta = instance.alphaBetaThetaB.y;
    params.theta = instance.alphaBetaThetaB.z;
    params.levels = clampedLevels(levels);
    params.spreadX = instance.halfWidthSpread.y;
    params.spreadZ = instance.halfWidthSpread.z;
    return params;
}

Result<gl::Program> loadStemSetProgram(const std::vector<std::string>& defines) {
    return gl::Program::load(
        {{GL_VERTEX_SHADER, "stem_set.vert"}, {GL_FRAGMENT_SHADER, "stem_set.frag"}}, "stem sets",
        defines);
}

void setStemSetColours(const gl::Program& program, const StemSetColours& colours) {
    program.set("uHealthyRoot", colours.healthyRoot);
    program.set("uHealthyTip", colours.healthyTip);
    program.set("uPoorRoot", colours.poorRoot);
    program.set("uPoorTip", colours.poorTip);
}

StemSetField::StemSetField(const std::vector<core::StemSetInstance>& instances,
                           const std::string& label)
    : mInstanceCount(instances.size()) {
    // Zero-sized buffers cannot be bound: an empty field keeps one unused instance.
    mInstances = instances.empty()
                     ? gl::Buffer::fromVector(std::vector<core::StemSetInstance>(1), label)
                     : gl::Buffer::fromVector(instances, label);
    mVisible = gl::Buffer::fromVector(std::vector<std::uint32_t>(std::max<std::size_t>(mInstanceCount, 1)),
                                      label + " visible");
    std::vector<std::uint32_t> indices;
    for (const int samples : core::STEM_SET_LOD_SAMPLES)
        for (int levels = 1; levels <= core::MAX_STEM_LEVELS; ++levels) {
            const std::vector<std::uint32_t> list = templateIndices(levels, samples);
            indices.insert(indices.end(), list.begin(), list.end());
        }
    mIndices = gl::Buffer::fromVector(indices, label + " indices", 0);
    mVertexArray = gl::VertexArray(label);
    mVertexArray.setElementBuffer(mIndices);
}

void StemSetField::update(std::size_t first, std::span<const core::StemSetInstance> instances) {
    if (first >= mInstanceCount)
        return;
    const std::size_t count = std::min(instances.size(), mInstanceCount - first);
    mInstances.update(std::as_bytes(instances.first(count)), first * sizeof(core::StemSetInstance));
}

void StemSetField::draw(const gl::Program& program, int levels) const {
    drawList(program, levels, core::STEM_SAMPLES_PER_LEVEL, false, 0, mInstanceCount);
}

void StemSetField::draw(const gl::Program& program, int levels,
                        const core::StemSetCullResult& culled) {
    mVisibleUpload.clear();
    for (const auto& list : culled.visible)
        mVisibleUpload.insert(mVisibleUpload.end(), list.begin(), list.end());
    if (mVisibleUpload.empty() || mVisibleUpload.size() > mInstanceCount)
        return;  // nothing to draw, or lists of another field
    mVisible.update(std::as_bytes(std::span<const std::uint32_t>(mVisibleUpload)));
    std::uint32_t first = 0;
    for (std::size_t lod = 0; lod < culled.visible.size(); ++lod) {
        const std::size_t count = culled.visible[lod].size();
        drawList(program, levels, core::STEM_SET_LOD_SAMPLES[lod], true, first, count);
        first += static_cast<std::uint32_t>(count);
    }
}

void StemSetField::drawList(const gl::Program& program, int levels, int samplesPerLevel,
                            bool useVisible, std::uint32_t first, std::size_t count) const {
    if (count == 0)
        return;
    const int drawnLevels = clampedLevels(levels);
    program.set("uLevels", drawnLevels);
    program.set("uSamplesPerLevel", clampedSamples(samplesPerLevel));
    program.set("uUseVisible", useVisible ? 1 : 0);
    program.set("uVisibleFirst", first);
    const ScopedCapability depthTest(GL_DEPTH_TEST, true);
    const ScopedCapability cullFace(GL_CULL_FACE, false);
    mVertexArray.bind();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, STEM_SET_BINDING, mInstances.id());
    // Bound even when unused: the shader's branch may read it either way on some drivers.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, STEM_SET_VISIBLE_BINDING, mVisible.id());
    glDrawElementsInstanced(GL_TRIANGLES, stemSetIndexCount(drawnLevels, samplesPerLevel),
                            GL_UNSIGNED_INT,
                            reinterpret_cast<const void*>(indexOffsetBytes(drawnLevels, samplesPerLevel)),
                            static_cast<GLsizei>(count));
    glBindVertexArray(0);
}

}  // namespace grass::render
