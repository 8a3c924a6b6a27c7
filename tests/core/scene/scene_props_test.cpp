// Props (scene_props.h): every collider becomes a drawable object that stands where the physics
// puts its collider at a given time.
#include <gtest/gtest.h>

#include <map>

#include "mesh/surface_mesh.h"
#include "scene/scene.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

TEST(SceneProps, SphereColliderIsAUnitBallScaledToItsRadiusFollowingItsPath) {
    LoadedProject loaded;
    ColliderDesc ball;
    ball.name = "ball";
    ball.radiusM = 0.5f;
    ball.position = {9, 9, 9};
    ball.path = {PathKey{0.0f, {0, 0, 0}}, PathKey{2.0f, {4, 0, 0}}};
    loaded.project.colliders.push_back(ball);
    auto props = loadSceneProps(loaded);
    ASSERT_TRUE(props.ok()) << props.error().str();
    ASSERT_EQ(props->size(), 1u);
    const SceneProp& prop = props->front();
    const Bounds bounds = meshBounds(prop.mesh);
    EXPECT_NEAR(bounds.max.x, 1.0f, 1e-3f);
    EXPECT_NEAR(bounds.min.y, -1.0f, 1e-3f);
    // Halfway along the path at t = 1 s; the radius scales the unit ball.
    const glm::vec4 top = prop.modelAt(1.0f) * glm::vec4(0, 1, 0, 1);
    EXPECT_NEAR(top.x, 2.0f, 1e-5f);
    EXPECT_NEAR(top.y, 0.5f, 1e-5f);
    EXPECT_EQ(prop.originAt(1.0f), samplePath(ball.path, 1.0f, ball.position));
}

TEST(SceneProps, MeshColliderLoadsItsFileAndTheSceneCarriesIt) {
    auto loaded = loadProject(test::sourceDir() / "tests/data/projects/rock");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    ASSERT_EQ(scene->props.size(), loaded->project.colliders.size());
    const SceneProp& cube = scene->props.front();
    EXPECT_GT(cube.mesh->n_faces(), 0u);
    EXPECT_EQ(cube.scale, loaded->project.colliders.front().scale);
}

TEST(SceneProps, MissingMeshFileNamesIt) {
    LoadedProject loaded;
    loaded.file = "projects/x/project.json";
    loaded.folder = test::sourceDir() / "tests/data/projects";
    ColliderDesc rock;
    rock.shape = ColliderShape::Mesh;
    rock.file = "no-such-rock.glb";
    loaded.project.colliders.push_back(rock);
    auto props = loadSceneProps(loaded);
    ASSERT_FALSE(props.ok());
    EXPECT_NE(props.error().str().find("no-such-rock.glb"), std::string::npos)
        << props.error().str();
}

// A ball added beside a rock, then the rock moved to the end: the props are remade from the
// ones at hand, so the rock's mesh is kept (its file need not exist) and only the ball is made.
TEST(SceneProps, RemadePropsKeepTheMeshesTheyHave) {
    auto loaded = loadProject(test::sourceDir() / "tests/data/projects/rock");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto props = loadSceneProps(*loaded);
    ASSERT_TRUE(props.ok()) << props.error().str();
    const std::vector<ColliderDesc> madeFor = loaded->project.colliders;
    ASSERT_EQ(madeFor.front().shape, ColliderShape::Mesh);
    const std::size_t rockFaces = props->front().mesh->n_faces();

    LoadedProject edited = *loaded;
    edited.folder = test::scratchDir("scene_props_remade");  // the rock's file is not there
    ColliderDesc ball;
    ball.radiusM = 0.25f;
    edited.project.colliders.insert(edited.project.colliders.begin(), ball);
    edited.project.colliders.back().position = {1.0f, 0.0f, 2.0f};
    ASSERT_FALSE(loadSceneProps(edited).ok()) << "read afresh, the rock's file is missing";
    auto remade = remakeSceneProps(edited, *props, madeFor);
    ASSERT_TRUE(remade.ok()) << remade.error().str();
    ASSERT_EQ(remade->size(), edited.project.colliders.size());
    EXPECT_EQ(remade->front().scale, 0.25f);
    EXPECT_GT(remade->front().mesh->n_faces(), 0u);
    EXPECT_EQ(remade->back().mesh->n_faces(), rockFaces);
    EXPECT_EQ(remade->back().position, glm::vec3(1.0f, 0.0f, 2.0f));
}

// A mesh collider added by the editor's add mesh…, whose file was read on a worker: its prop is
// made from that reading (the file is not read again, here not even there), and two colliders of
// the file each get the mesh.
TEST(SceneProps, ANewMeshColliderTakesTheMeshReadAhead) {
    auto loaded = loadProject(test::sourceDir() / "tests/data/projects/rock");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto props = loadSceneProps(*loaded);
    ASSERT_TRUE(props.ok()) << props.error().str();
    const std::size_t rockFaces = props->front().mesh->n_faces();
    LoadedProject edited = *loaded;
    edited.folder = test::scratchDir("scene_props_read_ahead");  // no file is there
    ColliderDesc rock = loaded->project.colliders.front();
    rock.file = "meshes/rock/rock.glb";
    edited.project.colliders = {rock, rock};
    ASSERT_FALSE(remakeSceneProps(edited, {}, {}).ok()) << "its file is missing";
    std::map<std::string, MovableSurfaceMesh> readAhead;
    readAhead.emplace(rock.file, props->front().mesh);
    auto remade = remakeSceneProps(edited, {}, {}, glm::dvec3(0.0), &readAhead);
    ASSERT_TRUE(remade.ok()) << remade.error().str();
    ASSERT_EQ(remade->size(), 2u);
    for (const SceneProp& prop : *remade)
        EXPECT_EQ(prop.mesh->n_faces(), rockFaces);
}

}  // namespace
}  // namespace grass::core
