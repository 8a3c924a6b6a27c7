// Turning a glTF 2.0 file on disk into a tinygltf::Model for geometry import: picks .glb or
// .gltf by the magic bytes, checks the GLB container, the JSON, asset.version and
// extensionsRequired, and every buffer's URI (base64 data: URIs, or files that must stay in the
// glTF file's folder) before tinygltf sees the file. tinygltf then reads only the buffer files
// approved here (through our FsCallbacks) and decodes no image. Internal to the glTF loader.
#pragma once

#include <tiny_gltf.h>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.h"

namespace grass::core::gltf {

struct GltfSource {
    tinygltf::Model model;  // images, textures, materials, animations, skins, cameras left out
    std::vector<std::string> notes;  // things ignored, one line each
    // Each material's pbrMetallicRoughness.baseColorFactor (linear RGBA; white where absent or
    // outside the spec's 0..1), by material index: with the names, what the geometry keeps of them.
    std::vector<glm::vec4> baseColors;
    // Each material's name ("" when unnamed), for the placement rules (mesh_parts.h).
    std::vector<std::string> materialNames;
};

// Errors name `file` as given and say what is wrong in one line.
Result<GltfSource> parseGltfFile(const std::filesystem::path& file);

// What a file that is not glTF seems to be, by its first bytes or its extension, with the way to
// a glTF ("; it looks like an OBJ file: grass reads glTF 2.0, so export …"): artists bring
// meshes in whatever their tool saves. Empty when it is no mesh format known.
std::string otherMeshFormat(const std::filesystem::path& file, std::string_view firstBytes = {});

// The file a relative URI of `gltfFile` names (percent-decoded), refused unless it is a regular
// file inside the glTF file's folder (no absolute paths, "..", schemes or links out). `what`
// names the referrer in the message ("image 2").
Result<std::filesystem::path> fileNextToGltf(const std::filesystem::path& gltfFile,
                                             const std::string& uri, const std::string& what);

}  // namespace grass::core::gltf
