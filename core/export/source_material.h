// The terrain's material in an export (issue 25): a project whose surface is a glTF file keeps
// that file's material (the first triangle primitive's, as the artist made it) instead of the
// flat ground colour. Its factors travel — base colour, metallic, roughness, emissive, alpha
// mode and cutoff, double-sidedness —; its textures do not yet (docs/export.md).
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

namespace grass::core {

// The glTF material (JSON, spec §5.19) of the first triangle primitive of `file`'s meshes that
// names one, reduced to its factors; null when the file has none or cannot be read (the
// export then uses the ground colour: the mesh itself already loaded, so nothing is lost).
nlohmann::json sourceMeshMaterial(const std::filesystem::path& file);

}  // namespace grass::core
