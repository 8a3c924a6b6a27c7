// The mesh and parameters the packing-cache fuzz target packs, shared with make_seeds.cpp so
// that the seed cache carries the key the target computes (a cache with another key is
// repacked without being parsed further). Small, so that a repack costs about a millisecond.
#pragma once

#include <filesystem>
#include <string_view>

#include "collider/packing_cache.h"
#include "mesh/procedural.h"

namespace grass::fuzz {

// Only the bytes enter the cache key; the mesh itself is a procedural sphere.
constexpr std::string_view PACKING_MESH_BYTES = "grass fuzz collider mesh\n";

inline core::SurfaceMesh packingMesh() {
    core::ProceduralMeshParams params;
    params.shape = core::ProceduralShape::Sphere;
    params.size = 1.0f;
    params.resolution = 6;
    return core::makeProceduralMesh(params);
}

inline core::SpherePackingParams packingParams() {
    core::SpherePackingParams params;
    params.sphereCount = 6;
    params.resolution = core::MIN_PACKING_RESOLUTION;
    return params;
}

}  // namespace grass::fuzz
