// `grass render --mesh` on any glTF (issue 26 item 2): a gently hilly terrain of 1 mm, 1 m and
// 1 km, and the 1 m one modelled in millimetres with +Z up and loaded with unit mm and up +Z:
// the default field's blades and camera follow the surface's size, so grass covers a stated
// share of every picture.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gl_context_fixture.h"
#include "mesh/gltf_loader.h"
#include "mesh/mesh_frame.h"
#include "render/offscreen_render.h"
#include "scene/scene.h"
#include "support/gltf_writer.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;
using MeshScaleTest = GlTest;

// A `size` square terrain with hills 8 % of its side, +Y up, or with the file's axes turned
// so that +Z is up.
GltfPrimitive hillyTerrain(float size, bool zUp) {
    GltfPrimitive p = gridPrimitive(size, size, 24);
    for (glm::vec3& v : p.positions) {
        v.y = 0.08f * size * std::sin(6.0f * v.x / size) * std::cos(5.0f * v.z / size);
        if (zUp)
            v = {v.x, -v.z, v.y};
    }
    for (glm::vec3& n : p.normals)
        n = zUp ? glm::vec3(0.0f, 0.0f, 1.0f) : n;  // recomputed from the faces below
    p.normals.clear();
    return p;
}

double grassShare(const fs::path& file, float metresPerUnit, core::UpAxis up) {
    auto imported = core::loadGltf(file);
    EXPECT_TRUE(imported.ok()) << imported.error().str();
    if (!imported)
        return 0.0;
    core::applyMeshFrame(imported->mesh, metresPerUnit, up);
    auto loaded = core::projectForMesh(file, imported->mesh, 20000);
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = core::buildSceneFromMesh(*loaded, std::move(imported->mesh), {});
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    if (!loaded || !scene)
        return 0.0;
    auto camera = render::projectCamera(loaded->project, "");
    render::OffscreenRequest request;
    request.width = 320;
    request.height = 180;
    request.frames = 1;
    request.options = render::renderOptionsFor(loaded->project, true);
    auto result = render::renderOffscreen(*scene, *camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    if (!result)
        return 0.0;
    // Next to the mesh for a look.
    fs::path picture = file;
    EXPECT_TRUE(writeRgba8Image(picture.replace_extension(".png"), result->image.width,
                                result->image.height, result->image.pixels)
                    .ok());
    return grassPixelShare(result->image.pixels);
}

TEST_F(MeshScaleTest, TheDefaultFieldShowsGrassAtEveryScale) {
    const fs::path dir = scratchDir("mesh_scale");
    for (const float size : {0.001f, 1.0f, 1000.0f}) {
        const fs::path file = dir / ("terrain_" + std::to_string(size) + ".glb");
        writeGltf(file, singleMeshAsset(hillyTerrain(size, false)), BufferStorage::Glb);
        const double share = grassShare(file, 1.0f, core::UpAxis::Y);
        std::printf("%g m terrain: grass covers %.3f of the picture\n", double(size), share);
        // Measured 0.108 to 0.117 at every scale (green blade pixels over the brown ground in a
        // picture the field fills vertically); before the field's distances and the camera
        // followed the surface, 0.052 at 1 mm and 0.000 at 1 km (thinned away at 100 m).
        EXPECT_GT(share, 0.07) << size << " m";
    }
    // The 1 m terrain as a CAD tool writes it: millimetres, +Z up.
    const fs::path cad = dir / "terrain_mm_zup.glb";
    writeGltf(cad, singleMeshAsset(hillyTerrain(1000.0f, true)), BufferStorage::Glb);
    const double share = grassShare(cad, 0.001f, core::UpAxis::Z);
    std::printf("1 m terrain in mm, +Z up: grass covers %.3f\n", share);
    EXPECT_GT(share, 0.07);
}

}  // namespace
}  // namespace grass::test
