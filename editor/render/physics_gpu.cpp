#include "render/physics_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "util/assert.h"
#include "util/blade_pass_group.h"
#include "util/dispatch_grid.h"

namespace grass::render {
namespace {

// Immutable storage cannot grow: a new buffer when the size changes, else an update in place.
template <class T>
void upload(gl::Buffer& buffer, const std::vector<T>& values, std::string_view label) {
    const auto bytes = std::as_bytes(std::span<const T>(values));
    if (buffer.id() == 0 || buffer.size() != bytes.size())
        buffer = gl::Buffer(bytes, label);
    else if (!bytes.empty())
        buffer.update(bytes);
}

}  // namespace

Result<PhysicsGpu> PhysicsGpu::load() {
    const Result<std::uint32_t> groupSize = core::bladePassGroupSizeFromEnvironment();
    if (!groupSize)
        return groupSize.error();
    return load(*groupSize);
}

Result<PhysicsGpu> PhysicsGpu::load(std::uint32_t groupSize) {
    auto program = gl::Program::load({{GL_COMPUTE_SHADER, "physics.comp"}}, "blade physics",
                                     {core::physicsGroupDefine(groupSize)});
    if (!program)
        return program.error();
    PhysicsGpu physics;
    physics.mGroupSize = groupSize;
    physics.mProgram = std::move(*program);
    return physics;
}

void PhysicsGpu::reset(std::span<const core::Blade> blades) {
    reset(blades, core::restTips(blades));
}

void PhysicsGpu::reset(std::span<const core::Blade> blades, std::span<const glm::vec3> restTips) {
    GRASS_ASSERT(restTips.size() == blades.size());
    mBladeCount = blades.size();
    std::vector<glm::vec4> tips;
    tips.reserve(blades.size());
    for (const glm::vec3 tip : restTips)
        tips.emplace_back(tip, 0.0f);
    upload(mRestTips, tips, "physics rest tips");
    upload(mEta, std::vector<float>(blades.size(), 0.0f), "physics eta");
}

void PhysicsGpu::resetRange(std::size_t first, std::span<const core::Blade> blades) {
    GRASS_ASSERT(first + blades.size() <= mBladeCount);
    if (blades.empty())
        return;
    std::vector<glm::vec4> tips;
    tips.reserve(blades.size());
    for (const glm::vec3 tip : core::restTipsAsGrown(blades))
        tips.emplace_back(tip, 0.0f);
    mRestTips.update(std::as_bytes(std::span<const glm::vec4>(tips)), first * sizeof(glm::vec4));
    const std::vector<float> eta(blades.size(), 0.0f);
    mEta.update(std::as_bytes(std::span<const float>(eta)), first * sizeof(float));
}

void PhysicsGpu::setGravityLoad(std::span<const float> perBlade) {
    GRASS_ASSERT(perBlade.empty() || perBlade.size() == mBladeCount);
    mGravityLoad = perBlade.empty() ? gl::Buffer()
                                    : gl::Buffer(std::as_bytes(perBlade), "physics gravity load");
}

void PhysicsGpu::step(gl::BufferRef bladeBuffer, std::size_t bladeCount,
                      const core::PhysicsParams& params, const std::vector<core::WindSource>& wind,
                      const std::vector<core::SphereCollider>& colliders, float timeS,
                      float gravityLoadScale) {
    GRASS_ASSERT(bladeCount == mBladeCount);
    const core::PhysicsStepInputs inputs = core::physicsStepInputs(params, wind, colliders, timeS);
    const std::uint32_t n = inputs.substepCount;
    if (bladeCount == 0 || n == 0)
        return;
    upload(mParams, std::vector<core::PhysicsParams>{params}, "physics params");
    upload(mSubsteps, inputs.substeps, "physics substeps");
    // A scene without wind or colliders holds no buffers for them (the shader reads none).
    if (!wind.empty()) {
        upload(mWindSources, inputs.windSources, "physics wind sources");
        upload(mWindCentres, inputs.windCentres, "physics wind centres");
    }
    if (!colliders.empty()) {
        upload(mColliders, inputs.colliderSpheres, "physics colliders");
        upload(mColliderGroups, inputs.colliderGroups, "physics collider groups");
    }

    mProgram.use();
    mProgram.set("bladeCount", static_cast<unsigned>(bladeCount));
    mProgram.set("substepCount", static_cast<unsigned>(n));
    mProgram.set("windCount", static_cast<unsigned>(wind.size()));
    mProgram.set("colliderCount", static_cast<unsigned>(colliders.size()));
    const bool loaded = mGravityLoad.id() != 0 && gravityLoadScale > 0.0f;
    mProgram.set("gravityLoadScale", loaded ? gravityLoadScale : 0.0f);
    if (loaded)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, mGravityLoad.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bladeBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, mParams.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, mEta.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, mRestTips.id());
    if (!wind.empty()) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, mWindSources.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, mWindCentres.id());
    }
    if (!colliders.empty()) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, mColliders.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, mColliderGroups.id());
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, mSubsteps.id());
    const bool reporting = static_cast<bool>(mMotionReport);
    mProgram.set("stillTipMove", reporting ? mStillTipMove : 0.0f);
    mProgram.set("etaDecayStep",
                 std::isfinite(params.etaDecayPerS) ? params.etaDecayPerS * params.dtS : 0.0f);
    if (reporting)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 10, mMotionReport.id());
    const core::DispatchGrid grid = core::dispatchGrid(bladeCount, mGroupSize);
    glDispatchCompute(grid.x, grid.y, 1);
    // Blades feed the cull and the draws (texel fetches) and read-backs; η feeds the next step
    // (SSBO reads).
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT);
}

void PhysicsGpu::setMotionReport(gl::BufferRef report, float stillTipMove) {
    mMotionReport = report;
    mStillTipMove = stillTipMove;
}

std::vector<std::string> PhysicsGpu::allocated() const {
    std::vector<std::string> out;
    if (mWindSources.id() != 0)
        out.push_back("wind");
    if (mColliders.id() != 0)
        out.push_back("colliders");
    if (mGravityLoad.id() != 0)
        out.push_back("snow_load");
    return out;
}

std::vector<float> PhysicsGpu::readEta() const {
    std::vector<float> out(mBladeCount);
    if (mBladeCount == 0)
        return out;
    const std::vector<std::byte> bytes = mEta.read(0, mBladeCount * sizeof(float));
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

std::size_t PhysicsGpu::capEta(float etaMax) {
    std::vector<float> eta = readEta();
    const std::size_t lowered = core::capEta(eta, etaMax);
    if (lowered > 0)
        mEta.update(std::as_bytes(std::span<const float>(eta)));
    return lowered;
}

}  // namespace grass::render
