#include "app/editor_ui.h"

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>

#include "ui/tessellator.h"
#include "app/window.h"

namespace grass::editor {

std::optional<ui::Key> uiKeyFor(int glfwKey) {
    switch (glfwKey) {
    case GLFW_KEY_LEFT: return ui::Key::Left;
    case GLFW_KEY_RIGHT: return ui::Key::Right;
    case GLFW_KEY_UP: return ui::Key::Up;
    case GLFW_KEY_DOWN: return ui::Key::Down;
    case GLFW_KEY_HOME: return ui::Key::Home;
    case GLFW_KEY_END: return ui::Key::End;
    case GLFW_KEY_BACKSPACE: return ui::Key::Backspace;
    case GLFW_KEY_DELETE: return ui::Key::Delete;
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER: return ui::Key::Enter;
    case GLFW_KEY_ESCAPE: return ui::Key::Escape;
    case GLFW_KEY_TAB: return ui::Key::Tab;
    case GLFW_KEY_A: return ui::Key::A;
    case GLFW_KEY_C: return ui::Key::C;
    case GLFW_KEY_V: return ui::Key::V;
    case GLFW_KEY_X: return ui::Key::X;
    case GLFW_KEY_Z: return ui::Key::Z;
    case GLFW_KEY_Y: return ui::Key::Y;
    case GLFW_KEY_S: return ui::Key::S;
    case GLFW_KEY_N: return ui::Key::N;
    case GLFW_KEY_O: return ui::Key::O;
    default: return std::nullopt;
    }
}

ui::Modifiers uiModifiers(int glfwMods) {
    return {(glfwMods & GLFW_MOD_SHIFT) != 0, (glfwMods & GLFW_MOD_CONTROL) != 0,
            (glfwMods & GLFW_MOD_ALT) != 0};
}

void appendUtf8(std::string& out, char32_t cp) {
    if (cp < 0x20 || cp == 0x7f || (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff)
        return;
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xc0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3f));
    } else if (cp < 0x10000) {
        out += char(0xe0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3f));
        out += char(0x80 | (cp & 0x3f));
    } else {
        out += char(0xf0 | (cp >> 18));
        out += char(0x80 | ((cp >> 12) & 0x3f));
        out += char(0x80 | ((cp >> 6) & 0x3f));
        out += char(0x80 | (cp & 0x3f));
    }
}

Result<std::unique_ptr<EditorUi>> EditorUi::create() {
    std::unique_ptr<EditorUi> self(new EditorUi());
    std::string error;
    auto fonts = ui::FontAtlas::load(ui::FontAtlas::defaultFontPath(), &error);
    if (!fonts)
        return makeError(ui::FontAtlas::defaultFontPath().string(),
                         error + " (install fonts-dejavu-core)");
    self->mFonts = std::make_unique<ui::FontAtlas>(std::move(*fonts));
    self->mContext = std::make_unique<ui::Context>(*self->mFonts);
    auto renderer = gl::UiRenderer::create();
    if (!renderer)
        return renderer.error();
    self->mRenderer = std::make_unique<gl::UiRenderer>(std::move(*renderer));
    return self;
}

float EditorUi::pointsPerScreenUnit(Window& window) {
    int fbW = 0, fbH = 0, winW = 0, winH = 0;
    window.framebufferSize(&fbW, &fbH);
    window.windowSize(&winW, &winH);
    const float toPixels = winW > 0 ? float(fbW) / float(winW) : 1.0f;
    return toPixels / window.contentScale();
}

std::vector<ui::Input> EditorUi::passes(Window& window, const InputState& input, double timeS,
                                        std::vector<PassSource>* sources) {
    int fbW = 0, fbH = 0;
    window.framebufferSize(&fbW, &fbH);
    // Points = pixels / content scale; cursor positions come in screen coordinates
    // (pointsPerScreenUnit).
    const float ppp = window.contentScale();
    const float toPoints = pointsPerScreenUnit(window);
    ui::Input in;
    in.pixelsPerPoint = ppp;
    in.screenRect = {{0.0f, 0.0f}, {float(fbW) / ppp, float(fbH) / ppp}};
    in.timeS = timeS;
    in.hasPointer = input.cursorInside;
    in.pointerPos = ui::Vec2(float(input.cursorX), float(input.cursorY)) * toPoints;
    in.buttonDown = {input.leftDown, input.rightDown, input.middleDown};
    // One wheel step scrolls about three lines of 14 pt text, as most toolkits do.
    in.scrollDelta = ui::Vec2(float(input.scrollX), float(input.scrollSteps)) * 50.0f;
    in.text = input.typed;
    in.keys = input.keys;
    in.modifiers = input.modifiers;
    for (const ui::KeyEvent& key : input.keys)
        if (key.key == ui::Key::V && key.modifiers.ctrl)
            in.clipboardText = window.clipboard();
    std::vector<ButtonEvent> events = input.buttonEvents;
    for (ButtonEvent& e : events) {
        e.pos = e.pos * toPoints;
        if (e.timeS < 0.0)
            e.timeS = timeS;  // a script's event: it happens now
    }
    return uiPasses(in, events, sources);
}

void EditorUi::beginFrame(ui::Input pass) {
    if (pass.pixelsPerPoint != mPixelsPerPoint || mContext->frameNumber() == 0) {
        mFonts->setPixelsPerPoint(pass.pixelsPerPoint);  // re-rasterises the glyphs sharp
        mPixelsPerPoint = pass.pixelsPerPoint;
    }
    mContext->beginFrame(std::move(pass));
}

const ui::Output& EditorUi::endFrame(Window& window) {
    const ui::Output& out = mContext->endFrame();
    if (out.copiedText)
        window.setClipboard(*out.copiedText);
    ui::tessellate(out.shapes, *mFonts, out.pixelsPerPoint, mMeshes);
    return out;
}

void EditorUi::draw(int framebufferWidth, int framebufferHeight) {
    mRenderer->draw(mMeshes, *mFonts, {framebufferWidth, framebufferHeight}, mPixelsPerPoint);
}

void EditorUi::showNotice(Window& window, std::initializer_list<std::string_view> lines) {
    int fbW = 0, fbH = 0;
    window.framebufferSize(&fbW, &fbH);
    if (fbW <= 0 || fbH <= 0)
        return;
    ui::Input in;
    in.pixelsPerPoint = window.contentScale();
    in.screenRect = {{0.0f, 0.0f},
                     {float(fbW) / in.pixelsPerPoint, float(fbH) / in.pixelsPerPoint}};
    in.hasPointer = false;
    const ui::Rect screen = in.screenRect;
    beginFrame(std::move(in));
    ui::Painter painter = mContext->painter(ui::Layer::Foreground, screen);
    constexpr float LINE = 24.0f;  // points between the lines' centres
    ui::Vec2 at = screen.centre() - ui::Vec2(0.0f, 0.5f * LINE * float(lines.size() - 1));
    for (const std::string_view line : lines) {
        painter.text(at, line, 16.0f, ui::Color32::rgb(220, 220, 220), ui::Vec2(0.5f));
        at.y += LINE;
    }
    endFrame(window);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.106f, 0.106f, 0.106f, 1.0f);  // the panels' grey (Editor::render)
    glClear(GL_COLOR_BUFFER_BIT);
    draw(fbW, fbH);
    window.swapBuffers();
}

}  // namespace grass::editor
