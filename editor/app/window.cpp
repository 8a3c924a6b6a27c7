#include "app/window.h"

#include <algorithm>
#include <mutex>

#include "app/editor_ui.h"
#include "app/window_size.h"
#include "gl/debug_output.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

namespace grass::editor {

namespace {

// Window::wake comes from workers, which may end after the window is gone (a job's worker is
// joined when the editor's state goes, after its window): GLFW must not be called then.
std::mutex gWakeMutex;
bool gWindowOpen = false;

}  // namespace

struct WindowCallbacks {
    static Window* self(GLFWwindow* w) { return static_cast<Window*>(glfwGetWindowUserPointer(w)); }
    static void cursor(GLFWwindow* w, double x, double y) {
        ++self(w)->mEvents;
        InputState& input = self(w)->mInput;
        if (input.leftDown || input.middleDown || input.rightDown) {
            input.dragDx += x - input.cursorX;
            input.dragDy += y - input.cursorY;
        }
        if (input.leftDown && input.leftPath.size() < MAX_LEFT_PATH_POINTS)
            input.leftPath.emplace_back(float(x), float(y));
        input.cursorX = x;
        input.cursorY = y;
    }
    static void drop(GLFWwindow* w, int count, const char** paths) {
        ++self(w)->mEvents;
        for (int i = 0; i < count; ++i)
            if (paths[i])
                self(w)->mInput.dropped.emplace_back(paths[i]);
    }
    static void enter(GLFWwindow* w, int entered) {
        ++self(w)->mEvents;
        self(w)->mInput.cursorInside = entered != 0;
    }
    static void character(GLFWwindow* w, unsigned int codepoint) {
        ++self(w)->mEvents;
        appendUtf8(self(w)->mInput.typed, char32_t(codepoint));
    }
    static void button(GLFWwindow* w, int button, int action, int mods) {
        ++self(w)->mEvents;
        InputState& input = self(w)->mInput;
        const bool down = action == GLFW_PRESS;
        if (button == GLFW_MOUSE_BUTTON_LEFT) {
            input.leftDown = down;
            input.leftPressed = input.leftPressed || down;
        }
        if (button == GLFW_MOUSE_BUTTON_MIDDLE)
            input.middleDown = down;
        if (button == GLFW_MOUSE_BUTTON_RIGHT)
            input.rightDown = down;
        const int uiButton = button == GLFW_MOUSE_BUTTON_LEFT    ? 0
                             : button == GLFW_MOUSE_BUTTON_RIGHT ? 1
                             : button == GLFW_MOUSE_BUTTON_MIDDLE ? 2
                                                                  : -1;
        if (uiButton >= 0)
            input.buttonEvents.push_back(
                {uiButton, down, ui::Vec2(float(input.cursorX), float(input.cursorY)),
                 self(w)->nowS(), input.typed.size(), input.leftPath.size(), input.keys.size()});
        input.shiftDown = (mods & GLFW_MOD_SHIFT) != 0;
        input.modifiers = uiModifiers(mods);
    }
    static void scroll(GLFWwindow* w, double dx, double dy) {
        ++self(w)->mEvents;
        self(w)->mInput.scrollSteps += dy;
        self(w)->mInput.scrollX += dx;
    }
    static void key(GLFWwindow* w, int key, int, int action, int mods) {
        ++self(w)->mEvents;
        InputState& input = self(w)->mInput;
        input.shiftDown =
            (mods & GLFW_MOD_SHIFT) != 0 ||
            (action != GLFW_RELEASE && (key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT));
        input.modifiers = uiModifiers(mods);
        if (action != GLFW_RELEASE)
            if (const auto uiKey = uiKeyFor(key))
                input.keys.push_back({*uiKey, input.modifiers, input.typed.size()});
        if (action == GLFW_PRESS && key == GLFW_KEY_F)
            input.frameRequested = true;
        if (action == GLFW_PRESS && key >= GLFW_KEY_1 && key <= GLFW_KEY_4)
            input.toggledCullTest = key - GLFW_KEY_1 + 1;
        if (action == GLFW_PRESS && key == GLFW_KEY_T)
            input.nextTechnique = true;
        if (action == GLFW_PRESS && key == GLFW_KEY_L)
            input.toggleLighting = true;
        // Escape closes popups and text edits first; the app closes the window only when the
        // UI did not take it (and asks about unsaved changes).
        if (action == GLFW_PRESS && key == GLFW_KEY_ESCAPE)
            input.escapePressed = true;
    }
};

static void onGlfwError(int, const char*) {
    // Reported through Result by create(); GLFW's own message would be a second line.
}

Result<std::unique_ptr<Window>> Window::create(int width, int height, const std::string& title,
                                               bool debugOutput, bool fitToScreen) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        return makeError("grass-editor",
                         "cannot open a window: no display (set DISPLAY, or run "
                         "under xvfb-run; 'grass render' renders without one)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debugOutput ? GLFW_TRUE : GLFW_FALSE);
    if (GLFWmonitor* monitor = fitToScreen ? glfwGetPrimaryMonitor() : nullptr) {
        int areaX = 0, areaY = 0, areaWidth = 0, areaHeight = 0;
        glfwGetMonitorWorkarea(monitor, &areaX, &areaY, &areaWidth, &areaHeight);
        float scaleX = 1.0f, scaleY = 1.0f;
        glfwGetMonitorContentScale(monitor, &scaleX, &scaleY);
        const WindowSize fitted =
            fitWindowSize({width, height}, areaWidth, areaHeight, std::max(scaleX, scaleY));
        width = fitted.width;
        height = fitted.height;
    }
    GLFWwindow* handle = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!handle) {
        const char* why = nullptr;
        glfwGetError(&why);
        glfwTerminate();
        return makeError("grass-editor", std::string("cannot create an OpenGL 4.5 core window: ") +
                                             (why ? why : "unknown reason"));
    }
    std::unique_ptr<Window> window(new Window());
    window->mWindow = handle;
    window->mOpenedS = glfwGetTime();
    glfwSetWindowUserPointer(handle, window.get());
    // Dragged smaller than the panels are laid out for, the timeline and the status bar ran off
    // the window's edge (window_size.h).
    int createdWidth = 0, createdHeight = 0;
    window->windowSize(&createdWidth, &createdHeight);
    const float pointsPerUnit = EditorUi::pointsPerScreenUnit(*window);
    const WindowSize least = leastWindowSize({createdWidth, createdHeight},
                                             pointsPerUnit > 0.0f ? 1.0f / pointsPerUnit : 1.0f);
    glfwSetWindowSizeLimits(handle, least.width, least.height, GLFW_DONT_CARE, GLFW_DONT_CARE);
    glfwSetCursorPosCallback(handle, WindowCallbacks::cursor);
    glfwSetMouseButtonCallback(handle, WindowCallbacks::button);
    glfwSetScrollCallback(handle, WindowCallbacks::scroll);
    glfwSetKeyCallback(handle, WindowCallbacks::key);
    glfwSetCharCallback(handle, WindowCallbacks::character);
    glfwSetCursorEnterCallback(handle, WindowCallbacks::enter);
    glfwSetDropCallback(handle, WindowCallbacks::drop);
    glfwMakeContextCurrent(handle);
    glfwSwapInterval(1);
    if (debugOutput)
        gl::enableDebugOutput();
    glfwGetCursorPos(handle, &window->mInput.cursorX, &window->mInput.cursorY);
    std::lock_guard lock(gWakeMutex);
    gWindowOpen = true;
    return window;
}

Window::~Window() {
    {
        std::lock_guard lock(gWakeMutex);
        gWindowOpen = false;
    }
    glfwDestroyWindow(mWindow);
    glfwTerminate();
}

bool Window::shouldClose() const {
    return glfwWindowShouldClose(mWindow) != 0;
}
void Window::requestClose() {
    glfwSetWindowShouldClose(mWindow, GLFW_TRUE);
}
void Window::cancelClose() {
    glfwSetWindowShouldClose(mWindow, GLFW_FALSE);
}
void Window::setTitle(const std::string& title) {
    glfwSetWindowTitle(mWindow, title.c_str());
}
void Window::swapBuffers() {
    glfwSwapBuffers(mWindow);
}
double Window::nowS() const {
    return glfwGetTime() - mOpenedS;
}
void Window::framebufferSize(int* width, int* height) const {
    glfwGetFramebufferSize(mWindow, width, height);
}
void Window::windowSize(int* width, int* height) const {
    glfwGetWindowSize(mWindow, width, height);
}
float Window::contentScale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(mWindow, &x, &y);
    return x > 0.0f ? x : 1.0f;
}
std::string Window::clipboard() const {
    const char* text = glfwGetClipboardString(mWindow);
    return text ? std::string(text) : std::string();
}
void Window::setClipboard(const std::string& text) {
    glfwSetClipboardString(mWindow, text.c_str());
}

void Window::hide() {
    glfwHideWindow(mWindow);
}

void Window::gatherEvents() {
    glfwPollEvents();
}

void Window::waitForEvents(double timeoutS) {
    if (timeoutS > 0.0)
        glfwWaitEventsTimeout(timeoutS);
    else
        glfwPollEvents();  // GLFW takes no zero wait
}

void Window::wake() {
    std::lock_guard lock(gWakeMutex);
    if (gWindowOpen)
        glfwPostEmptyEvent();
}

InputState Window::pollInput() {
    glfwPollEvents();
    mInput.minimised = glfwGetWindowAttrib(mWindow, GLFW_ICONIFIED) != 0;
    const InputState gathered = mInput;
    // What happened since: the next call starts from the held buttons and the cursor alone.
    mInput.dragDx = mInput.dragDy = mInput.scrollSteps = mInput.scrollX = 0.0;
    mInput.leftPressed = mInput.escapePressed = false;
    mInput.typed.clear();
    mInput.buttonEvents.clear();
    mInput.leftPath.clear();
    mInput.keys.clear();
    mInput.dropped.clear();
    mInput.frameRequested = false;
    mInput.toggledCullTest = 0;
    mInput.nextTechnique = mInput.toggleLighting = false;
    return gathered;
}

}  // namespace grass::editor
