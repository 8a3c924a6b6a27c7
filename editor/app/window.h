// Window: a GLFW window with an OpenGL 4.5 core context (the editor's only GLFW user). Input
// arrives through callbacks into an InputState the app reads once per frame: the camera's view
// of it (drags, wheel steps, shortcut keys) and the raw events the UI needs (editor_ui.h turns
// them into a ui::Input).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/input_passes.h"
#include "ui/context.h"
#include "util/result.h"

struct GLFWwindow;

namespace grass::editor {

struct InputState {
    double cursorX = 0.0, cursorY = 0.0;  // screen coordinates (GLFW's, not pixels)
    double dragDx = 0.0, dragDy = 0.0;  // cursor motion since last frame while a button is down
    double scrollSteps = 0.0;
    double scrollX = 0.0;  // horizontal wheel steps, for the UI only
    bool leftDown = false, middleDown = false, rightDown = false;
    bool shiftDown = false;
    // Pen pressure in [0, 1]: 1 for a mouse (GLFW reports no tablet pressure); scripts set it.
    float pressure = 1.0f;
    bool cursorInside = true;
    // A button went down this frame (the UI must see a press even if it was released again).
    bool leftPressed = false;
    // Every button change this frame, in order, at the window's screen coordinates and on
    // Window::nowS's clock (EditorUi turns them into UI passes, input_passes.h).
    std::vector<ButtonEvent> buttonEvents;
    // Where the pointer went while the left button was held this frame, in order (screen
    // coordinates): a brush stroke follows it however few frames it spans.
    std::vector<ui::Vec2> leftPath;
    bool frameRequested = false;  // F key: frame the selected object, else the whole scene
    // Keys 1–4: toggle the orientation, frustum, distance, occlusion cull tests; T: next grass
    // technique (blades, billboards, hybrid); L: grass lighting on/off.
    int toggledCullTest = 0;  // 1..4, 0 = none this frame
    bool nextTechnique = false;
    bool toggleLighting = false;
    bool escapePressed = false;
    // Files dropped on the window this frame (routeDroppedFiles, panels.h).
    std::vector<std::string> dropped;
    // For the UI: typed text (UTF-8), key presses and repeats, modifiers held now.
    std::string typed;
    std::vector<ui::KeyEvent> keys;
    ui::Modifiers modifiers;
    // The window is minimised (iconified): nothing of it is on screen. On X11 its framebuffer
    // keeps its size, so the 0×0 test alone kept a minimised window drawing while it played.
    bool minimised = false;
};

class Window {
public:
    // The error says there is no display and how to render without one. `debugOutput` asks for
    // a debug context whose messages go to stderr (gl/debug_output.h). `fitToScreen` makes a
    // window too large for the primary monitor's work area smaller (window_size.h).
    static Result<std::unique_ptr<Window>> create(int width, int height, const std::string& title,
                                                  bool debugOutput, bool fitToScreen = false);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    bool shouldClose() const;
    void requestClose();
    // Keeps the window open after the user asked to close it (the app asks to save first).
    void cancelClose();
    // Takes the window off the screen (the process may still have work to finish).
    void hide();
    void setTitle(const std::string& title);
    void swapBuffers();
    // Polls events; the returned input holds everything since the last call: this frame's
    // drags and scrolls, and the events gatherEvents() collected meanwhile.
    InputState pollInput();
    // Collects pending events into the next pollInput() without handing them out, so each is
    // stamped with the time it came in (its callback's nowS()) rather than the next frame's.
    // Called while a frame waits: GLFW reports events only when polled, and a double-click
    // whose second click was polled a slow frame after its first read as two single clicks.
    void gatherEvents();
    // Sleeps until an event comes (collected as gatherEvents does) or `timeoutS` has passed.
    void waitForEvents(double timeoutS);
    // Ends a waitForEvents at once; from any thread (a worker that finished), harmless once the
    // window is gone.
    static void wake();
    // How many input events (pointer, buttons, wheel, keys, text, drops) have come so far.
    std::uint64_t eventCount() const { return mEvents; }
    // Seconds since the window opened: the clock of input events and the UI.
    double nowS() const;
    void framebufferSize(int* width, int* height) const;
    // Window size in screen coordinates (what cursor positions are in).
    void windowSize(int* width, int* height) const;
    // The monitor's content scale (HiDPI factor, 1 on a plain screen).
    float contentScale() const;
    std::string clipboard() const;
    void setClipboard(const std::string& text);

private:
    Window() = default;
    GLFWwindow* mWindow = nullptr;
    InputState mInput;
    std::uint64_t mEvents = 0;
    double mOpenedS = 0.0;  // glfwGetTime() when the window opened
    friend struct WindowCallbacks;
};

}  // namespace grass::editor
