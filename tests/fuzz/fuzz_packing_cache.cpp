// Fuzz target: a sphere-packing cache file (<project>/.grass-cache/*.spheres.json) through
// loadOrPackSpheres, as a scene loads a mesh collider: a cache that parses and matches is used,
// anything else is repacked and rewritten.
#include <cmath>
#include <string>

#include "fuzz_scratch.h"
#include "packing_fixture.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grass;
    static const core::SurfaceMesh mesh = fuzz::packingMesh();
    const core::SpherePackingParams params = fuzz::packingParams();
    const std::filesystem::path meshFile = fuzz::scratchDir() / "rock.glb";
    const std::string_view meshBytes = fuzz::PACKING_MESH_BYTES;
    fuzz::writeBytes(meshFile, {reinterpret_cast<const std::uint8_t*>(meshBytes.data()),
                                meshBytes.size()});
    const std::filesystem::path cache = core::packingCachePath(fuzz::scratchDir(), meshFile, params);
    std::filesystem::create_directories(cache.parent_path());
    fuzz::writeBytes(cache, {data, size});
    const auto packing = core::loadOrPackSpheres(meshFile, mesh, params, cache);
    if (!packing) {
        fuzz::checkError(packing.error());
    } else {
        if (packing->spheres.empty() || packing->spheres.size() > params.sphereCount)
            fuzz::fail("a packing has " + std::to_string(packing->spheres.size()) + " spheres");
        for (const core::PackedSphere& sphere : packing->spheres)
            if (!(sphere.radiusM > 0.0f) || !std::isfinite(sphere.radiusM) ||
                !std::isfinite(sphere.centre.x + sphere.centre.y + sphere.centre.z))
                fuzz::fail("a packing has a sphere that is not finite or not positive");
    }
    fuzz::clearScratch();
    return 0;
}
