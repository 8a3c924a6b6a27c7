// glTF 2.0 import (issue 3): .gltf with external or base64 buffers and .glb, through tinygltf.
// Every triangle primitive of every mesh reachable from the scene's nodes is merged into one
// SurfaceMesh with node transforms applied (normals by the inverse-transpose); strips and fans
// become triangles; points and lines are skipped with a note; sparse accessors are honoured;
// normalized integer UVs are decoded. Missing normals are computed (area-weighted); missing
// UV0 is generated (generatePlanarUVs). Every accessor range is checked against its buffer,
// every index against the vertex count; URIs may not leave the file's folder; required
// extensions we cannot decode (e.g. KHR_draco_mesh_compression) are refused by name.
#pragma once

#include <filesystem>
#include <stop_token>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/surface_mesh.h"
#include "util/result.h"

namespace grass::core {

struct GltfImport {
    MovableSurfaceMesh mesh;
    bool hasNormals = false;         // every merged primitive carried NORMAL
    bool hasUv = false;              // every merged primitive carried TEXCOORD_0
    std::vector<std::string> notes;  // things skipped or generated, one line each
    // The point of the file (its units and axes) that the mesh's (0, 0, 0) stands for: zero,
    // unless a ground mesh far from the file's origin was moved next to it, or a collider with
    // it (GltfPlacement).
    glm::dvec3 origin{0.0};
    // For GltfPlacement::InGroundFrame: what was done with a mesh far from its file's origin
    // (also among `notes`); empty for a near one.
    std::string placementNote;
};

// A ground mesh (the surface the grass grows on) lying farther than this from its file's origin
// is moved next to grass's origin. 32-bit floats are 2 to 4 mm apart at 32 km, a fraction of a
// blade's width; a georeferenced terrain (UTM: 10^5 to 10^7 m) would have its blades snapped to
// a grid of centimetres to a metre, in stripes, and the depth buffer too coarse for the
// occlusion test. Game-world chunks within ±32 km stay where their file puts them.
inline constexpr double GROUND_RECENTRE_BEYOND_M = 32768.0;

enum class GltfPlacement {
    AsInFile,  // props and colliders: placed by their own transforms in the project
    // The project's ground mesh: when its bounds' centre lies beyond GROUND_RECENTRE_BEYOND_M of
    // the origin (judged in metres with `metresPerUnit`), every vertex is moved by minus the
    // centre rounded to whole file units, in double precision before it becomes a float, and
    // GltfImport::origin says by how much (with a note). Deterministic: the same file always
    // lands at the same place, so the project's cameras, colliders and wind stay put.
    GroundNearOrigin,
    // A collider in the ground's frame: a mesh whose bounds' centre lies beyond
    // GROUND_RECENTRE_BEYOND_M of its file's origin (in metres with `metresPerUnit`, the
    // ground's unit) shares the ground's georeferenced frame, and is moved by minus
    // `groundOrigin` (the ground's GltfImport::origin) in double precision, with a note; origin
    // then says by how much. Nearer meshes stay as in their file (AsInFile). With no ground
    // moved (groundOrigin zero) a far mesh stays too, noted as out of the field's reach.
    InGroundFrame,
};

// `stop`: a request ends the read before its next 65,536 triangles (or its next stage) with
// readStopped's error: the editor's Cancel, or its window closed, while a large mesh is read
// (an 8-million-triangle ground takes seconds, most of them building the mesh).
Result<GltfImport> loadGltf(const std::filesystem::path& file,
                            GltfPlacement placement = GltfPlacement::AsInFile,
                            double metresPerUnit = 1.0, glm::dvec3 groundOrigin = glm::dvec3(0.0),
                            std::stop_token stop = {});
// The error of a read ended by its stop token.
Error readStopped(const std::filesystem::path& file);

// The rule of GltfPlacement::GroundNearOrigin: zero, or the centre of the bounds [lo, hi] (file
// units) rounded to whole units when it lies beyond GROUND_RECENTRE_BEYOND_M.
glm::dvec3 groundOrigin(const glm::dvec3& lo, const glm::dvec3& hi, double metresPerUnit);

// Whether `path` names a glTF file by its extension (.gltf or .glb, any case): what a command
// given a mesh where a project goes takes as the mesh.
bool isGltfPath(const std::filesystem::path& path);

// The files a .gltf names by relative URI (buffers and images; data: URIs and anything outside
// its folder left out), as paths next to it. Empty for a .glb or a file that cannot be read.
std::vector<std::filesystem::path> gltfExternalFiles(const std::filesystem::path& file);

}  // namespace grass::core
