// The physics part of project.json (issue 4): gravity, wind sources and colliders load, round-trip
// exactly, and every bad value gives one line naming the file, the JSON path and the problem.
#include <gtest/gtest.h>

#include "project/project.h"
#include "scene/scene_physics.h"
#include "support/test_paths.h"
#include "support/project_errors.h"

namespace grass::core {
namespace {

const std::string SOURCE = "projects/test/project.json";

std::string document(const std::string& members) {
    return R"({"format": "grass-project", "version": 1, )" + members + "}";
}

void expectError(const std::string& text, const std::string& pointer, const std::string& problem) {
    test::expectProjectError(text, SOURCE, pointer, problem);
}

Project windyProject() {
    Project project;
    project.physics.dtS = 0.01f;
    project.physics.gravity = {0.0f, 0.0f, 0.0f, 5.0f};
    project.physics.gravityMode = GravityMode::Centre;
    project.physics.maxSubsteps = 4;
    WindDesc wave;
    wave.name = "breeze";
    wave.source.direction = {1.0f, 0.0f, 0.25f};
    wave.source.strength = 30.0f;
    wave.source.gust = 0.5f;
    WindDesc tornado;
    tornado.name = "tornado";
    tornado.source.kind = WindKind::Vortex;
    tornado.source.radiusM = 4.0f;
    tornado.source.path = {{0.0f, {-5.0f, 0.0f, 0.0f}}, {10.0f, {5.0f, 0.0f, 1.0f}}};
    project.wind = {wave, tornado};
    ColliderDesc ball;
    ball.name = "ball";
    ball.radiusM = 0.75f;
    ball.path = {{0.0f, {0.0f, 0.5f, 0.0f}}, {2.5f, {3.0f, 0.5f, 0.0f}}};
    ColliderDesc rock;
    rock.name = "rock";
    rock.shape = ColliderShape::Mesh;
    rock.file = "meshes/rock.glb";
    rock.scale = 2.0f;
    rock.sphereCount = 48;
    rock.packingResolution = 96;
    project.colliders = {ball, rock};
    return project;
}

TEST(ProjectPhysics, DefaultsHaveGravityAndNoWindOrColliders) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 1})", SOURCE);
    ASSERT_TRUE(parsed) << parsed.error().str();
    EXPECT_EQ(parsed->physics, PhysicsParams{});
    EXPECT_TRUE(parsed->wind.empty());
    EXPECT_TRUE(parsed->colliders.empty());
}

TEST(ProjectPhysics, WindAndCollidersRoundTripExactly) {
    const Project project = windyProject();
    const std::string text = serializeProject(project);
    const auto parsed = parseProject(text, "saved");
    ASSERT_TRUE(parsed) << parsed.error().str();
    EXPECT_EQ(*parsed, project);
    EXPECT_EQ(serializeProject(*parsed), text);
    // Centre gravity is written as a centre, not as a direction.
    EXPECT_NE(text.find("\"centre\": [0.0, 0.0, 0.0]"), std::string::npos) << text;
    EXPECT_EQ(text.find("\"direction\": [0.0, 0.0, 0.0]"), std::string::npos) << text;
}

TEST(ProjectPhysics, ReadsEveryKind) {
    const auto parsed = parseProject(document(R"(
        "physics": {"step_s": 0.02, "gravity": {"direction": [0, -1, 0], "strength": 3}},
        "wind": [{"name": "w", "kind": "directional", "strength": 20, "wavelength": 5},
                 {"name": "heli", "kind": "point", "position": [1, 2, 3], "radius": 6},
                 {"name": "twister", "kind": "vortex", "axis": [0, 1, 0], "core_radius": 0.5}],
        "colliders": [{"name": "ball", "radius": 1.5, "color": [0.2, 0.3, 0.4],
                       "path": [{"time": 0, "position": [0, 1, 0]},
                                {"time": 5, "position": [9, 1, 0]}]}])"),
                                     SOURCE);
    ASSERT_TRUE(parsed) << parsed.error().str();
    EXPECT_FLOAT_EQ(parsed->physics.dtS, 0.02f);
    EXPECT_FLOAT_EQ(parsed->physics.gravity.w, 3.0f);
    ASSERT_EQ(parsed->wind.size(), 3u);
    EXPECT_EQ(parsed->wind[1].source.kind, WindKind::Point);
    EXPECT_EQ(parsed->wind[1].source.position, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(parsed->wind[2].source.kind, WindKind::Vortex);
    ASSERT_EQ(parsed->colliders.size(), 1u);
    EXPECT_EQ(parsed->colliders[0].shape, ColliderShape::Sphere);
    ASSERT_EQ(parsed->colliders[0].path.size(), 2u);
    EXPECT_EQ(samplePath(parsed->colliders[0].path, 2.5f, {}), glm::vec3(4.5f, 1.0f, 0.0f));
    EXPECT_EQ(parsed->colliders[0].color, glm::vec3(0.2f, 0.3f, 0.4f));
    // The colour is written back only when set, and read back the same.
    const auto again = parseProject(serializeProject(*parsed), SOURCE);
    ASSERT_TRUE(again) << again.error().str();
    EXPECT_EQ(again->colliders, parsed->colliders);
}

TEST(ProjectPhysics, BadValuesAreRejectedWithTheirPath) {
    expectError(document(R"("physics": {"step_s": 0})"), "/physics/step_s", "[0.00001, 60]");
    expectError(document(R"("physics": {"max_substeps": 0})"), "/physics/max_substeps", "1");
    expectError(document(R"("physics": {"gravity": {"direction": [0, 0, 0]}})"),
                "/physics/gravity/direction", "must not be [0, 0, 0]");
    expectError(
        document(R"("physics": {"gravity": {"direction": [0, -1, 0], "centre": [0, 0, 0]}})"),
        "/physics/gravity/centre", "not both");
    expectError(document(R"("physics": {"gravity": {"strength": -1}})"),
                "/physics/gravity/strength", ">= 0");
    expectError(document(R"("wind": [{"kind": "tornado"}])"), "/wind/0/kind", "\"vortex\"");
    expectError(document(R"("wind": [{"gust": 2}])"), "/wind/0/gust", "1");
    expectError(document(R"("wind": [{"direction": [0, 0, 0]}])"), "/wind/0/direction",
                "must not be [0, 0, 0]");
    expectError(document(R"("wind": [{"kind": "vortex", "axis": [0, 0, 0]}])"), "/wind/0/axis",
                "must not be [0, 0, 0]");
    expectError(document(R"("wind": [{}, {}])"), "/wind/1/name", "duplicate");
    expectError(document(R"("wind": [{"strenght": 3}])"), "/wind/0/strenght", "\"strength\"");
    expectError(document(R"("wind": [{"path": [{"time": 2, "position": [0, 0, 0]},
                                              {"time": 1, "position": [1, 0, 0]}]}])"),
                "/wind/0/path/1/time", "time order");
    expectError(document(R"("wind": [{"path": [{"time": 2}]}])"), "/wind/0/path/0", "needs both");
    expectError(document(R"("colliders": [{"radius": 0}])"), "/colliders/0/radius", "> 0");
    expectError(document(R"("colliders": [{"shape": "mesh"}])"), "/colliders/0/file",
                "missing required key");
    expectError(document(R"("colliders": [{"shape": "mesh", "file": "/abs/rock.glb"}])"),
                "/colliders/0/file", "");
    expectError(document(R"("colliders": [{"shape": "mesh", "file": "r.glb", "radius": 1}])"),
                "/colliders/0/radius", "only for");
    expectError(document(R"("colliders": [{"file": "r.glb"}])"), "/colliders/0/file", "only for");
    expectError(document(R"("colliders": [{"shape": "mesh", "file": "r.glb", "spheres": 0}])"),
                "/colliders/0/spheres", "1");
    expectError(document(R"("colliders": [{"shape": "mesh", "file": "r.glb",
                                           "packing_resolution": 4}])"),
                "/colliders/0/packing_resolution", "8");
    expectError(document(R"("colliders": [{"color": [1.5, 0, 0]}])"), "/colliders/0/color/0",
                "[0, 1]");
    expectError(document(R"("colliders": [{"color": "red"}])"), "/colliders/0/color", "[r, g, b]");
}

}  // namespace
}  // namespace grass::core

namespace grass::core {
namespace {

// Every project shipped in projects/ loads, and its physics builds (the user's first files).
TEST(ProjectPhysics, ShippedProjectsLoadWithTheirPhysics) {
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "projects")) {
        if (!std::filesystem::exists(entry.path() / "project.json"))
            continue;
        const auto loaded = loadProject(entry.path());
        ASSERT_TRUE(loaded) << loaded.error().str();
        const auto physics = buildScenePhysics(*loaded);
        ASSERT_TRUE(physics) << physics.error().str();
        ++count;
    }
    EXPECT_GE(count, 2u);
}

}  // namespace
}  // namespace grass::core
