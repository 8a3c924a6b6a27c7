// The editor window, seen without a person: grass-editor --screenshot --no-ui under Xvfb must
// show the same picture `grass render` writes headless for the same project, and with its UI
// the window must show both the side panel and the grass in the viewport.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl_context_fixture.h"
#include "render/offscreen_render.h"
#include "scene/scene_physics.h"
#include "support/gltf_writer.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

using EditorScreenshotTest = GlTest;

TEST_F(EditorScreenshotTest, WindowUnderXvfbShowsWhatHeadlessRenderShows) {
    const auto dir = scratchDir("editor_screenshot");
    std::ofstream(dir / "project.json") << R"({
  "format": "grass-project", "version": 1, "name": "tiny",
  "mesh": {"procedural": "plane", "size": 3, "resolution": 4},
  "layers": [{"name": "grass", "density": 400}],
  "cameras": [{"name": "near", "position": [2.5, 1.6, 2.5], "target": [0, 0.2, 0]}],
  "render": {"width": 320, "height": 240, "geometry": "strips", "msaa": 4}
})";
    const std::string shot = (dir / "window.png").string();
    const std::string command = "xvfb-run -a -s '-screen 0 640x480x24' " +
                                std::string(GRASS_EDITOR_EXE) + " --gl-debug " + dir.string() +
                                " --no-ui --screenshot " + shot + " --frames 2 > " +
                                (dir / "log.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    expectNoGlErrorLines(dir / "log.txt");
    ASSERT_EQ(status, 0) << command << "\n(see " << (dir / "log.txt")
                         << "; needs the xvfb package)";
    auto window = readRgba8Image(shot);
    ASSERT_TRUE(window.ok()) << window.error().str();
    ASSERT_EQ(window->width, 320);
    ASSERT_EQ(window->height, 240);

    auto loaded = core::loadProject(dir);
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = core::buildScene(*loaded);
    ASSERT_TRUE(scene.ok());
    // The editor runs the physics live, one step per frame when taking a screenshot: the
    // reference takes the same two steps on the CPU (the GPU agrees to 1e-5·h, physics_gl_test).
    auto physics = core::buildScenePhysics(*loaded);
    ASSERT_TRUE(physics.ok()) << physics.error().str();
    core::SceneSimulation simulation(*scene, *physics);
    simulation.step();
    simulation.step();
    render::OffscreenRequest request;
    request.width = 320;
    request.height = 240;
    request.frames = 1;
    request.options = render::renderOptionsFor(loaded->project, true);
    auto headless =
        render::renderOffscreen(*scene, *render::projectCamera(loaded->project, ""), request);
    ASSERT_TRUE(headless.ok()) << headless.error().str();

    // Same scene, camera, renderer (llvmpipe under both GLX and EGL), so the pictures match
    // closely; a window that shows nothing, the wrong camera or no grass differs in most
    // pixels. Tolerance: mean absolute difference under 3/255 per channel (MSAA resolve
    // paths may differ slightly between a window and an offscreen target).
    double sum = 0.0;
    for (std::size_t i = 0; i < window->pixels.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c)
            sum += std::abs(int(window->pixels[i + c]) - int(headless->image.pixels[i + c]));
    const double mean = sum / (static_cast<double>(window->pixels.size() / 4) * 3.0);
    EXPECT_LT(mean, 3.0);
    EXPECT_GT(grassPixelShare(window->pixels), 0.2);
}

// Mean sRGB colour of a region of an RGBA8 image (row 0 at the top).
glm::vec3 meanColor(const std::vector<std::uint8_t>& rgba, int width, int x0, int y0, int x1,
                    int y1) {
    glm::dvec3 sum(0.0);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
            sum += glm::dvec3(rgba[i], rgba[i + 1], rgba[i + 2]);
        }
    return glm::vec3(sum / double((x1 - x0) * (y1 - y0)));
}

TEST_F(EditorScreenshotTest, WindowShowsSidePanelAndGrassViewport) {
    const auto dir = scratchDir("editor_screenshot_ui");
    std::ofstream(dir / "project.json") << R"({
  "format": "grass-project", "version": 1, "name": "tiny",
  "mesh": {"procedural": "plane", "size": 3, "resolution": 4},
  "layers": [{"name": "grass", "density": 400}],
  "cameras": [{"name": "near", "position": [2.5, 1.6, 2.5], "target": [0, 0.2, 0]}],
  "render": {"width": 960, "height": 540, "geometry": "strips", "msaa": 4}
})";
    const std::string shot = (dir / "window.png").string();
    const std::string command = "xvfb-run -a -s '-screen 0 1280x720x24' " +
                                std::string(GRASS_EDITOR_EXE) + " --gl-debug " + dir.string() +
                                " --screenshot " + shot + " --frames 3 > " +
                                (dir / "log.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    expectNoGlErrorLines(dir / "log.txt");
    ASSERT_EQ(status, 0) << command << "\n(see " << (dir / "log.txt") << ")";
    auto window = readRgba8Image(shot);
    ASSERT_TRUE(window.ok()) << window.error().str();
    ASSERT_EQ(window->width, 960);
    ASSERT_EQ(window->height, 540);
    // The left panel (330 points wide at Xvfb's scale of 1): the UI's dark grey, with text.
    const glm::vec3 panel = meanColor(window->pixels, 960, 10, 60, 300, 500);
    EXPECT_LT(std::max({panel.r, panel.g, panel.b}), 70.0f) << "panel mean " << panel.r;
    EXPECT_LT(std::abs(panel.r - panel.g) + std::abs(panel.g - panel.b), 20.0f);
    // The viewport (right of the panel, between the menu and the status bar) shows grass.
    std::vector<std::uint8_t> view;
    for (int y = 60; y < 480; ++y)
        for (int x = 400; x < 940; ++x) {
            const std::size_t i = (std::size_t(y) * 960 + std::size_t(x)) * 4;
            view.insert(view.end(), window->pixels.begin() + std::ptrdiff_t(i),
                        window->pixels.begin() + std::ptrdiff_t(i + 4));
        }
    EXPECT_GT(grassPixelShare(view), 0.2);
}


// `grass-editor rock.glb`: a mesh given instead of a project starts a new, unsaved project
// around it, as File > New from mesh does; before, the editor refused it ("not a project").
// Nothing is written next to the mesh until the user saves.
TEST_F(EditorScreenshotTest, AMeshOnTheCommandLineStartsANewProjectAroundIt) {
    const auto dir = scratchDir("editor_screenshot_mesh");
    writeGltf(dir / "hill.glb", singleMeshAsset(gridPrimitive(6.0f, 6.0f, 8)), BufferStorage::Glb);
    const std::string shot = (dir / "window.png").string();
    const std::string command = "xvfb-run -a -s '-screen 0 1280x720x24' " +
                                std::string(GRASS_EDITOR_EXE) + " --gl-debug " +
                                (dir / "hill.glb").string() + " --no-ui --screenshot " + shot +
                                " --frames 2 > " + (dir / "log.txt").string() + " 2>&1";
    const int status = std::system(command.c_str());
    expectNoGlErrorLines(dir / "log.txt");
    ASSERT_EQ(status, 0) << command << "\n(see " << (dir / "log.txt") << ")";
    auto window = readRgba8Image(shot);
    ASSERT_TRUE(window.ok()) << window.error().str();
    EXPECT_GT(grassPixelShare(window->pixels), 0.05) << "the new field, framed";
    std::set<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        files.insert(entry.path().filename().string());
    EXPECT_EQ(files, (std::set<std::string>{"hill.glb", "log.txt", "window.png"}))
        << "nothing saved beside the mesh";
}

}  // namespace
}  // namespace grass::test
