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
#include "support/image_compare.h"
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

// `grass render --mesh` of the file: the default field and camera, 320 × 180, written next to the
// file for a look.
gl::Rgba8Image renderMeshFile(const fs::path& file, float metresPerUnit, core::UpAxis up,
                              core::GltfPlacement placement = core::GltfPlacement::GroundNearOrigin) {
    auto imported = core::loadGltf(file, placement, metresPerUnit);
    EXPECT_TRUE(imported.ok()) << imported.error().str();
    if (!imported)
        return {};
    core::applyMeshFrame(imported->mesh, metresPerUnit, up);
    auto loaded = core::projectForMesh(file, imported->mesh, 20000);
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = core::buildSceneFromMesh(*loaded, std::move(imported->mesh), {});
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    if (!loaded || !scene)
        return {};
    auto camera = render::projectCamera(loaded->project, "");
    render::OffscreenRequest request;
    request.width = 320;
    request.height = 180;
    request.frames = 1;
    request.options = render::renderOptionsFor(loaded->project, true);
    auto result = render::renderOffscreen(*scene, *camera, request);
    EXPECT_TRUE(result.ok()) << result.error().str();
    if (!result)
        return {};
    fs::path picture = file;
    EXPECT_TRUE(writeRgba8Image(picture.replace_extension(".png"), result->image.width,
                                result->image.height, result->image.pixels)
                    .ok());
    return std::move(result->image);
}

double grassShare(const fs::path& file, float metresPerUnit, core::UpAxis up) {
    return grassPixelShare(renderMeshFile(file, metresPerUnit, up).pixels);
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

namespace grass::test {
namespace {

// A georeferenced terrain (GIS exports place a tile at its map coordinates: here UTM-like,
// 512 km east and 5412 km north, by its node's translation) draws as the same terrain at the
// origin: the loader moves a ground that far out next to grass's origin in double precision
// (core::GltfPlacement). Tolerance as the golden tests (0.5 % of pixels beyond 48 levels): the
// two scenes differ only by the rounding of a translation. Left where the file puts it, 32-bit
// floats are 0.5 m apart there: blades snap onto each other and bare patches show.
TEST_F(MeshScaleTest, AGeoreferencedTerrainDrawsAsTheSameTerrainAtTheOrigin) {
    const fs::path dir = scratchDir("mesh_far");
    const fs::path near = dir / "terrain_here.glb";
    const fs::path far = dir / "terrain_utm.glb";
    writeGltf(near, singleMeshAsset(hillyTerrain(100.0f, false)), BufferStorage::Glb);
    GltfAsset utm = singleMeshAsset(hillyTerrain(100.0f, false));
    utm.nodes[0].translation = {512345.0f, 120.0f, 5412345.0f};
    writeGltf(far, utm, BufferStorage::Glb);
    const gl::Rgba8Image here = renderMeshFile(near, 1.0f, core::UpAxis::Y);
    const gl::Rgba8Image moved = renderMeshFile(far, 1.0f, core::UpAxis::Y);
    ASSERT_FALSE(here.pixels.empty() || moved.pixels.empty());
    const ImageDifference difference = compareImages(here.pixels, moved.pixels, 48);
    std::printf("georeferenced terrain moved to the origin against the same at the origin: "
                "%.4f of pixels differ, mean %.3f\n",
                difference.differingShare, difference.meanAbs);
    EXPECT_LT(difference.differingShare, 0.005);
    EXPECT_GT(grassPixelShare(moved.pixels), 0.07);
    const gl::Rgba8Image asInFile =
        renderMeshFile(far, 1.0f, core::UpAxis::Y, core::GltfPlacement::AsInFile);
    const ImageDifference unmoved = compareImages(here.pixels, asInFile.pixels, 48);
    std::printf("left at its map coordinates: %.4f of pixels differ, mean %.3f\n",
                unmoved.differingShare, unmoved.meanAbs);
    // Measured 1.5 % of pixels, mean 2.8 levels: bare patches where blades collapsed onto each
    // other, three times what the tolerance above allows.
    EXPECT_GT(unmoved.differingShare, 0.005) << "the precision loss this guards against";
}

}  // namespace
}  // namespace grass::test
