// The billboards' vertex animation on the GPU against its C++ twin (issue 30 item 3):
// tests/gl/shaders/billboard_motion_twins.comp runs billboardVertexMotion of
// shaders/include/billboard_wind.glsl (what billboard.vert calls) on the star vertices of a small
// field under a moving helicopter, a gusty wind and a vortex, in every animation mode, and
// core::billboardVertexMotion must give the same positions and normals. On the GPU's own output
// the modes must differ where GPU Gems ch. 7 says: per object, the six tops of a star move alike;
// per vertex, each by its own position; roots never move.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "billboard/billboard_motion.h"
#include "gl/buffer.h"
#include "gl/program.h"
#include "gl_context_fixture.h"
#include "mesh/procedural.h"
#include "physics/physics_step_inputs.h"
#include "render/billboard_gpu.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

using BillboardMotionTwins = GlTest;
using core::BillboardWindMode;

constexpr std::uint32_t WORK_GROUP = 64;  // local_size_x of billboard_motion_twins.comp
constexpr float STIFFNESS = 55.0f;
constexpr float TIME_S = 2.6f;

// About 60 objects on a 3 m plane, one cluster.
std::vector<core::GrassObject> fieldObjects() {
    core::ProceduralMeshParams plane;
    plane.shape = core::ProceduralShape::Plane;
    plane.size = 3.0f;
    plane.resolution = 4;
    core::StarBillboardParams params;
    params.density = 7.0f;
    params.heightRangeM = {0.2f, 0.5f};
    params.clusterSizeM = 0.0f;
    return core::placeGrassObjects(core::makeProceduralMesh(plane), params, 5);
}

// The field's stars as the CPU lays out their vertices (the GPU reads their instances).
core::StarMesh fieldStars() {
    return core::buildStarVertices(fieldObjects());
}

std::vector<core::WindSource> sceneWind() {
    core::WindSource helicopter;
    helicopter.kind = core::WindKind::Point;
    helicopter.strength = 3.0f;
    helicopter.radiusM = 4.0f;
    helicopter.coreRadiusM = 0.5f;
    helicopter.path = {{0.0f, {-1.0f, 1.5f, 0.0f}}, {5.0f, {1.0f, 1.5f, 0.5f}}};
    core::WindSource breeze;
    breeze.direction = {1.0f, 0.0f, 0.6f};
    breeze.strength = 1.2f;
    breeze.wavelengthM = 4.0f;
    breeze.gust = 0.6f;
    core::WindSource vortex;
    vortex.kind = core::WindKind::Vortex;
    vortex.position = {0.5f, 0.0f, -0.5f};
    vortex.strength = 2.0f;
    vortex.radiusM = 2.5f;
    return {helicopter, breeze, vortex};
}

core::BillboardWind sway() {
    core::BillboardWind wind;
    wind.directionXZ = {0.8f, 0.6f};
    wind.amplitudeM = 0.05f;
    wind.frequencyHz = 0.7f;
    return wind;
}

struct Motion {
    glm::vec4 position;
    glm::vec4 normal;
    glm::vec4 rest;      // the vertex as starVertex made it (xyz), sway
    glm::vec4 uvHeight;  // uv, object height, tint's green
};

// The shader's motion of every vertex in `mode`, the scene wind bound as BillboardField binds it.
std::vector<Motion> runShader(const gl::Program& program, const core::StarMesh& stars,
                              BillboardWindMode mode, glm::vec3 clusterCentre) {
    const std::vector<core::WindSource> wind = sceneWind();
    const core::WindSourcesAt packed = core::packWindSourcesAt(wind, TIME_S);
    const gl::Buffer sourceBuffer = gl::Buffer::fromVector(packed.sources, "twin wind sources");
    const gl::Buffer centreBuffer = gl::Buffer::fromVector(packed.centres, "twin wind centres");
    const gl::Buffer input =
        gl::Buffer::fromVector(core::buildStarInstances(fieldObjects()).stars, "twin stars");
    // NaN first: a vertex the shader never wrote cannot pass by accident.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const gl::Buffer output = gl::Buffer::fromVector(
        std::vector<Motion>(stars.vertices.size(),
                            Motion{glm::vec4(nan), glm::vec4(nan), glm::vec4(nan), glm::vec4(nan)}),
        "twin motions");
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::BILLBOARD_WIND_SOURCE_BINDING,
                     sourceBuffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::BILLBOARD_WIND_CENTRE_BINDING,
                     centreBuffer.id());
    const core::BillboardWind book = sway();
    program.use();
    program.set("uVertexCount", static_cast<unsigned>(stars.vertices.size()));
    program.set("uWindMode", static_cast<int>(mode));
    program.set("uClusterSway", core::billboardWindOffset(clusterCentre, TIME_S, book));
    program.set("uClusterWind", core::windAt(wind, clusterCentre, TIME_S));
    program.set("uTime", TIME_S);
    program.set("uWindDirection", book.directionXZ);
    program.set("uWindAmplitude", book.amplitudeM);
    program.set("uWindFrequency", book.frequencyHz);
    program.set("uStiffness", STIFFNESS);
    program.set("uWindSourceCount", static_cast<int>(wind.size()));
    glDispatchCompute((static_cast<GLuint>(stars.vertices.size()) + WORK_GROUP - 1) / WORK_GROUP,
                      1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<Motion> motions(stars.vertices.size());
    const std::vector<std::byte> bytes = output.read(0, output.size());
    std::memcpy(motions.data(), bytes.data(), bytes.size());
    return motions;
}

gl::Program loadProgram() {
    auto program = gl::Program::load(
        {{GL_COMPUTE_SHADER,
          (sourceDir() / "tests/gl/shaders/billboard_motion_twins.comp").string()}},
        "billboard motion twins");
    EXPECT_TRUE(program.ok()) << (program.ok() ? "" : program.error().str());
    return program.ok() ? std::move(*program) : gl::Program{};
}

// Positions are metres within ~2 m of the origin and the wind's sines take phases of a few
// radians: llvmpipe's sin/cos and the driver's fused multiply-adds stay within ~1e-6 m there; a
// wrong constant or term moves tops by millimetres or more.
constexpr float POSITION_TOLERANCE_M = 2.0e-5f;
constexpr float NORMAL_TOLERANCE = 1.0e-4f;

// billboard.vert draws a star from its 64-byte instance: every vertex it makes is the one
// core::starVertex makes (and buildStarVertices lays out), position, uv, sway, height and tint.
TEST_F(BillboardMotionTwins, ShaderMakesEveryStarVertexAsTheCpuTwin) {
    const gl::Program program = loadProgram();
    ASSERT_NE(program.id(), 0u);
    const core::StarMesh stars = fieldStars();
    const std::vector<Motion> gpu =
        runShader(program, stars, BillboardWindMode::PerObject, stars.clusters[0].centre);
    float worst = 0.0f;
    for (std::size_t i = 0; i < stars.vertices.size(); ++i) {
        const core::StarVertex& v = stars.vertices[i];
        worst = std::max(worst, glm::length(glm::vec3(gpu[i].rest) - v.position));
        ASSERT_EQ(gpu[i].rest.w, v.sway) << "vertex " << i;
        ASSERT_EQ(glm::vec2(gpu[i].uvHeight), v.uv) << "vertex " << i;
        ASSERT_EQ(gpu[i].uvHeight.z, v.objectHeight) << "vertex " << i;
        ASSERT_EQ(gpu[i].uvHeight.w, v.tint.g) << "vertex " << i;
    }
    RecordProperty("worst_rest_position_m", std::to_string(worst));
    // The same products and sums; only the driver's fused multiply-adds may round otherwise.
    EXPECT_LT(worst, 1.0e-6f);
}

TEST_F(BillboardMotionTwins, ShaderMovesEveryVertexAsTheCpuTwinInEveryMode) {
    const gl::Program program = loadProgram();
    ASSERT_NE(program.id(), 0u);
    const core::StarMesh stars = fieldStars();
    ASSERT_EQ(stars.clusters.size(), 1u);
    ASSERT_GT(stars.objectCount(), 40u);
    const glm::vec3 clusterCentre = stars.clusters[0].centre;
    const std::vector<core::WindSource> wind = sceneWind();
    const core::BillboardSceneWind scene{wind, STIFFNESS};
    for (const BillboardWindMode mode : {BillboardWindMode::PerCluster,
                                         BillboardWindMode::PerVertex,
                                         BillboardWindMode::PerObject}) {
        const std::vector<Motion> gpu = runShader(program, stars, mode, clusterCentre);
        float worstPosition = 0.0f, worstNormal = 0.0f, largestMove = 0.0f;
        for (std::size_t i = 0; i < stars.vertices.size(); ++i) {
            const core::StarVertex& v = stars.vertices[i];
            const core::StarVertexMotion cpu =
                core::billboardVertexMotion(v, mode, clusterCentre, TIME_S, sway(), scene);
            worstPosition =
                std::max(worstPosition, glm::length(glm::vec3(gpu[i].position) - cpu.position));
            worstNormal =
                std::max(worstNormal, glm::length(glm::vec3(gpu[i].normal) - cpu.normal));
            largestMove = std::max(largestMove, glm::length(cpu.position - v.position));
        }
        RecordProperty("worst_position_m_mode_" + std::to_string(static_cast<int>(mode)),
                       std::to_string(worstPosition));
        EXPECT_LT(worstPosition, POSITION_TOLERANCE_M) << "mode " << static_cast<int>(mode);
        EXPECT_LT(worstNormal, NORMAL_TOLERANCE) << "mode " << static_cast<int>(mode);
        EXPECT_GT(largestMove, 0.02f) << "the wind must move the tops for this to mean anything";
    }
}

TEST_F(BillboardMotionTwins, PerObjectMovesAStarsTopsAlikePerVertexEachByItsOwn) {
    const gl::Program program = loadProgram();
    ASSERT_NE(program.id(), 0u);
    const core::StarMesh stars = fieldStars();
    const glm::vec3 clusterCentre = stars.clusters[0].centre;
    std::map<BillboardWindMode, float> spread;
    for (const BillboardWindMode mode :
         {BillboardWindMode::PerVertex, BillboardWindMode::PerObject}) {
        const std::vector<Motion> gpu = runShader(program, stars, mode, clusterCentre);
        float largest = 0.0f;
        for (std::size_t o = 0; o < stars.objectCount(); ++o) {
            const std::size_t first = o * core::STAR_VERTICES_PER_OBJECT;
            std::vector<glm::vec3> tops;
            for (std::size_t k = 0; k < core::STAR_VERTICES_PER_OBJECT; ++k) {
                const core::StarVertex& v = stars.vertices[first + k];
                const glm::vec3 moved = glm::vec3(gpu[first + k].position) - v.position;
                if (v.sway > 0.0f)
                    tops.push_back(moved);
                else
                    EXPECT_EQ(moved, glm::vec3(0.0f)) << "a root moved";
            }
            for (const glm::vec3& top : tops)
                largest = std::max(largest, glm::length(top - tops.front()));
        }
        spread[mode] = largest;
    }
    RecordProperty("per_vertex_spread_m", std::to_string(spread[BillboardWindMode::PerVertex]));
    RecordProperty("per_object_spread_m", std::to_string(spread[BillboardWindMode::PerObject]));
    // Tops of one star are up to ~0.6 m apart: per vertex their phases and winds differ by
    // millimetres at least; per object they are computed once, so only rounding may differ.
    EXPECT_GT(spread[BillboardWindMode::PerVertex], 2.0e-3f);
    EXPECT_LT(spread[BillboardWindMode::PerObject], 1.0e-6f);
}

}  // namespace
}  // namespace grass::test
