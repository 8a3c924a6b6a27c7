// Fuzz target: glTF and GLB through loadGltf, as a project's mesh, a collider mesh and
// `grass mesh-info` are read, and through loadGltfView (colours and instance colours too). Built twice: GRASS_FUZZ_GLTF_EXTENSION ".glb" writes the input as
// scene.glb; ".gltf" writes the input up to its first NUL byte as scene.gltf and the rest, when
// there is a NUL, as scene.bin, so that the buffer a .gltf references is fuzzed with it (JSON
// text holds no raw NUL; seeds with data: URIs carry their buffers inline).
#include <algorithm>
#include <cmath>
#include <string>

#include "fuzz_scratch.h"
#include "mesh/gltf_loader.h"
#include "mesh/gltf_view.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grass;
    const std::string_view extension = GRASS_FUZZ_GLTF_EXTENSION;
    const std::filesystem::path file = fuzz::scratchDir() / ("scene" + std::string(extension));
    std::span<const std::uint8_t> bytes(data, size);
    if (extension == ".gltf") {
        const auto* nul = std::find(data, data + size, std::uint8_t{0});
        bytes = {data, nul};
        if (nul != data + size)
            fuzz::writeBytes(fuzz::scratchDir() / "scene.bin", {nul + 1, data + size});
    }
    fuzz::writeBytes(file, bytes);
    // As a project's ground: the placement that also measures the bounds and may move them.
    const auto imported = core::loadGltf(file, core::GltfPlacement::GroundNearOrigin);
    if (!imported) {
        fuzz::checkError(imported.error());
    } else {
        const core::SurfaceMesh& mesh = imported->mesh;
        if (mesh.n_faces() == 0)
            fuzz::fail("a loaded glTF has no triangles");
        // gltf_loader.h: missing and broken normals are recomputed.
        if (mesh.has_vertex_normals())
            for (const auto vh : mesh.vertices())
                for (int axis = 0; axis < 3; ++axis)
                    if (!std::isfinite(mesh.normal(vh)[axis]))
                        fuzz::fail("a loaded glTF has a non-finite normal at vertex " +
                                   std::to_string(vh.idx()));
    }
    // The view reads what the import skips (COLOR_0, _COLOR_0); a bounded vertex count keeps
    // an instancing bomb from exhausting memory.
    const auto view = core::loadGltfView(file, 1u << 20);
    if (!view) {
        fuzz::checkError(view.error());
    } else {
        if (view->colors.size() != view->positions.size() || view->normals.size() != view->positions.size())
            fuzz::fail("a glTF view's attributes differ in count");
        for (const std::uint32_t index : view->indices)
            if (index >= view->positions.size())
                fuzz::fail("a glTF view's index is out of range");
    }
    fuzz::clearScratch();
    return 0;
}
