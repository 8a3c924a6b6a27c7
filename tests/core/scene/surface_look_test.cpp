// A glTF surface's own look (issue 26, scene/surface_look.h): its material's base colour factor
// and base-colour texture are what the viewport draws; without a material, or on a procedural
// surface, the project's ground colour stays.
#include "scene/surface_look.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "support/scratch_folder.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

const fs::path STONE_FOLDER = "tests/data/projects/textured_stone";

// The textured stone with a base colour factor added, in `folder`.
fs::path tintedStone(const fs::path& folder, const nlohmann::json& factor) {
    for (const char* file : {"stone.bin", "stone.png"})
        fs::copy_file(test::sourceDir() / STONE_FOLDER / file, folder / file);
    std::ifstream in(test::sourceDir() / STONE_FOLDER / "stone.gltf");
    std::stringstream text;
    text << in.rdbuf();
    nlohmann::json gltf = nlohmann::json::parse(text.str());
    gltf["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = factor;
    std::ofstream(folder / "stone.gltf") << gltf.dump();
    return folder / "stone.gltf";
}

TEST(SurfaceLook, TheTextureIsTheFilesPicture) {
    const SurfaceLook look = surfaceLookOf(test::sourceDir() / STONE_FOLDER / "stone.gltf", true);
    ASSERT_TRUE(look.baseColor.has_value());
    EXPECT_EQ(*look.baseColor, glm::vec3(1.0f)) << "no factor: white, as glTF defines";
    auto picture = readRgba8Image(test::sourceDir() / STONE_FOLDER / "stone.png");
    ASSERT_TRUE(picture.ok());
    EXPECT_EQ(look.baseTexture.width, 8);
    EXPECT_EQ(look.baseTexture.pixels, picture->pixels);
    EXPECT_EQ(look.wrapS, 10497);
    EXPECT_TRUE(look.notes.empty());
}

TEST(SurfaceLook, TheFactorIsKeptAndGeneratedUvsDropTheTextureWithANote) {
    const test::ScratchFolder folder("surface-look-factor");
    const fs::path file = tintedStone(folder.path(), {0.5, 0.25, 1.0, 1.0});
    const SurfaceLook look = surfaceLookOf(file, false);
    ASSERT_TRUE(look.baseColor.has_value());
    EXPECT_EQ(*look.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_TRUE(look.baseTexture.pixels.empty());
    ASSERT_EQ(look.notes.size(), 1u);
    EXPECT_NE(look.notes[0].find("TEXCOORD_0"), std::string::npos) << look.notes[0];
}

TEST(SurfaceLook, AProjectsSceneCarriesItAndAProceduralSurfaceHasNone) {
    auto loaded = loadProject(test::sourceDir() / STONE_FOLDER);
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    EXPECT_EQ(scene->look.baseTexture.width, 8);
    LoadedProject plane;
    auto bare = buildScene(plane);
    ASSERT_TRUE(bare.ok());
    EXPECT_FALSE(bare->look.baseColor.has_value());
    // A file without a material: nothing, so the ground colour is drawn.
    EXPECT_FALSE(surfaceLookOf(test::sourceDir() / "tests/data/gltf/quad.gltf", true).baseColor);
    // The file's material turned off ("file_material": false): the ground colour too, on the
    // same UVs (the painted maps keep theirs).
    LoadedProject grounded = *loaded;
    grounded.project.mesh.fileMaterial = false;
    auto plain = buildScene(grounded);
    ASSERT_TRUE(plain.ok()) << plain.error().str();
    EXPECT_FALSE(plain->look.baseColor.has_value());
    EXPECT_TRUE(plain->look.baseTexture.pixels.empty());
    EXPECT_EQ(plain->paintUvs.generated, scene->paintUvs.generated);
    EXPECT_EQ(plain->paintUvs.fingerprint, scene->paintUvs.fingerprint);
}

}  // namespace
}  // namespace grass::core
