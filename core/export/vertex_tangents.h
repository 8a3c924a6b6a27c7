// Per-vertex tangents for a normal-mapped export (glTF 2.0 §3.7.2.1 TANGENT): xyz the direction
// in which u grows, made perpendicular to the vertex normal, w = ±1 the handedness such that
// bitangent = cross(normal, xyz) · w points where v grows. Per-triangle UV derivatives summed
// over the triangles around a vertex (weighted by area, as the triangle's size enters its
// derivative), then orthonormalized (Lengyel's method). A vertex whose triangles have no UV
// area gets any unit direction perpendicular to its normal, w = 1.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace grass::core {

std::vector<glm::vec4> vertexTangents(const std::vector<glm::vec3>& positions,
                                      const std::vector<glm::vec3>& normals,
                                      const std::vector<glm::vec2>& uvs,
                                      const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace grass::core
