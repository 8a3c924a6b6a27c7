// The default field made for a mesh (core::projectForMesh) moves as the default field does,
// whatever the mesh's size: its blades are sized to the mesh, and gravity with them
// (core::physicsScaleFor). The physics is a displacement-rate model: gravity holds a blade about
// g/k metres off its rest tip whatever its height, so at 9.81 a 1 m box's 8 cm blades lay flat
// within seconds of play and a 60 km sphere's 3 km blades stood rigid.
#include <gtest/gtest.h>

#include <cstdio>

#include "mesh/gltf_loader.h"
#include "project/project.h"
#include "scene/scene.h"
#include "scene/scene_physics.h"
#include "support/gltf_writer.h"
#include "support/scratch_folder.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

// The mean over the field of how high each blade's tip stands above its root, as a share of the
// blade's height, after `seconds` of the project's physics (gravity alone here).
double meanTipRise(const LoadedProject& loaded, Scene& scene, float seconds) {
    auto physics = buildScenePhysics(loaded);
    EXPECT_TRUE(physics.ok()) << physics.error().str();
    if (!physics)
        return 0.0;
    SceneSimulation simulation(scene, std::move(*physics), 1);
    while (simulation.timeS() < seconds)
        simulation.step();
    double rise = 0.0;
    std::size_t blades = 0;
    for (const LayerField& layer : scene.layers)
        for (const Blade& blade : layer.patched.blades)
            if (blade.v1H.w > 0.0f) {
                const glm::vec3 up(blade.upS);
                rise += glm::dot(glm::vec3(blade.v2W) - glm::vec3(blade.v0Theta), up) / blade.v1H.w;
                ++blades;
            }
    EXPECT_GT(blades, 500u);
    return blades ? rise / double(blades) : 0.0;
}

// A flat square of `size` metres written as a glTF file and grown as `grass render --mesh` grows
// it; the mean tip rise after two seconds of play.
double meshFieldTipRise(const fs::path& folder, float size, float* gravity = nullptr) {
    const fs::path file = folder / ("square_" + std::to_string(size) + ".glb");
    test::writeGltf(file, test::singleMeshAsset(test::gridPrimitive(size, size, 8)),
                    test::BufferStorage::Glb);
    auto imported = loadGltf(file, GltfPlacement::GroundNearOrigin, 1.0);
    EXPECT_TRUE(imported.ok()) << imported.error().str();
    if (!imported)
        return 0.0;
    auto loaded = projectForMesh(file, imported->mesh, 2000);
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    if (!loaded)
        return 0.0;
    if (gravity)
        *gravity = loaded->project.physics.gravity.w;
    auto scene = buildSceneFromMesh(*loaded, std::move(imported->mesh), {});
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    return scene ? meanTipRise(*loaded, *scene, 2.0f) : 0.0;
}

TEST(MeshFieldPhysics, TheFieldOnAnyMeshDroopsAsTheDefaultFieldDoes) {
    const test::ScratchFolder folder("mesh-field-physics");
    // The default project: default blades on a 10 m plane under 9.81.
    LoadedProject reference;
    reference.project.mesh.procedural.size = 10.0f;  // a plane by default
    reference.project.layers.front().scatter.density = 30.0f;
    auto referenceScene = buildScene(reference);
    ASSERT_TRUE(referenceScene.ok()) << referenceScene.error().str();
    const double expected = meanTipRise(reference, *referenceScene, 2.0f);
    std::printf("default field: tips at %.3f of the blades' height\n", expected);
    // Gravity bends the default blades visibly, without laying them flat.
    EXPECT_GT(expected, 0.5);
    EXPECT_LT(expected, 0.98);
    for (const float size : {0.1f, 1.0f, 10.0f, 1000.0f, 60000.0f}) {
        float gravity = 0.0f;
        const double rise = meshFieldTipRise(folder.path(), size, &gravity);
        std::printf("%g m square: gravity %.4g, tips at %.3f of the blades' height\n", double(size),
                    double(gravity), rise);
        // Measured 0.947 at every size, the default field 0.938; before gravity followed the
        // blades, 0.000 on the 0.1 and 1 m squares (flat on the ground) and 1.000 on the 1 and
        // 60 km ones (upright, as if no gravity pulled).
        EXPECT_NEAR(rise, expected, 0.03) << size << " m";
    }
}

// The project made for a mesh of any size saves and loads again: a 105 km sphere's field had
// blades of 2.3 to 4.2 km, beyond project.json's 100 m, and the editor's Save refused it. Such
// blades are capped, with a note that names the unit as the likely cause.
TEST(MeshFieldPhysics, TheProjectMadeForAMeshOfAnySizeSaves) {
    const test::ScratchFolder folder("mesh-field-saves");
    for (const float size : {0.001f, 1.0f, 1000.0f, 60000.0f, 2.0e6f}) {
        const fs::path file = folder.path() / ("square_" + std::to_string(size) + ".glb");
        test::writeGltf(file, test::singleMeshAsset(test::gridPrimitive(size, size, 8)),
                        test::BufferStorage::Glb);
        auto imported = loadGltf(file, GltfPlacement::GroundNearOrigin, 1.0);
        ASSERT_TRUE(imported.ok()) << imported.error().str();
        std::vector<std::string> notes;
        auto loaded = projectForMesh(file, imported->mesh, 40000, &notes);
        ASSERT_TRUE(loaded.ok()) << loaded.error().str();
        const fs::path saved = folder.path() / ("project_" + std::to_string(size) + ".json");
        const Result<void> written = saveProject(loaded->project, saved);
        ASSERT_TRUE(written.ok()) << size << " m: " << written.error().str();
        auto again = loadProject(saved);
        ASSERT_TRUE(again.ok()) << again.error().str();
        const BladeRanges& blade = again->project.layers.front().scatter.blade;
        EXPECT_LE(blade.heightMax, MAX_BLADE_HEIGHT_M);
        // A note only where the blades were capped: the 1 km square's are 70 m at most.
        const bool capped = size > 10000.0f;
        EXPECT_EQ(notes.size(), capped ? 1u : 0u) << size << " m";
        if (capped && !notes.empty()) {
            EXPECT_FLOAT_EQ(blade.heightMax, MAX_BLADE_HEIGHT_M);
            EXPECT_NE(notes.front().find("unit"), std::string::npos) << notes.front();
        }
    }
}

TEST(MeshFieldPhysics, TheScaleIsTheBladesMeanHeightOverTheDefaultBlades) {
    EXPECT_FLOAT_EQ(physicsScaleFor(BladeRanges{}), 1.0f);
    BladeRanges tall;
    tall.heightMin = 4.0f;
    tall.heightMax = 4.0f;
    EXPECT_FLOAT_EQ(physicsScaleFor(tall), 10.0f);  // the default blades' mean is 0.4 m
    BladeRanges none;
    none.heightMin = 0.0f;
    none.heightMax = 0.0f;
    EXPECT_FLOAT_EQ(physicsScaleFor(none), 1.0f) << "no blades: forces as they are";
}

}  // namespace
}  // namespace grass::core
