// The terrain's material in an export (issue 25): a project whose surface is a glTF file keeps
// that file's material (the first triangle primitive's, as the artist made it) instead of the
// flat ground colour. Its factors travel — base colour, metallic, roughness, emissive, alpha
// mode and cutoff, double-sidedness — and its PNG and JPEG textures (base colour,
// metallic-roughness, normal, occlusion, emissive) when they read the primitive's own
// TEXCOORD_0, which the terrain keeps (docs/export.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace grass::core {

// One image a material slot reads, as the source file held it.
struct SourceTexture {
    std::string mimeType;       // "image/png" or "image/jpeg"
    std::string bytes;          // the encoded image
    nlohmann::json sampler;     // the source's sampler (filters, wrap), or null
};

struct SourceMaterial {
    // The glTF material (JSON, spec §5.19) reduced to what the spec allows; null when the file
    // has none or cannot be read (the export then uses the ground colour: the mesh itself
    // already loaded, so nothing is lost). A texture slot's "index" is into `textures`.
    nlohmann::json material;
    std::vector<SourceTexture> textures;
    // Textures left behind, one line each (another UV set, an unsupported image format, ...).
    std::vector<std::string> notes;
};

// The material of the first triangle primitive of `file`'s meshes that names one.
SourceMaterial sourceMeshMaterial(const std::filesystem::path& file);

}  // namespace grass::core
