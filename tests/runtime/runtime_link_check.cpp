// Issue 28's link check: a program that links grass_runtime and nothing else (no core, no
// editor, no UI, OpenMesh, OpenImageIO or tinygltf), reads a raw export with it and says what it
// holds. tests/cli/runtime_link_test.sh runs it and checks what the executable needs with ldd.
#include <cstdio>
#include <cstdlib>

#include "runtime/grass_runtime.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: runtime_link_check EXPORT\n");
        return 2;
    }
    // Never set by the test: it makes the drawing and physics code reachable, so the whole
    // runtime (and with it libepoxy) is linked, not only the reader. Set, it needs a current
    // GL context, which this program never makes.
    if (std::getenv("GRASS_LINK_CHECK_DRAW") != nullptr) {
        grass::runtime::Field field;
        std::string ignored;
        if (field.load(argv[1], ignored))
            field.draw(grass::runtime::exportCameraView(field.data(), 1, 1));
    }
    grass::runtime::ExportData data;
    std::string error;
    if (!grass::runtime::readExport(argv[1], data, error)) {
        std::fprintf(stderr, "runtime_link_check: %s\n", error.c_str());
        return 1;
    }
    std::size_t blades = 0;
    for (const grass::runtime::LayerData& layer : data.layers)
        blades += layer.liveBlades;
    std::printf("runtime export: %zu layers, %zu blades, %zu wind sources, %zu colliders, %zu meshes\n",
                data.layers.size(), blades, data.wind.size(), data.colliders.size(),
                data.meshes.size());
    return 0;
}
