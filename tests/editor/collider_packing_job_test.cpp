// A mesh collider the live field holds no packing of is packed on a worker
// (app/collider_packing_job.h): the packing a fresh build would make, or the reason it cannot,
// naming the file; the packings the field holds are not made again.
#include "app/collider_packing_job.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>

#include "support/scratch_folder.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;

// A plane's project in `folder` with the test cube as a mesh collider of 8 spheres.
core::LoadedProject cubeColliderProject(const fs::path& folder) {
    fs::copy_file(sourceDir() / "tests/data/gltf/cube.glb", folder / "cube.glb");
    core::LoadedProject loaded;
    loaded.folder = folder;
    core::ColliderDesc cube;
    cube.name = "cube";
    cube.shape = core::ColliderShape::Mesh;
    cube.file = "cube.glb";
    cube.sphereCount = 8;
    cube.position = {0.0f, 0.5f, 0.0f};
    loaded.project.colliders = {cube};
    return loaded;
}

TEST(ColliderPackingJob, PacksWhatAFreshBuildPacksAndWakesTheWindow) {
    const ScratchFolder folder("collider-packing-job");
    const core::LoadedProject loaded = cubeColliderProject(folder.path());
    std::atomic<int> woken{0};
    editor::ColliderPackingJob job(loaded, glm::dvec3(0.0), {}, [&woken] { ++woken; });
    EXPECT_EQ(job.what(), "packing cube.glb");
    auto packed = job.take();
    ASSERT_TRUE(packed.ok()) << packed.error().str();
    EXPECT_TRUE(job.done());
    EXPECT_EQ(woken.load(), 1);
    ASSERT_EQ(packed->packings.byFile.size(), 1u);
    EXPECT_FALSE(packed->notes.empty())
        << "the note a build prints: how many spheres, cached where";

    // A build given those packings places the spheres a fresh build places, reading no file.
    auto fresh = core::buildScenePhysics(loaded);
    ASSERT_TRUE(fresh.ok()) << fresh.error().str();
    fs::remove(folder.path() / "cube.glb");
    fs::remove_all(folder.path() / ".grass-cache");
    core::ColliderPackings kept = packed->packings;
    auto followed = core::buildScenePhysics(loaded, glm::dvec3(0.0), &kept);
    ASSERT_TRUE(followed.ok()) << followed.error().str();
    EXPECT_EQ(followed->colliders, fresh->colliders);

    // What the field holds already is not packed again: the job reads nothing.
    editor::ColliderPackingJob again(loaded, glm::dvec3(0.0), packed->packings);
    auto known = again.take();
    ASSERT_TRUE(known.ok()) << known.error().str();
    EXPECT_TRUE(known->notes.empty());
}

TEST(ColliderPackingJob, AMeshThatCannotBeReadIsRefusedNamingIt) {
    const ScratchFolder folder("collider-packing-job-broken");
    core::LoadedProject loaded = cubeColliderProject(folder.path());
    fs::copy_file(sourceDir() / "tests/data/gltf/truncated.gltf", folder.path() / "broken.gltf");
    loaded.project.colliders[0].file = "broken.gltf";
    editor::ColliderPackingJob job(loaded, glm::dvec3(0.0), {});
    auto packed = job.take();
    ASSERT_FALSE(packed.ok());
    EXPECT_NE(packed.error().str().find("broken.gltf"), std::string::npos) << packed.error().str();
}

}  // namespace
}  // namespace grass::test
