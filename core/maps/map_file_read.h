// Reading an image file as a map (docs/project-format.md, maps): the one value a texel holds,
// chosen from its channels by name (maps/map_channels.h), as a viewer shows the file
// (util/image_layout.h: orientation tag, OpenEXR's display window), clamped to [0, 1] with a
// note, refused naming the file when it is missing, unreadable, too large or not finite.
#pragma once

#include <filesystem>

#include "maps/map_image.h"
#include "util/result.h"

namespace grass::core {

// The map at the file's own size (loadMapImage and loadMapImageAt resample it).
Result<MapImage> readMapFile(const std::filesystem::path& file);

}  // namespace grass::core
