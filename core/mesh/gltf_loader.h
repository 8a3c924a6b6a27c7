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
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "util/result.h"

namespace grass::core {

struct GltfImport {
    SurfaceMesh mesh;
    bool hasNormals = false;         // every merged primitive carried NORMAL
    bool hasUv = false;              // every merged primitive carried TEXCOORD_0
    std::vector<std::string> notes;  // things skipped or generated, one line each
};

Result<GltfImport> loadGltf(const std::filesystem::path& file);

// The files a .gltf names by relative URI (buffers and images; data: URIs and anything outside
// its folder left out), as paths next to it. Empty for a .glb or a file that cannot be read.
std::vector<std::filesystem::path> gltfExternalFiles(const std::filesystem::path& file);

}  // namespace grass::core
