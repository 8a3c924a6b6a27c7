// What the surface itself looks like (issue 26): a glTF surface shows its own material's base
// colour and base-colour texture in the viewport and in `grass render`, as the artist made it,
// instead of the flat ground colour (which stays for procedural surfaces and files without a
// material). The material is the first triangle primitive's (export/source_material.h: the same
// one an export keeps); the texture only when it reads the surface's own TEXCOORD_0.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/image_file.h"

namespace grass::core {

// The largest base-colour texture drawn (an 8192² RGBA8 texture is 256 MiB with its mips);
// larger ones are left out with a note.
inline constexpr int MAX_SURFACE_TEXTURE_SIDE = 8192;

struct SurfaceLook {
    std::optional<glm::vec3> baseColor;  // linear RGB; none: the project's ground colour
    Rgba8Pixels baseTexture;             // sRGB-encoded RGBA, row 0 = v 0; empty: none
    // glTF wrap modes (10497 repeat, 33071 clamp to edge, 33648 mirrored repeat).
    int wrapS = 10497, wrapT = 10497;
    std::vector<std::string> notes;  // a texture left out and why
};

// The look of the glTF surface in `file`; `meshHasUv`: every merged primitive carried
// TEXCOORD_0 (else the surface's UVs are generated and a texture would not fit them).
SurfaceLook surfaceLookOf(const std::filesystem::path& file, bool meshHasUv);

}  // namespace grass::core
