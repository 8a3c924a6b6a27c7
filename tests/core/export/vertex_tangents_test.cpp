// Tangents for normal-mapped exports (core/export/vertex_tangents.h): the direction u grows in,
// perpendicular to the normal, with the handedness glTF defines.
#include "export/vertex_tangents.h"

#include <gtest/gtest.h>

namespace grass::core {
namespace {

// A unit quad in the XZ plane, normal +Y, u along +X, v along `vDirection` (±Z).
void expectQuadTangents(float vDirection, float expectedW) {
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    const std::vector<glm::vec3> normals(4, glm::vec3(0, 1, 0));
    const float v = vDirection > 0.0f ? 1.0f : 0.0f;
    const std::vector<glm::vec2> uvs = {{0, 1 - v}, {1, 1 - v}, {1, v}, {0, v}};
    const std::vector<std::array<std::uint32_t, 3>> triangles = {{0, 2, 1}, {0, 3, 2}};
    for (const glm::vec4& t : vertexTangents(positions, normals, uvs, triangles)) {
        EXPECT_NEAR(glm::distance(glm::vec3(t), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
        EXPECT_EQ(t.w, expectedW);
        // bitangent = cross(normal, tangent) · w points where v grows.
        EXPECT_GT(glm::dot(glm::cross(glm::vec3(0, 1, 0), glm::vec3(t)) * t.w,
                           glm::vec3(0, 0, vDirection)), 0.99f);
    }
}

TEST(VertexTangents, FollowUAndTheHandednessOfV) {
    expectQuadTangents(+1.0f, -1.0f);  // cross(+Y, +X) = −Z, so v along +Z needs w = −1
    expectQuadTangents(-1.0f, +1.0f);
}

TEST(VertexTangents, AreMadePerpendicularToTheNormalAndSurviveDegenerateUvs) {
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.3f, 1.0f, 0.0f));
    const std::vector<glm::vec3> normals(3, tilted);
    const std::vector<std::array<std::uint32_t, 3>> triangles = {{0, 2, 1}};
    for (const glm::vec4& t : vertexTangents(positions, normals, {{0, 0}, {1, 0}, {0, 1}}, triangles)) {
        EXPECT_NEAR(glm::dot(glm::vec3(t), tilted), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-6f);
    }
    // Every vertex at one UV: no direction to follow, still a valid unit tangent.
    for (const glm::vec4& t : vertexTangents(positions, normals, {{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}, triangles)) {
        EXPECT_NEAR(glm::dot(glm::vec3(t), tilted), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-6f);
        EXPECT_EQ(t.w, 1.0f);
    }
}

}  // namespace
}  // namespace grass::core
