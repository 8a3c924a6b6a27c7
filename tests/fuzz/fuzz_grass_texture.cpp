// Fuzz target: a billboard texture (billboards.texture of a project, an RGBA PNG) through
// loadGrassTexture, as a scene with star billboards loads it.
#include <string>

#include "billboard/grass_texture.h"
#include "fuzz_scratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grass;
    const std::filesystem::path file = fuzz::scratchDir() / "texture.png";
    fuzz::writeBytes(file, {data, size});
    const auto texture = core::loadGrassTexture(file);
    if (!texture) {
        fuzz::checkError(texture.error());
    } else if (texture->width <= 0 || texture->height <= 0 ||
               texture->pixels.size() != std::size_t(texture->width) *
                                             std::size_t(texture->height) * 4u) {
        fuzz::fail("a loaded texture's pixels do not match its size");
    }
    fuzz::clearScratch();
    return 0;
}
