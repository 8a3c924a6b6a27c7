// Grass billboard textures (SPEC §8, GPU Gems 1 ch. 7): an RGBA8 image of several grass blades,
// alpha 1 inside the blades and 0 outside, blades rooted along the bottom edge. Generated
// procedurally or loaded from an image file that has an alpha channel. Images use the
// Rgba8Pixels layout of util/image_file.h: row 0 is the TOP of the image, 4 bytes per pixel.
#pragma once

#include <cstdint>
#include <filesystem>

#include <glm/glm.hpp>

#include "util/image_file.h"
#include "util/result.h"

namespace grass::core {

// `bladeCount` curved, tapering blades with roots spread along the bottom edge and tips at
// 55–100 % of the image height. Edges are antialiased analytically (coverage from the signed
// distance to the blade outline). Colour goes from rootColor at the bottom row to tipColor at
// the top row, with a little per-blade brightness variation; transparent texels carry the same
// colour ramp (alpha 0), so bilinear filtering and mipmaps never bleed black into the edges.
// Deterministic for a given seed. Preconditions: width, height ≥ 1, bladeCount ≥ 0.
Rgba8Pixels generateGrassTexture(int width, int height, int bladeCount, std::uint64_t seed,
                                 glm::vec3 rootColor, glm::vec3 tipColor);

// Reads a grass texture (any format OpenImageIO reads), colours as stored (unassociated alpha,
// as PNG defines it). Fully transparent texels get the mean colour of their row's blades, since
// files often store black there and filtering would bleed it into the edges. Errors name the
// file: it is missing or unreadable, it has no alpha channel, or its alpha is opaque everywhere
// (a billboard would then be a solid rectangle).
Result<Rgba8Pixels> loadGrassTexture(const std::filesystem::path& file);

// The alpha-weighted mean colour of a grass texture, 0..1 per channel (the values as the shader
// reads them): what a distant tuft of it looks like. Black for a texture without opaque texels.
glm::vec3 meanGrassColour(const Rgba8Pixels& texture);

}  // namespace grass::core
