// grass-runtime-sample: the smallest host of the reference runtime (docs/runtime.md). It opens a
// raw export in a window, draws the export's terrain and props and the field, lets the first
// collider follow the mouse (left button held) and runs the physics in real time.
//   grass-runtime-sample EXPORT [--frames N] [--screenshot F.png] [--size WxH] [--time T]
// epoxy first: it replaces GL/gl.h, which GLFW would include otherwise.
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <stb/stb_image_write.h>

#include "runtime/grass_runtime.h"

namespace {

const char* USAGE =
    "usage: grass-runtime-sample EXPORT [--frames N] [--screenshot F.png] [--size WxH] [--time T]\n"
    "  EXPORT          a folder written by `grass export PROJECT --format raw --out EXPORT`\n"
    "  --frames N      draw N frames (physics one export step each), then exit\n"
    "  --screenshot F  write the last frame to the PNG file F (with --frames)\n"
    "  --size WxH      window size in pixels (default: the project's render size)\n"
    "  --time T        simulate T seconds before the first frame\n"
    "Hold the left mouse button to move the export's first collider over the field.\n";

struct Options {
    std::string folder;
    int frames = 0;  // 0: until the window is closed
    std::string screenshot;
    int width = 0, height = 0;
    float timeS = 0.0f;
};

int fail(const std::string& message) {
    std::fprintf(stderr, "grass-runtime-sample: %s\n", message.c_str());
    return 1;
}

bool parse(int argc, char** argv, Options& options, std::string& error) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                error = arg + ": needs a value";
                return {};
            }
            return argv[++i];
        };
        if (arg == "--frames") {
            const std::string v = value();
            options.frames = std::atoi(v.c_str());
            if (options.frames <= 0 && error.empty())
                error = "--frames: expected a whole number of frames > 0, got \"" + v + "\"";
        } else if (arg == "--screenshot") {
            options.screenshot = value();
        } else if (arg == "--size") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%dx%d", &options.width, &options.height) != 2 ||
                options.width < 16 || options.height < 16 || options.width > 8192 ||
                options.height > 8192)
                error = "--size: expected WxH from 16x16 to 8192x8192, got \"" + v + "\"";
        } else if (arg == "--time") {
            const std::string v = value();
            char* end = nullptr;
            options.timeS = std::strtof(v.c_str(), &end);
            if (end == v.c_str() || *end != '\0' || !(options.timeS >= 0.0f && options.timeS <= 3600.0f))
                error = "--time: expected seconds from 0 to 3600, got \"" + v + "\"";
        } else if (!arg.empty() && arg[0] == '-') {
            error = arg + ": unknown option";
        } else if (options.folder.empty()) {
            options.folder = arg;
        } else {
            error = arg + ": only one EXPORT folder";
        }
        if (!error.empty())
            return false;
    }
    if (options.folder.empty())
        error = "EXPORT: missing (a folder written by `grass export PROJECT --format raw`)";
    else if (!options.screenshot.empty() && options.frames == 0)
        error = "--screenshot: needs --frames N (the frame to write)";
    return error.empty();
}

// Where the mouse ray meets the horizontal plane at `height`; false when it points away.
bool mouseOnPlane(GLFWwindow* window, const grass::runtime::View& view, float height,
                  glm::vec3& hit) {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    int w = 1, h = 1;
    glfwGetWindowSize(window, &w, &h);
    const glm::vec2 ndc(2.0f * float(x) / float(w) - 1.0f, 1.0f - 2.0f * float(y) / float(h));
    const glm::mat4 inverse = glm::inverse(view.projection * view.view);
    const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 origin = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 direction = glm::vec3(farPoint) / farPoint.w - origin;
    if (std::abs(direction.y) < 1e-6f)
        return false;
    const float t = (height - origin.y) / direction.y;
    if (t <= 0.0f)
        return false;
    hit = origin + t * direction;
    return true;
}

bool writeScreenshot(const std::string& file, int width, int height) {
    std::vector<unsigned char> pixels(std::size_t(width) * std::size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    stbi_flip_vertically_on_write(1);  // GL's rows start at the bottom
    return stbi_write_png(file.c_str(), width, height, 4, pixels.data(), width * 4) != 0;
}

// Loads the export and draws it until the window closes or --frames are done; 0 on success.
int run(GLFWwindow* window, Options& options, grass::runtime::ExportData exported) {
    grass::runtime::Field field;
    if (std::string error; !field.load(std::move(exported), error)) {
        return fail(error);
    }
    const grass::runtime::ExportData& data = field.data();
    int fbWidth = 1, fbHeight = 1;

    // Simulated before the first frame, so a screenshot can show the field in motion.
    while (field.timeS() + 0.5f * data.physics.dtS < options.timeS)
        field.step();
    // The mouse moves collider 0 on the plane through its centre.
    const bool hasCollider = !data.colliders.empty();
    const float colliderHeight = hasCollider ? field.colliderOrigin(0).y : 0.0f;
    if (!hasCollider)
        std::fprintf(stderr, "note: the export has no collider for the mouse to move\n");

    bool movedByMouse = false;
    std::vector<double> frameMs;
    auto last = std::chrono::steady_clock::now();
    for (int frame = 0; !glfwWindowShouldClose(window); ++frame) {
        glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
        const grass::runtime::View view = grass::runtime::exportCameraView(data, fbWidth, fbHeight);
        glm::vec3 hit;
        if (hasCollider && glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS &&
            mouseOnPlane(window, view, colliderHeight, hit)) {
            field.moveCollider(0, hit);
            movedByMouse = true;
        }

        const auto now = std::chrono::steady_clock::now();
        const float elapsedS = std::chrono::duration<float>(now - last).count();
        last = now;
        // --frames: one physics step a frame, so runs repeat exactly; else real time.
        options.frames > 0 ? field.step() : field.update(elapsedS);

        glViewport(0, 0, fbWidth, fbHeight);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_MULTISAMPLE);
        const glm::vec3 sky = data.render.skyColor;
        glClearColor(sky.r, sky.g, sky.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        field.drawMeshes(view);
        field.draw(view);
        glFinish();
        frameMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - now).count());

        const bool lastFrame = options.frames > 0 && frame + 1 >= options.frames;
        if (lastFrame && !options.screenshot.empty() &&
            !writeScreenshot(options.screenshot, fbWidth, fbHeight)) {
            return fail(options.screenshot + ": cannot write the PNG");
        }
        glfwSwapBuffers(window);
        glfwPollEvents();
        if (lastFrame)
            break;
    }
    std::sort(frameMs.begin(), frameMs.end());
    const grass::runtime::DrawStats stats = field.readStats();
    std::size_t liveBlades = 0;
    for (const grass::runtime::LayerData& layer : data.layers)
        liveBlades += layer.liveBlades;
    std::printf("frames %zu, median frame %.1f ms, simulated %.2f s, blades drawn %zu of %zu\n",
                frameMs.size(), frameMs.empty() ? 0.0 : frameMs[frameMs.size() / 2],
                double(field.timeS()), stats.bladesDrawn, liveBlades);
    if (hasCollider) {
        const glm::vec3 at = field.colliderOrigin(0);
        std::printf("collider \"%s\" at (%.3f, %.3f, %.3f), %s\n", data.colliders[0].name.c_str(),
                    double(at.x), double(at.y), double(at.z),
                    movedByMouse ? "moved by the mouse" : "on its path");
    }
    if (!options.screenshot.empty())
        std::printf("wrote %s (%dx%d)\n", options.screenshot.c_str(), fbWidth, fbHeight);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
            std::fputs(USAGE, stdout);
            return 0;
        }
    Options options;
    if (std::string error; !parse(argc, argv, options, error))
        return fail(error + " (grass-runtime-sample --help lists the options)");

    // The export is read before any window opens, so a wrong folder fails at once, anywhere.
    grass::runtime::ExportData data;
    if (std::string error; !grass::runtime::readExport(options.folder, data, error))
        return fail(error);

    if (!glfwInit())
        return fail("cannot open a window (no display? run it under xvfb-run)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_SAMPLES, 4);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    // The project's render size unless --size says otherwise.
    const int width = options.width > 0 ? options.width : data.render.width;
    const int height = options.height > 0 ? options.height : data.render.height;
    GLFWwindow* window = glfwCreateWindow(width, height, "grass runtime sample", nullptr, nullptr);
    if (window == nullptr) {
        glfwTerminate();
        return fail("cannot create a GL 4.5 core window");
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(options.frames > 0 ? 0 : 1);

    // The field's GL objects go before the context does.
    const int status = run(window, options, std::move(data));
    glfwTerminate();
    return status;
}
