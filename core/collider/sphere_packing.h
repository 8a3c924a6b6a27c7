// Sphere packing (SPEC §5): the solid a triangle mesh encloses, approximated by at most N
// spheres that lie inside it and cover as much of it as the greedy choice can. Blades collide
// with spheres (physics/physics.h SphereCollider), so any glTF mesh can become a collider.
// Spheres are in the mesh's own coordinates and units (metres for glTF); the caller applies the
// node transform. The method and the measured numbers are in docs/sphere-packing.md.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "mesh/surface_mesh.h"
#include "util/result.h"

namespace grass::core {

constexpr std::uint32_t MAX_PACKED_SPHERES = 4096;
constexpr std::uint32_t MIN_PACKING_RESOLUTION = 8;
constexpr std::uint32_t MAX_PACKING_RESOLUTION = 256;

struct PackedSphere {
    glm::vec3 centre{0.0f};
    float radiusM = 0.0f;
    bool operator==(const PackedSphere&) const = default;
};

struct SpherePackingParams {
    std::uint32_t sphereCount = 32;  // at most this many spheres, in [1, MAX_PACKED_SPHERES]
    // Voxels along the longest side of the mesh's bounding box, in [MIN_PACKING_RESOLUTION,
    // MAX_PACKING_RESOLUTION]. Sphere centres lie on voxel centres.
    std::uint32_t resolution = 64;
    bool operator==(const SpherePackingParams&) const = default;
};

struct SpherePacking {
    // In the order the greedy chose them, largest gain first: the first k spheres are the
    // packing for sphereCount = k. Fewer than sphereCount when no further sphere would cover
    // another inside voxel.
    std::vector<PackedSphere> spheres;
    // Share of the union-of-spheres volume that lies inside the mesh (1 = fully inside), and
    // share of the mesh's inside volume the union covers; both estimated from `samples` seeded
    // uniform points in the bounding box (standard error: docs/sphere-packing.md).
    float insideShare = 0.0f;
    float coverage = 0.0f;
    std::uint32_t samples = 0;
    float voxelSize = 0.0f;  // edge of one voxel, in mesh units: the packing's resolution
    bool operator==(const SpherePacking&) const = default;
};

// Deterministic: the same mesh and params give a bit-identical packing. Errors (Error::path
// left empty for the caller): no triangles, a non-finite position, sphereCount or resolution
// out of range, no enclosed volume (a plane or an open sheet).
Result<SpherePacking> packSpheres(const SurfaceMesh& mesh, const SpherePackingParams& params);

}  // namespace grass::core
