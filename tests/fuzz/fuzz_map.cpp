// Fuzz target: a density, soil or light map through loadMapImageAt, as a scene loads a layer's
// maps (resampled to the layer's map resolution). Built once per format the maps are kept in:
// GRASS_FUZZ_MAP_EXTENSION ".png", ".tif", ".exr" or ".tga" names the file; the reader is the one
// its first bytes name, else the extension's (core/util/image_open.h).
#include <cmath>
#include <string>

#include "fuzz_scratch.h"
#include "maps/map_image.h"

namespace {

// Small, so that every input is cheap; not the image's size, so that resampling runs.
constexpr int MAP_WIDTH = 24;
constexpr int MAP_HEIGHT = 16;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grass;
    const std::filesystem::path file =
        fuzz::scratchDir() / ("map" + std::string(GRASS_FUZZ_MAP_EXTENSION));
    fuzz::writeBytes(file, {data, size});
    const auto map = core::loadMapImageAt(file, MAP_WIDTH, MAP_HEIGHT);
    if (!map) {
        fuzz::checkError(map.error());
    } else {
        if (map->width != MAP_WIDTH || map->height != MAP_HEIGHT ||
            map->texels.size() != std::size_t{MAP_WIDTH} * MAP_HEIGHT)
            fuzz::fail("a loaded map does not have the size asked for");
        // map_image.h: values are in [0, 1], NaN and Inf are refused.
        for (const float texel : map->texels)
            if (!(texel >= 0.0f && texel <= 1.0f))
                fuzz::fail("a loaded map has a texel outside [0, 1]: " + std::to_string(texel));
    }
    fuzz::clearScratch();
    return 0;
}
