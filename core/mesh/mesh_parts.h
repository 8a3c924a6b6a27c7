// Which glTF node, mesh and material each face of a surface came from (issue 27: rules that
// include or exclude grass by name). The table travels with the SurfaceMesh as an OpenMesh mesh
// property, so every copy of the mesh keeps it; a mesh without one (procedural surfaces) is a
// single unnamed part.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace grass::core {

struct MeshPart {
    // The node that placed the faces first, then the nodes above it up to the scene root. An
    // unnamed node is "node <index>", as is an unnamed mesh "mesh <index>" and an unnamed
    // material "material <index>"; faces without a material have "(no material)".
    std::vector<std::string> nodes;
    std::string mesh;
    std::string material;
    bool operator==(const MeshPart&) const = default;
};

struct MeshParts {
    std::vector<MeshPart> parts;
    std::vector<std::uint32_t> faceParts;  // per face index, into parts
    bool operator==(const MeshParts&) const = default;
};

// The table, or null when the mesh has none.
const MeshParts* meshPartsOf(const SurfaceMesh& mesh);
// Stores `parts` with the mesh. Precondition: faceParts has one entry per face, each < parts.
void setMeshParts(SurfaceMesh& mesh, MeshParts parts);

// Whether part `part` carries `name` as its node (or a node above it), its mesh or its material.
bool partHasName(const MeshPart& part, const std::string& name);

// Every distinct name a mesh's parts carry, sorted: what a rule's checklist offers.
std::vector<std::string> partNames(const SurfaceMesh& mesh);

}  // namespace grass::core
