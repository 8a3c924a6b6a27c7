// The editor's UI plumbing between GLFW and the UI library: GLFW keys, modifiers and characters
// turned into ui::Input events (window.cpp's callbacks call the translators), and EditorUi, which
// owns the font atlas, the ui::Context and the GL backend, and runs one UI frame: input in
// points (the window's content scale is the pixels-per-point), the app's panels, tessellation,
// and drawing over the scene. Panels themselves live in panels.h.
#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/input_passes.h"
#include "gl/ui_renderer.h"
#include "ui/context.h"
#include "ui/font.h"
#include "ui/mesh.h"
#include "util/result.h"

namespace grass::editor {

class Window;
struct InputState;

// The UI key for a GLFW key code, if the UI reacts to it.
std::optional<ui::Key> uiKeyFor(int glfwKey);
ui::Modifiers uiModifiers(int glfwMods);
// Appends the UTF-8 encoding of a code point (GLFW's char callback gives code points); control
// characters and invalid code points are dropped, since the UI wants printable text only.
void appendUtf8(std::string& out, char32_t codepoint);

class EditorUi {
public:
    // Loads DejaVu Sans (fonts-dejavu-core) and the UI shaders; the error names what is missing.
    static Result<std::unique_ptr<EditorUi>> create();

    ui::Context& context() { return *mContext; }
    // Pixels per point of the frame begun last (the window's content scale).
    float pixelsPerPoint() const { return mPixelsPerPoint; }
    // This frame's input as UI passes (input_passes.h): one per button event, then the frame's
    // final state with its keys, text and wheel. The clipboard is read from the OS only when a
    // paste key arrives (reading it is an X round trip).
    // `sources` as uiPasses gives them: the InputState::buttonEvents index of each pass but the
    // last, and whether it is the event's or the keys typed before it.
    std::vector<ui::Input> passes(Window& window, const InputState& input, double timeS,
                                  std::vector<PassSource>* sources = nullptr);
    // Points per unit of the window's screen coordinates (its cursor positions): pixels on X11,
    // points on macOS and Wayland, so the framebuffer/window ratio over the content scale.
    static float pointsPerScreenUnit(Window& window);
    // Feeds one pass to the context (the fonts follow its pixels per point).
    void beginFrame(ui::Input pass);
    // Ends the frame, hands copied text to the OS clipboard and tessellates the shapes.
    const ui::Output& endFrame(Window& window);
    // Draws the last frame's meshes over whatever the bound (default) framebuffer holds.
    void draw(int framebufferWidth, int framebufferHeight);
    // One frame of the window with `lines` in its middle and nothing else, shown at once: what
    // the window says while the first field grows, before the editor's first frame (a large
    // mesh takes seconds, which a black window left the user to guess at).
    void showNotice(Window& window, std::initializer_list<std::string_view> lines);

private:
    EditorUi() = default;
    std::unique_ptr<ui::FontAtlas> mFonts;
    std::unique_ptr<ui::Context> mContext;
    std::unique_ptr<gl::UiRenderer> mRenderer;
    // Kept across frames so tessellation reuses its storage.
    std::vector<ui::Mesh> mMeshes;
    float mPixelsPerPoint = 1.0f;
};

}  // namespace grass::editor
