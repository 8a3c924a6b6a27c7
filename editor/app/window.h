// Window: a GLFW window with an OpenGL 4.5 core context (the editor's only GLFW user). Input
// arrives through callbacks into an InputState the app reads once per frame.
#pragma once

#include <memory>
#include <string>

#include "util/result.h"

struct GLFWwindow;

namespace grass::editor {

struct InputState {
    double cursorX = 0.0, cursorY = 0.0;
    double dragDx = 0.0, dragDy = 0.0;  // cursor motion since last frame while a button is down
    double scrollSteps = 0.0;
    bool leftDown = false, middleDown = false, rightDown = false;
    bool shiftDown = false;
    bool frameRequested = false;  // F key: frame the whole scene
    // Keys 1–4: toggle the orientation, frustum, distance, occlusion cull tests; T: next grass
    // technique (blades, billboards, hybrid); L: grass lighting on/off.
    int toggledCullTest = 0;  // 1..4, 0 = none this frame
    bool nextTechnique = false;
    bool toggleLighting = false;
};

class Window {
public:
    // The error says there is no display and how to render without one.
    static Result<std::unique_ptr<Window>> create(int width, int height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    bool shouldClose() const;
    void requestClose();
    void setTitle(const std::string& title);
    void swapBuffers();
    // Polls events; the returned input holds this frame's drags and scrolls.
    InputState pollInput();
    void framebufferSize(int* width, int* height) const;

private:
    Window() = default;
    GLFWwindow* mWindow = nullptr;
    InputState mInput;
    friend struct WindowCallbacks;
};

}  // namespace grass::editor
