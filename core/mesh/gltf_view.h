// What a stock glTF viewer draws of a file, as plain triangles in world space: every triangle
// primitive its scene places (node hierarchy, EXT_mesh_gpu_instancing's TRANSLATION, ROTATION
// and SCALE), coloured as the core spec and the widely used per-instance convention say:
// material baseColorFactor × vertex COLOR_0 × the instance's `_COLOR_0`. Textures, lights and
// extensions that only change appearance are not read. The check of docs/export.md: an export
// drawn this way must look like `grass render` of its project (tests/gl/export_stock_gl_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::core {

struct GltfView {
    std::vector<glm::vec3> positions;  // world space
    std::vector<glm::vec3> normals;    // unit; flat (the triangle's) where the file has none
    std::vector<glm::vec4> colors;     // linear RGBA, the product above
    std::vector<std::uint32_t> indices;  // triangles, the file's winding (mirrors reversed)
    std::size_t placedMeshes = 0;        // nodes and GPU instances that place a mesh
    std::vector<std::string> notes;
};

// Refuses (naming the file) what the geometry import refuses, and a scene that expands to more
// than `maxVertices` vertices.
Result<GltfView> loadGltfView(const std::filesystem::path& file, std::size_t maxVertices);

}  // namespace grass::core
