// The editor's input each frame: the UI first, then the viewport's tools, the camera and the
// keys (editor.h describes the whole frame).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "app/editor_keys.h"
#include "app/editor.h"
#include "app/viewport_tools.h"

namespace grass::editor {

namespace {

// F frames `selection` when there is one, else the whole scene.
void moveCamera(InputState input, bool drag, bool wheel, int viewportHeight,
                const core::Scene& scene, const std::optional<core::Bounds>& selection,
                core::OrbitCamera& camera) {
    if (!drag)
        input.leftDown = input.middleDown = false;
    if (!wheel)
        input.scrollSteps = 0.0;
    const bool panning = input.middleDown || (input.leftDown && input.shiftDown);
    if (panning)
        camera.pan(static_cast<float>(input.dragDx), static_cast<float>(input.dragDy),
                   static_cast<float>(viewportHeight));
    else if (input.leftDown)
        camera.orbit(static_cast<float>(input.dragDx), static_cast<float>(input.dragDy));
    if (input.scrollSteps != 0.0)
        camera.zoom(static_cast<float>(input.scrollSteps));
    if (input.frameRequested)
        camera = core::frameBounds(selection ? *selection : scene.bounds, camera.fovYRad);
    // Keep the depth range proportional to the distance so zooming never clips the field.
    camera.nearPlane = std::max(camera.distance * 1e-3f, 1e-4f);
    camera.farPlane = camera.distance * 20.0f + 100.0f;
}

// A change of the left button during the frame, for the viewport's tools: the event (its place
// in UI points, how much of the frame's typed text and left-button path came before it),
// whether the UI took it, and the viewport's rect in that pass.
struct LeftButtonStep {
    ui::Vec2 at;
    bool down = false;
    KeysTaken keysBefore;
    std::size_t pathBefore = 0;
    bool uiTook = false;
    ui::Rect central;
};

// The viewport's pointer at `at` (UI points) for a viewport at `central`.
void placePointer(ViewportPointer& pointer, ui::Vec2 at, ui::Rect central, float ppp) {
    pointer.pixel = glm::vec2(at.x - central.min.x, at.y - central.min.y) * ppp;
    pointer.viewportSize = glm::vec2(central.width(), central.height()) * ppp;
}

PixelRect toPixels(ui::Rect r, float ppp, int framebufferHeight) {
    PixelRect p;
    p.x = int(std::lround(r.min.x * ppp));
    p.w = std::max(1, int(std::lround(r.max.x * ppp)) - p.x);
    const int top = int(std::lround(r.min.y * ppp));
    p.h = std::max(1, int(std::lround(r.max.y * ppp)) - top);
    p.y = framebufferHeight - top - p.h;
    return p;
}

}  // namespace

void Editor::runInput(InputState input, int width, int height) {
    if (!input.dropped.empty())
        routeDroppedFiles(mState, input.dropped);
    // The UI first: it decides who gets the pointer and the keys this frame.
    const Clock::time_point uiStart = Clock::now();
    mView = PixelRect{0, 0, width, height};
    bool uiPointer = false, uiKeyboard = false;
    bool pressOnUi = false;  // a press this frame that a panel took (not the viewport's)
    // The frame's keys and text that are the viewport's, in order: those typed while no field
    // had the keyboard (each piece of a frame reaches the UI in a pass of its own, before the
    // click that follows it: input_passes.h), no dialog is open and no document is loading
    // (applyEditorKeys waits then). Without the UI, all of them.
    const bool keysMayBeTheViewports = !mState.transient.browser && !mState.loading();
    InputState viewportKeys = input;
    bool keysAllTheViewports = true;  // no piece went to a field (the render keys' flags go too)
    if (mUi) {
        viewportKeys.typed.clear();
        viewportKeys.keys.clear();
    }
    const auto takeKeys = [&](const ui::Input& piece, bool theViewports) {
        if (piece.text.empty() && piece.keys.empty())
            return;
        keysAllTheViewports = keysAllTheViewports && theViewports;
        if (!theViewports)
            return;
        for (ui::KeyEvent key : piece.keys) {
            if (key.textBefore != std::string::npos)
                key.textBefore += viewportKeys.typed.size();
            viewportKeys.keys.push_back(key);
        }
        viewportKeys.typed += piece.text;
    };
    const auto noFieldHasTheKeyboard = [&] { return mUi->context().focusedId().value == 0; };
    std::vector<LeftButtonStep> leftSteps;
    KeysTaken keysTaken;  // the viewport's keys applied before the frame's presses
    ui::Rect central;
    float ppp = 1.0f;
    ViewportPointer pointer;
    mState.view.camera = mCamera;
    if (mUi) {
        // One UI pass per button event and per piece of keys typed before one (input_passes.h),
        // the last one drawn.
        std::vector<PassSource> sources;
        std::vector<ui::Input> passes = mUi->passes(*mWindow, input, mWindow->nowS(), &sources);
        for (std::size_t i = 0; i + 1 < passes.size(); ++i) {
            // Each pass but the last is one button's change (a repeat makes none) or the keys
            // typed before it.
            const ButtonEvent& event = input.buttonEvents[sources[i].event];
            const ui::Vec2 eventAt = passes[i].pointerPos;
            if (sources[i].keysBefore)
                takeKeys(passes[i], keysMayBeTheViewports && noFieldHasTheKeyboard());
            mUi->beginFrame(std::move(passes[i]));
            const ui::Rect passCentral = buildPanels(mUi->context(), mState);
            const bool uiWantsPointer = mUi->context().endFrame().wantsPointer;
            if (event.button != 0 || sources[i].keysBefore)
                continue;
            pressOnUi = pressOnUi || (event.down && uiWantsPointer);
            leftSteps.push_back({eventAt,
                                 event.down,
                                 {viewportKeys.keys.size(), viewportKeys.typed.size()},
                                 std::min(event.pathBefore, input.leftPath.size()),
                                 uiWantsPointer,
                                 passCentral});
        }
        // The last piece is the viewport's when no field had the keyboard before or after it.
        const bool lastKeysMayBeTheViewports = keysMayBeTheViewports && noFieldHasTheKeyboard();
        ui::Input lastKeys;
        lastKeys.text = passes.back().text;
        lastKeys.keys = passes.back().keys;
        mUi->beginFrame(std::move(passes.back()));
        central = buildPanels(mUi->context(), mState);
        ppp = mUi->pixelsPerPoint();
        const ui::Vec2 at = mUi->context().pointerPos();
        placePointer(pointer, at, central, ppp);
        pointer.inside = input.cursorInside && central.contains(at);
        drawViewportOverlay(mUi->context(), central, ppp, mState, mCamera, pointer);
        const ui::Output& out = mUi->endFrame(*mWindow);
        uiPointer = out.wantsPointer;
        uiKeyboard = out.wantsKeyboard;
        takeKeys(lastKeys, lastKeysMayBeTheViewports && !uiKeyboard);
        mPanelsChangeInS = out.repaintAfterS;
        mView = toPixels(central, out.pixelsPerPoint, height);
        // A camera bookmark chosen in the panel: the view goes there.
        if (mState.view.cameraRequest) {
            mCamera = *mState.view.cameraRequest;
            mState.view.cameraRequest.reset();
        }
        mState.transient.status.uiMs =
            std::chrono::duration<double, std::milli>(Clock::now() - uiStart).count();
    }
    // A button that went down or came up during the frame was held for part of it: at 1–3
    // frames a second a whole flick (press, move, release) fits in one frame, and a drag's last
    // stretch comes with its release. Both move the camera (dragDx holds the motion up to the
    // release) and reach the tools (one step per left-button change, at its place).
    bool leftHeld = input.leftDown, middleHeld = input.middleDown, rightHeld = input.rightDown;
    for (const ButtonEvent& e : input.buttonEvents) {
        leftHeld = leftHeld || e.button == 0;
        rightHeld = rightHeld || e.button == 1;
        middleHeld = middleHeld || e.button == 2;
    }
    // The viewport's tools: a press on the mesh (brush) or on an object (gizmo) makes the drag
    // theirs; the camera orbits with the right button meanwhile.
    bool toolUsed = false;
    bool leftIsTools = mToolDrag || mState.view.toolDragActive;
    bool pressStepped = false;  // a press went to the tools at its own place (a step below)
    if (mUi) {
        pointer.ctrl = input.modifiers.ctrl;
        pointer.shift = input.modifiers.shift;
        pointer.pressure = input.pressure;
        const auto runTool = [&](const ViewportPointer& p) {
            const bool used = runViewportTool(mState, mCamera, p);
            if (used && p.pressed)
                mToolDrag = true;
            if (!p.down)
                mToolDrag = false;
            leftIsTools = leftIsTools || mToolDrag || mState.view.toolDragActive;
            return used;
        };
        // The left-button path in UI points, and the share of it each step takes: the points
        // before its event, after the last step's.
        const float toPoints = EditorUi::pointsPerScreenUnit(*mWindow);
        std::size_t pathTaken = 0;
        // The keys pressed before a press of the same frame act before it: a tool chosen by a
        // key (g, then a click on a marker, inside one slow frame) takes that press, a Delete
        // removes what was selected before the click selects another, an undo undoes what came
        // before the click. The rest act after the frame's presses (applyKeys).
        const auto takePath = [&](ViewportPointer& p, std::size_t until, ui::Rect area) {
            for (; pathTaken < until; ++pathTaken) {
                const ui::Vec2 at = input.leftPath[pathTaken] * toPoints;
                p.pathBefore.push_back(glm::vec2(at.x - area.min.x, at.y - area.min.y) * ppp);
            }
        };
        for (const LeftButtonStep& step : leftSteps) {
            if (step.down)
                logKeyChange(applyKeysUpTo(mState, viewportKeys, true, keysTaken, step.keysBefore));
            ViewportPointer p = pointer;
            placePointer(p, step.at, step.central, ppp);
            takePath(p, step.pathBefore, step.central);
            // A key before it opened a dialog (Ctrl+O, Ctrl+N): the press is not the tools'.
            const bool dialogOpened = mState.transient.browser || mState.transient.quitDialog;
            p.inside = input.cursorInside && step.central.contains(step.at) && !step.uiTook &&
                       !mCameraDrag && !dialogOpened;
            p.down = step.down;
            p.pressed = step.down && !step.uiTook && !dialogOpened;
            p.released = !step.down;
            runTool(p);
            pressStepped = pressStepped || step.down;
        }
        pointer.inside = pointer.inside && !uiPointer && !mCameraDrag;
        pointer.down = input.leftDown;
        pointer.pressed = input.leftPressed && !pressOnUi && !pressStepped;
        pointer.released = !input.leftDown;
        takePath(pointer, input.leftPath.size(), central);
        toolUsed = runTool(pointer);
        if (leftIsTools)
            leftHeld = false;
        if (mState.view.tool != ViewportTool::Camera && rightHeld)
            leftHeld = true;
    }
    InputState cameraInput = input;
    cameraInput.leftDown = leftHeld;
    cameraInput.middleDown = middleHeld;
    cameraInput.rightDown = rightHeld;
    const bool anyDown = (input.leftDown && leftHeld) || input.middleDown || input.rightDown;
    const bool anyHeld = leftHeld || middleHeld || rightHeld;
    // The camera's drag this frame: one it held already, or one a press on the viewport began
    // (judged where the press happened when the frame had its event, else where the pointer is).
    bool cameraDrag = false;
    if (!mUi)
        cameraDrag = anyHeld && !toolUsed;
    else
        cameraDrag = mCameraDrag || (anyHeld && !(pressStepped ? pressOnUi : uiPointer) &&
                                     !leftIsTools && mUi->context().activeId().value == 0);
    mCameraDrag = cameraDrag && anyDown;
    // A focused field owns the keyboard: an F typed into it is text, not "frame the scene"; the
    // same for the other render keys' flags (the window sets them per frame, not per key).
    if (uiKeyboard || !keysAllTheViewports) {
        input.frameRequested = cameraInput.frameRequested = false;
        viewportKeys.toggledCullTest = 0;
        viewportKeys.nextTechnique = viewportKeys.toggleLighting = false;
    }
    moveCamera(cameraInput, cameraDrag, !uiPointer, mView.h, *mLive.scene,
               selectionBounds(mState, float(mState.view.timeline.timeS())), mCamera);
    // What keeps the viewport's picture reduced (adaptive quality, Editor::chooseQuality).
    mInteracting = (cameraDrag && anyHeld) || (input.scrollSteps != 0.0 && !uiPointer) ||
                   mToolDrag || mState.view.toolDragActive ||
                   (mUi && mUi->context().activeId().value != 0);
    // The file browser is a dialog: while it is open no key reaches the viewport behind it (a
    // Delete there would remove the selected collider, a T change the technique).
    if (!mState.transient.browser)
        applyKeys(viewportKeys, keysTaken);
}

void Editor::logKeyChange(const std::string& changed) {
    if (!changed.empty())
        std::fprintf(stderr, "grass-editor: %s\n", changed.c_str());
}

void Editor::applyKeys(const InputState& input, KeysTaken taken) {
    logKeyChange(applyEditorKeys(mState, input, mUi != nullptr, taken));
    // With the UI, Escape belongs to it (closing popups and text edits): one press must not
    // also quit. File → Quit and the window's close button remain.
    if (input.escapePressed && !mUi)
        mWindow->requestClose();
}

}  // namespace grass::editor
