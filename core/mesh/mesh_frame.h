// A glTF surface's units and up axis (issue 26): grass works in metres with +Y up; a file
// modelled in millimetres, inches or with +Z up (CAD tools, Blender's own axes before export) is
// scaled and turned once it is loaded, so every distance of the project is in metres.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "mesh/surface_mesh.h"
#include "util/result.h"

namespace grass::core {

enum class UpAxis { Y, Z };

struct MeshUnit {
    std::string_view name;
    float metres;
};

// The named units; any other positive factor is written as a number.
inline constexpr MeshUnit MESH_UNITS[] = {
    {"mm", 0.001f}, {"cm", 0.01f}, {"m", 1.0f}, {"in", 0.0254f}, {"ft", 0.3048f}};

// Metres per file unit, at least this small and at most this large.
inline constexpr float MIN_METRES_PER_UNIT = 1e-6f;
inline constexpr float MAX_METRES_PER_UNIT = 1e6f;

// "mm", "cm", "m", "in", "ft" or a number of metres per unit in [1e-6, 1e6]. The error (no path)
// lists what is accepted.
Result<float> parseMeshUnit(std::string_view text);
// The unit's name when it is one of MESH_UNITS, else the number.
std::string meshUnitText(float metresPerUnit);

// "+Y" or "+Z" (also "y", "z").
Result<UpAxis> parseUpAxis(std::string_view text);
std::string_view upAxisText(UpAxis up);

// Scales every point by `metresPerUnit` and turns +Z up into +Y up (x, y, z) → (x, z, −y), a
// rotation, so windings and normals stay right.
void applyMeshFrame(SurfaceMesh& mesh, float metresPerUnit, UpAxis up);

}  // namespace grass::core
