// Procedural meshes available by name in project files (issue 3): plane, hills (noise terrain),
// sphere, torus, Möbius strip. All are centred at the origin with +Y up, in metres, with
// normals and UVs in [0, 1]².
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "mesh/surface_mesh.h"
#include "util/result.h"

namespace grass::core {

enum class ProceduralShape { Plane, Hills, Sphere, Torus, Moebius };

struct ProceduralMeshParams {
    ProceduralShape shape = ProceduralShape::Plane;
    float size = 10.0f;           // plane/hills: side length; sphere: radius; torus: major radius;
                                  // Möbius: radius of the centre circle
    float minorSize = 1.0f;       // torus: tube radius; Möbius: half width of the strip
    float hillHeight = 1.0f;      // hills: peak-to-trough amplitude
    float hillScale = 4.0f;       // hills: feature size (wavelength of the lowest octave)
    int resolution = 64;          // quads along each parametric direction
    std::uint64_t noiseSeed = 7;  // hills: the noise seed
    bool operator==(const ProceduralMeshParams&) const = default;
};

// "plane", "hills", "sphere", "torus", "moebius"; an error lists the valid names.
Result<ProceduralShape> parseProceduralShape(std::string_view name);
std::string_view proceduralShapeName(ProceduralShape shape);
std::vector<std::string_view> proceduralShapeNames();

MovableSurfaceMesh makeProceduralMesh(const ProceduralMeshParams& params);

// Height of the hills terrain at (x, z), so tests and cameras can use the same function.
float hillsHeight(const ProceduralMeshParams& params, float x, float z);

}  // namespace grass::core
