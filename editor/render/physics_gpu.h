// PhysicsGpu: the blade physics of core/physics/ run by shaders/physics.comp on a blade buffer
// (SPEC §1 layout, SSBO 0), one invocation per blade. World space, metres, seconds.
//
// It owns the per-blade state the CPU reference passes alongside the blades (η and the rest tips
// Iv2) and the per-step inputs. The shader runs every substep of a step in one dispatch; what
// depends on time only (the substep count and times, wind-source and collider path positions) is
// evaluated here with the CPU reference's own functions, per substep, exactly as stepBlade samples
// them: wind at t = timeS + i·τ, colliders at t + τ.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gl/buffer.h"
#include "gl/gl_ref.h"
#include "gl/program.h"
#include "physics/physics.h"
#include "physics/physics_step_inputs.h"
#include "util/result.h"

namespace grass::render {

// The std430 records of physics.comp (core/physics/physics_step_inputs.h).
using core::ColliderGroupGpu;
using core::WindSourceGpu;

class PhysicsGpu {
public:
    // Work groups of 32 invocations, or GRASS_COMPUTE_GROUP's (core/util/blade_pass_group.h).
    static Result<PhysicsGpu> load();
    // Work groups of `groupSize` (a multiple of 32 up to 256): the same steps whatever the size.
    static Result<PhysicsGpu> load(std::uint32_t groupSize);
    std::uint32_t groupSize() const { return mGroupSize; }

    // Sets the rest tips Iv2 from `blades` (core::restTips) and η = 0, as a CPU simulation starts.
    void reset(std::span<const core::Blade> blades);
    // The same with rest tips given (a grown field: core::restTipsAsGrown).
    void reset(std::span<const core::Blade> blades, std::span<const glm::vec3> restTips);
    // Blades [first, first + count) were re-grown (a brush stroke): their rest tips become the
    // new blades' own (restTipsAsGrown) and η 0. Preconditions: the range is inside the reset
    // count.
    void resetRange(std::size_t first, std::span<const core::Blade> blades);
    // The per-blade part of core::GravityLoad (snow load), one value per blade of the reset
    // count; empty frees it. Allocated only while a scene has a load.
    void setGravityLoad(std::span<const float> perBlade);
    // One step of params.dtS from timeS for bladeCount blades of bladeBuffer (the count given to
    // reset), with |gE| of blade i raised by gravityLoadScale · perBlade[i] (setGravityLoad).
    // Ends with a barrier, so later draws and buffer reads see the new blades.
    void step(gl::BufferRef bladeBuffer, std::size_t bladeCount, const core::PhysicsParams& params,
              const std::vector<core::WindSource>& wind,
              const std::vector<core::SphereCollider>& colliders, float timeS,
              float gravityLoadScale = 0.0f);
    // Rest detection (the editor's: app/live_scene.h): while `report` is a buffer, each step
    // sets its first uint to 1 when it moved a tip by more than `stillTipMove` of its blade's
    // height or let a crushed blade recover (η falling by more than half the step's pure decay).
    // No buffer (the default): nothing is marked.
    void setMotionReport(gl::BufferRef report, float stillTipMove);
    // The optional inputs that hold GPU buffers (issue 10: none without their feature): "wind",
    // "colliders", "snow_load".
    std::vector<std::string> allocated() const;
    // η of every blade (a GPU read-back, for tests and tools).
    std::vector<float> readEta() const;
    // Lowers every η above `etaMax` to it (read back, uploaded again when any changed); returns
    // how many blades it lowered.
    std::size_t capEta(float etaMax);

private:
    gl::Program mProgram;
    std::uint32_t mGroupSize = 32;
    std::size_t mBladeCount = 0;
    gl::Buffer mParams;
    gl::Buffer mEta;
    gl::Buffer mRestTips;
    gl::Buffer mWindSources;
    gl::Buffer mWindCentres;
    gl::Buffer mColliders;
    gl::Buffer mColliderGroups;
    gl::Buffer mSubsteps;
    gl::Buffer mGravityLoad;
    gl::BufferRef mMotionReport;
    float mStillTipMove = 0.0f;
};

}  // namespace grass::render
