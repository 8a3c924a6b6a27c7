// Issue 28: the reference runtime (editor/runtime) against the editor. A raw export of a project,
// loaded by the runtime and drawn into a framebuffer like a host's, looks as `grass render` of
// the project does; its physics after 5 s stands where the CPU reference (`grass sim`) stands,
// with the export's colliders on their paths and with a collider the host moves.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "export/export.h"
#include "gl/framebuffer.h"
#include "gl_context_fixture.h"
#include "project/project.h"
#include "render/offscreen_render.h"
#include "runtime/grass_runtime.h"
#include "scene/scene.h"
#include "scene/scene_physics.h"
#include "support/image_compare.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using RuntimeTest = GlTest;

// The golden-image tolerances (golden_gl_test.cpp): a channel may move 48 levels before a pixel
// counts as different, at most 0.5 % of the pixels may, and the mean difference stays ≤ 1 level.
// The runtime runs the editor's shaders on the same buffers, so what may differ is only what the
// runtime leaves out on purpose: the occlusion cull (it needs the host's depth; hidden blades are
// hidden by the depth test anyway, but the editor's pre-pass also drops a few blades whose root
// is hidden and whose tip shows over a crest) and float rounding in the camera.
constexpr int PIXEL_THRESHOLD = 48;
constexpr double MAX_DIFFERING_SHARE = 0.005;
constexpr double MAX_MEAN_ABS = 1.0;
constexpr int WIDTH = 640, HEIGHT = 360;

fs::path exportRaw(const core::LoadedProject& loaded, const core::Scene& scene, const fs::path& out) {
    core::ExportOptions options;
    options.format = core::ExportFormat::Raw;
    options.outDir = out;
    auto report = core::exportProject(loaded, scene, options, {});
    EXPECT_TRUE(report.ok()) << report.error().str();
    return out;
}

// What a host does each frame: clear to the sky, its own scene (here the export's meshes), the
// field.
gl::Rgba8Image drawWithRuntime(runtime::Field& field, int samples) {
    gl::Framebuffer framebuffer(WIDTH, HEIGHT, samples);
    framebuffer.bind();
    glViewport(0, 0, WIDTH, HEIGHT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    const glm::vec3 sky = field.data().render.skyColor;
    glClearColor(sky.r, sky.g, sky.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const runtime::View view = runtime::exportCameraView(field.data(), WIDTH, HEIGHT);
    field.drawMeshes(view);
    field.draw(view);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return framebuffer.readPixels();
}

// A project (the meadow by default) exported raw, loaded by the runtime and drawn on `path`
// (switched to with setGeometry when the export's choice differs: the first switch compiles that
// path's programs), against `grass render` of the project on the same path.
void expectTheMeadowAsGrassRenderDraws(const fs::path& dir, render::GeometryPath path,
                                       const fs::path& project = sourceDir() / "projects/meadow") {
    auto loaded = core::loadProject(project);
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = core::buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    exportRaw(*loaded, *scene, dir / "meadow");

    runtime::Field field;
    std::string error;
    ASSERT_TRUE(field.load(dir / "meadow", error)) << error;
    ASSERT_EQ(field.data().layers.size(), 1u);
    EXPECT_EQ(field.data().layers[0].liveBlades, scene->layers[0].liveBlades);
    const runtime::GeometryPath runtimePath = path == render::GeometryPath::Tessellation
                                                  ? runtime::GeometryPath::Tessellation
                                                  : runtime::GeometryPath::Strips;
    ASSERT_TRUE(field.setGeometry(runtimePath, error)) << error;
    EXPECT_EQ(field.geometry(), runtimePath);
    const gl::Rgba8Image ours = drawWithRuntime(field, loaded->project.render.msaaSamples);
    const std::size_t drawn = field.readStats().bladesDrawn;

    auto camera = render::projectCamera(loaded->project, "");
    ASSERT_TRUE(camera.ok());
    render::OffscreenRequest request;
    request.width = WIDTH;
    request.height = HEIGHT;
    request.msaaSamples = loaded->project.render.msaaSamples;
    request.frames = 1;
    request.options = render::renderOptionsFor(loaded->project, gl::isSoftwareRenderer());
    request.options.geometry = path;
    request.options.cull.collectStats = true;
    auto reference = render::renderOffscreen(*scene, *camera, request);
    ASSERT_TRUE(reference.ok()) << reference.error().str();
    ASSERT_EQ(ours.pixels.size(), reference->image.pixels.size());
    EXPECT_TRUE(writeRgba8Image(dir / "runtime.png", WIDTH, HEIGHT, ours.pixels).ok());
    EXPECT_TRUE(writeRgba8Image(dir / "grass_render.png", WIDTH, HEIGHT,
                                reference->image.pixels).ok());

    const ImageDifference diff = compareImages(ours.pixels, reference->image.pixels, PIXEL_THRESHOLD);
    const std::size_t referenceDrawn = reference->lastFrame.cull.drawn;
    std::printf("[ runtime ] meadow %dx%d, %s: differing %.4f, mean abs %.3f, max %d; blades "
                "drawn %zu (grass render %zu, occlusion culled %zu)\n",
                WIDTH, HEIGHT, path == render::GeometryPath::Tessellation ? "tessellation" : "strips",
                diff.differingShare, diff.meanAbs, diff.maxChannel, drawn, referenceDrawn,
                reference->lastFrame.cull.culledOcclusion);
    EXPECT_LE(diff.differingShare, MAX_DIFFERING_SHARE) << "pictures in " << dir;
    EXPECT_LE(diff.meanAbs, MAX_MEAN_ABS) << "pictures in " << dir;
    // Every blade the editor draws, the runtime draws too (it only lacks the occlusion test).
    EXPECT_EQ(drawn, referenceDrawn + reference->lastFrame.cull.culledOcclusion);
    // And the picture is a field, not the sky: most of its lower half is grass.
    EXPECT_GT(grassPixelShare(ours.pixels), 0.2);
}

TEST_F(RuntimeTest, DrawsTheMeadowAsGrassRenderDoes) {
    expectTheMeadowAsGrassRenderDraws(scratchDir("runtime_gl"), render::GeometryPath::Strips);
}

TEST_F(RuntimeTest, DrawsTheMeadowAsGrassRenderDoesWithTessellation) {
    expectTheMeadowAsGrassRenderDraws(scratchDir("runtime_gl_tess"),
                                      render::GeometryPath::Tessellation);
}

// An export lit by the simple model: the runtime compiles its blade programs with that model
// alone (GRASS_SIMPLE_LIGHTING), as the renderer picks its variant.
TEST_F(RuntimeTest, DrawsASimplyLitMeadowAsGrassRenderDoes) {
    const fs::path dir = scratchDir("runtime_gl_simple");
    const fs::path project = dir / "simple_meadow";
    fs::remove_all(project);
    fs::copy(sourceDir() / "projects/meadow", project, fs::copy_options::recursive);
    json document = json::parse(std::ifstream(project / "project.json"));
    document["lighting"]["model"] = "simple";
    std::ofstream(project / "project.json") << document.dump(2);
    expectTheMeadowAsGrassRenderDraws(dir, render::GeometryPath::Strips, project);
}

// The meadow, thinned to a few thousand blades so 300 CPU steps stay quick, with a vortex on a
// path added to its breeze and its rolling ball.
fs::path smallWindyMeadow(const fs::path& folder) {
    fs::remove_all(folder);
    fs::copy(sourceDir() / "projects/meadow", folder, fs::copy_options::recursive);
    json project = json::parse(std::ifstream(folder / "project.json"));
    project["layers"][0]["density"] = 12.0;
    project["wind"].push_back({{"name", "whirl"},
                               {"kind", "vortex"},
                               {"position", {2.0, 0.0, -2.0}},
                               {"direction", {1.0, 0.0, 0.0}},
                               {"axis", {0.0, 1.0, 0.0}},
                               {"strength", 6.0},
                               {"radius", 5.0},
                               {"core_radius", 1.0},
                               {"wavelength", 8.0},
                               {"speed", 3.0},
                               {"gust", 0.0},
                               {"path",
                                {{{"time", 0.0}, {"position", {2.0, 0.0, -2.0}}},
                                 {{"time", 5.0}, {"position", {-3.0, 0.0, 3.0}}}}}});
    std::ofstream(folder / "project.json") << project.dump(2);
    return folder;
}

// `project` grown, exported raw into `dir`/export and loaded by the runtime, with the CPU
// reference's physics of the same project.
struct LoadedRun {
    core::LoadedProject loaded;
    core::Scene scene;
    core::ScenePhysics physics;
    std::vector<core::Blade> rest;  // the blades as grown
    runtime::Field field;
};

bool loadRun(const fs::path& dir, LoadedRun& run, const fs::path& project) {
    auto loaded = core::loadProject(project);
    EXPECT_TRUE(loaded.ok()) << loaded.error().str();
    if (!loaded)
        return false;
    run.loaded = std::move(*loaded);
    auto scene = core::buildScene(run.loaded);
    EXPECT_TRUE(scene.ok()) << scene.error().str();
    auto physics = core::buildScenePhysics(run.loaded);
    EXPECT_TRUE(physics.ok()) << physics.error().str();
    if (!scene || !physics)
        return false;
    run.scene = std::move(*scene);
    run.physics = std::move(*physics);
    run.rest = run.scene.layers[0].patched.blades;
    exportRaw(run.loaded, run.scene, dir / "export");
    std::string error;
    const bool ok = run.field.load(dir / "export", error);
    EXPECT_TRUE(ok) << error;
    return ok;
}

struct TipError {
    float maxRelative = 0.0f;
    float maxMoveM = 0.0f;  // how far the CPU tips moved from rest: the run must bend the field
};

TipError compareTips(const std::vector<core::Blade>& gpu, const std::vector<core::Blade>& cpu,
                     const std::vector<core::Blade>& rest) {
    TipError error;
    for (std::size_t i = 0; i < cpu.size(); ++i) {
        const float h = cpu[i].h();
        if (h <= 0.0f)
            continue;
        error.maxRelative =
            std::max(error.maxRelative, glm::length(gpu[i].v2() - cpu[i].v2()) / h);
        error.maxMoveM = std::max(error.maxMoveM, glm::length(cpu[i].v2() - rest[i].v2()));
    }
    return error;
}

// Tolerance: the CPU/GPU agreement of the physics (physics_gl_test.cpp), 1e-3·h on every tip.
TEST_F(RuntimeTest, PhysicsAfterFiveSecondsMatchesTheCpuReference) {
    LoadedRun run;
    const fs::path dir = scratchDir("runtime_gl_physics");
    ASSERT_TRUE(loadRun(dir, run, smallWindyMeadow(dir / "project")));
    core::Scene* scene = &run.scene;
    runtime::Field& field = run.field;
    ASSERT_GT(scene->layers[0].liveBlades, 1000u);
    ASSERT_EQ(field.data().wind.size(), 2u);
    ASSERT_EQ(field.data().colliders.size(), 1u);
    const core::ScenePhysics* physics = &run.physics;
    core::SceneSimulation simulation(*scene, *physics, 2);
    const int steps = static_cast<int>(std::lround(5.0 / double(physics->params.dtS)));
    for (int i = 0; i < steps; ++i) {
        simulation.step();
        field.step();
    }
    EXPECT_FLOAT_EQ(field.timeS(), simulation.timeS());
    const TipError tips =
        compareTips(field.readBlades(0), scene->layers[0].patched.blades, run.rest);
    std::printf("[ runtime ] %zu blades, %d steps: max |v2_runtime - v2_cpu| / h = %.3g, tips "
                "moved up to %.3f m\n",
                scene->layers[0].liveBlades, steps, double(tips.maxRelative),
                double(tips.maxMoveM));
    EXPECT_GT(tips.maxMoveM, 0.05f);
    EXPECT_LT(tips.maxRelative, 1e-3f);
}

// A collider the host moves each frame (moveCollider) crushes the blades as a collider standing
// there in the CPU reference does, and its path no longer counts.
TEST_F(RuntimeTest, ACollidersHostPositionDrivesThePhysics) {
    LoadedRun run;
    const fs::path dir = scratchDir("runtime_gl_host_collider");
    ASSERT_TRUE(loadRun(dir, run, smallWindyMeadow(dir / "project")));
    core::Scene* scene = &run.scene;
    runtime::Field& field = run.field;
    const core::ScenePhysics* physics = &run.physics;
    // The host drags the ball along a line of its own (not the project's path), sunk 0.3 m
    // into the grass; the CPU reference gets the same positions step by step.
    ASSERT_EQ(physics->colliders.size(), 1u);
    core::SceneSimulation simulation(*scene, *physics, 2);
    for (int i = 0; i < 120; ++i) {
        const float x = -4.0f + 0.05f * float(i);
        const glm::vec3 origin(x, 0.7f, -1.0f);
        field.moveCollider(0, origin);
        EXPECT_EQ(field.colliderOrigin(0), origin);
        simulation.physics().colliders[0].centre = origin;
        simulation.physics().colliders[0].path.clear();
        simulation.step();
        field.step();
    }
    const TipError tips =
        compareTips(field.readBlades(0), scene->layers[0].patched.blades, run.rest);
    std::printf("[ runtime ] host-moved collider: max |v2_runtime - v2_cpu| / h = %.3g\n",
                double(tips.maxRelative));
    EXPECT_LT(tips.maxRelative, 1e-3f);
    // And it did press the grass where the host put it: under its last position the lowest tip
    // stands at under half its blade's height (at rest the meadow's blades stand at 0.7–1 h).
    const glm::vec3 last(-4.0f + 0.05f * 119.0f, 0.7f, -1.0f);
    float lowest = 1.0f;
    const std::vector<core::Blade> blades = field.readBlades(0);
    for (const core::Blade& blade : blades)
        if (blade.h() > 0.0f && glm::distance(glm::vec2(blade.v0().x, blade.v0().z),
                                              glm::vec2(last.x, last.z)) < 0.5f)
            lowest = std::min(lowest, glm::dot(blade.v2() - blade.v0(), blade.up()) / blade.h());
    EXPECT_LT(lowest, 0.5f);
    // Released, it follows its path again.
    field.releaseCollider(0);
    EXPECT_EQ(field.colliderOrigin(0),
              core::samplePath(field.data().colliders[0].path, field.timeS(),
                               field.data().colliders[0].origin));
}

// A packed mesh collider (tests/data/projects/rock: a cube as 16 spheres behind one bounding
// sphere, sliding through the field) travels as spheres with their group and moves the same.
TEST_F(RuntimeTest, APackedMeshColliderMatchesTheCpuReference) {
    const fs::path dir = scratchDir("runtime_gl_rock");
    fs::remove_all(dir / "project");
    fs::copy(sourceDir() / "tests/data/projects/rock", dir / "project",
             fs::copy_options::recursive);  // the packing cache lands next to the copy
    LoadedRun run;
    ASSERT_TRUE(loadRun(dir, run, dir / "project"));
    ASSERT_EQ(run.field.data().colliders.size(), 1u);
    EXPECT_EQ(run.field.data().colliders[0].sphereCount, run.physics.colliders.size());
    EXPECT_GT(run.physics.colliders.size(), 1u);
    EXPECT_EQ(run.field.data().spheres.front().groupSize, run.physics.colliders.front().groupSize);
    core::SceneSimulation simulation(run.scene, run.physics, 2);
    const int steps = static_cast<int>(std::lround(1.0 / double(run.physics.params.dtS)));
    for (int i = 0; i < steps; ++i) {
        simulation.step();
        run.field.step();
    }
    const TipError tips =
        compareTips(run.field.readBlades(0), run.scene.layers[0].patched.blades, run.rest);
    std::printf("[ runtime ] packed cube, %d steps: max |v2_runtime - v2_cpu| / h = %.3g, tips "
                "moved up to %.3f m\n",
                steps, double(tips.maxRelative), double(tips.maxMoveM));
    EXPECT_GT(tips.maxMoveM, 0.05f);  // the cube did push the grass
    EXPECT_LT(tips.maxRelative, 1e-3f);
}

TEST_F(RuntimeTest, ABrokenExportIsRefusedNamingTheFile) {
    const fs::path dir = scratchDir("runtime_gl_broken");
    fs::remove_all(dir);
    fs::create_directories(dir);
    runtime::Field field;
    std::string error;
    EXPECT_FALSE(field.load(dir, error));
    EXPECT_NE(error.find("manifest.json"), std::string::npos) << error;

    std::ofstream(dir / "manifest.json") << R"({"format": "grass-raw-export", "layers": []})";
    error.clear();
    EXPECT_FALSE(field.load(dir, error));
    EXPECT_NE(error.find("no \"runtime\" block"), std::string::npos) << error;
}

}  // namespace
}  // namespace grass::test
