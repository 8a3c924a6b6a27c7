// The UI's only context (STYLE.md §6, §7): the app creates one, feeds it an Input at the start
// of each frame, builds its panels with ui::Ui over it, and takes the Output (shapes by layer,
// whether the UI wants the pointer/keyboard, clipboard text) at the end. It owns everything that
// lives across frames: per-id widget state, hot/active/focus ids, the open popup, the id stack
// and the style. No OS calls: the clipboard goes in and out through Input and Output.
// Positions in points, y down, origin at the window's top-left.
#pragma once

#include <any>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "font.h"
#include "painter.h"
#include "response.h"
#include "shape.h"
#include "style.h"
#include "types.h"

namespace grass::ui {

// Keys widgets react to; letters only for shortcuts (select all, copy, paste, cut, undo, redo, save,
// new, open).
enum class Key {
    Left,
    Right,
    Up,
    Down,
    Home,
    End,
    Backspace,
    Delete,
    Enter,
    Escape,
    Tab,
    A,
    C,
    V,
    X,
    Z,
    Y,
    S,
    N,
    O
};

struct Modifiers {
    bool shift = false;
    bool ctrl = false;
    bool alt = false;
    bool operator==(const Modifiers&) const = default;
};

// A key press or auto-repeat, with the modifiers held at the time, and where it fell in the
// frame's typed text: a slow frame gathers several keystrokes, and Ctrl+A, Backspace or an arrow
// pressed between two characters must act between them (a text edit replays them in order).
struct KeyEvent {
    Key key = Key::Escape;
    Modifiers modifiers;
    // Bytes of Input::text typed before this key; npos: after all of it.
    std::size_t textBefore = std::string::npos;
};

enum class PointerButton { Primary, Secondary, Middle };
inline constexpr int POINTER_BUTTON_COUNT = 3;

struct Input {
    Rect screenRect;
    float pixelsPerPoint = 1.0f;
    double timeS = 0.0;
    bool hasPointer = true;  // false while the pointer is outside the window
    Vec2 pointerPos{0.0f};
    // The app may set only buttonDown: the context derives pressed/released from the change
    // since the last frame. Setting them too keeps a press and release within one frame.
    std::array<bool, POINTER_BUTTON_COUNT> buttonDown{};
    std::array<bool, POINTER_BUTTON_COUNT> buttonPressed{};
    std::array<bool, POINTER_BUTTON_COUNT> buttonReleased{};
    // Wheel movement, points; +y = wheel turned away from the user (content moves down).
    Vec2 scrollDelta{0.0f};
    std::string text;  // typed text, UTF-8, without control characters
    std::vector<KeyEvent> keys;
    Modifiers modifiers;
    // What a paste (Ctrl+V) inserts: the app copies the OS clipboard here.
    std::string clipboardText;
};

enum class CursorIcon { Default, PointingHand, Text, ResizeHorizontal, ResizeVertical, Move };

struct Output {
    // All layers' shapes in paint order (Layer order, then the order they were added).
    std::vector<ClippedShape> shapes;
    // The pointer is over UI (a widget or a registered area) or a widget is being dragged: the
    // app should not also use it (camera, brush).
    bool wantsPointer = false;
    // A widget has keyboard focus, or had it when the frame began: the frame's keys were its
    // own even when one of them (Enter, Escape) ended the focus. A slow frame gathers several
    // keystrokes; before, the ones typed with the Enter also reached the app's shortcuts (a
    // folder path typed into the export window at 1 fps changed the technique).
    bool wantsKeyboard = false;
    // Set when the UI copied or cut text; the app puts it on the OS clipboard.
    std::optional<std::string> copiedText;
    CursorIcon cursor = CursorIcon::Default;
    // Input::pixelsPerPoint of this frame, for the renderer (mesh positions are in points).
    float pixelsPerPoint = 1.0f;
    // The panels change without input within this many seconds (a caret's blink): the app
    // must run a frame by then even if nothing happens (egui's request_repaint_after). Unset:
    // the panels stay as they are until the next input.
    std::optional<double> repaintAfterS;
};

// Paint layers, back to front. Hit testing follows the same order.
// Paint and hit order, back to front. Popups (combo lists, menus) lie above the windows, the
// frontmost on Foreground included: a combo's list opened in a window was painted under the
// window's later widgets.
enum class Layer { Background, Panels, Foreground, Popups, Tooltips };
inline constexpr int LAYER_COUNT = 5;

// What a widget reacts to (Context::interact).
struct Sense {
    bool click = false;
    bool drag = false;
    bool focusable = false;
    static Sense hover() { return {}; }
    static Sense clickOnly() { return {true, false, false}; }
    static Sense dragOnly() { return {false, true, false}; }
    static Sense clickAndDrag() { return {true, true, false}; }
};

class Context {
public:
    explicit Context(const FontAtlas& fonts, Style style = {});
    // One per app (or per test); copying would fork the widget state.
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    void beginFrame(Input input);
    // Checks the id stack is balanced, settles focus and dragging, and fills the output.
    const Output& endFrame();
    Output& output() { return mOutput; }
    // For widgets that change with time alone: asks for a frame within `seconds` (the soonest
    // request of the frame wins; Output::repaintAfterS).
    void requestRepaintAfter(double seconds);

    const Input& input() const { return mInput; }
    const Style& style() const { return mStyle; }
    Style& style() { return mStyle; }
    const FontAtlas& fonts() const { return mFonts; }
    std::uint64_t frameNumber() const { return mFrame; }
    Rect screenRect() const { return mInput.screenRect; }
    float pixelsPerPoint() const { return mInput.pixelsPerPoint; }

    // Pointer and keys of this frame.
    Vec2 pointerPos() const { return mInput.pointerPos; }
    Vec2 pointerDelta() const { return mPointerDelta; }
    bool buttonDown(PointerButton b = PointerButton::Primary) const;
    bool buttonPressed(PointerButton b = PointerButton::Primary) const;
    bool buttonReleased(PointerButton b = PointerButton::Primary) const;
    // Where the primary button went down, while it is held.
    std::optional<Vec2> pressOrigin() const { return mPressOrigin; }
    bool keyPressed(Key key) const;
    // Takes a key event (with exactly these modifiers) out of the frame's input so no other
    // widget reacts to it; returns whether there was one.
    bool consumeKey(Key key, Modifiers modifiers = {});
    // Returns the wheel delta and zeroes it, so nested scroll areas scroll only the innermost.
    Vec2 consumeScroll();

    // Id stack (hash of parent id + salt).
    Id currentId() const { return mIdStack.back(); }
    void pushId(Id id) { mIdStack.push_back(id); }
    void popId();
    // Ids for widgets without a natural salt (labels): unique by call order within a frame, so
    // stable while the layout's structure is.
    Id autoId() { return Id::fromString("auto").with(mAutoIds++); }

    // Hit-tests `rect` (within `clip`, on `layer`) for widget `id` and updates hot/active/focus
    // state. Topmost wins: later layers, then later calls within a layer, judged on last frame's
    // rects so a widget painted over another blocks it from the next frame on.
    Response interact(Rect rect, Rect clip, Layer layer, Id id, Sense sense);
    Id activeId() const { return mActiveId; }
    Id focusedId() const { return mFocusId; }
    void requestFocus(Id id);
    void clearFocus();
    // Widgets whose id was used twice this frame (a loop without pushId): a bug in the caller.
    int duplicateIdCount() const { return mDuplicateIds; }
    // Marks an area that takes the pointer (panel, window) for Output::wantsPointer.
    void registerArea(Rect rect);

    // One popup (combo list, menu) is open at a time.
    void openPopup(Id id) { mOpenPopup = id; }
    void closePopup() { mOpenPopup = Id{}; }
    bool isPopupOpen(Id id) const { return mOpenPopup == id && id.value != 0; }
    // A popup is open and the pointer is not over it (last frame's layout): the widgets under
    // the pointer show no tooltip, which would cover the list (a combo's own, under its box).
    bool pointerBesideOpenPopup() const;

    std::vector<ClippedShape>& layerShapes(Layer layer) { return mLayers[std::size_t(layer)]; }
    Painter painter(Layer layer, Rect clip) { return Painter(layerShapes(layer), mFonts, clip); }

    // Typed per-widget state that lives across frames (open flags, scroll offsets, grid
    // widths). A missing entry, or one of another type, is (re)created from `init`.
    template <class T>
    T& state(Id id, T init = T{}) {
        std::any& slot = mState[id.value];
        if (T* value = std::any_cast<T>(&slot)) {
            return *value;
        }
        return slot.emplace<T>(std::move(init));
    }
    template <class T>
    T* findState(Id id) {
        const auto it = mState.find(id.value);
        return it == mState.end() ? nullptr : std::any_cast<T>(&it->second);
    }
    void removeState(Id id) { mState.erase(id.value); }

private:
    struct Hit {
        Id id;
        Rect rect;  // already clipped
        Layer layer;
    };
    static Id topmostAt(const std::vector<Hit>& hits, Vec2 pos);

    const FontAtlas& mFonts;
    Style mStyle;
    Input mInput;
    Output mOutput;
    std::uint64_t mFrame = 0;
    std::array<bool, POINTER_BUTTON_COUNT> mPrevDown{};
    Vec2 mPrevPointer{0.0f};
    Vec2 mPointerDelta{0.0f};
    std::optional<Vec2> mPressOrigin;
    bool mPressMovedFar = false;

    std::vector<Id> mIdStack;
    std::uint64_t mAutoIds = 0;
    std::vector<Hit> mHitsLastFrame;
    std::vector<Hit> mHitsThisFrame;
    Id mTopAtPointer;
    Id mActiveId;
    bool mActiveSeen = false;
    Id mFocusId;
    Id mFocusAtBegin;  // mFocusId when the frame began (Output::wantsKeyboard)
    bool mFocusSeen = false;
    bool mFocusTakenThisFrame = false;
    Id mLostFocusId;
    Id mGainedFocusId;
    std::uint64_t mLostFocusFrame = 0;
    std::vector<Id> mFocusable;
    Id mLastClickId;
    double mLastClickTimeS = -1.0;
    Vec2 mLastClickPos{0.0f};
    Id mOpenPopup;
    std::unordered_set<std::uint64_t> mSeenIds;
    int mDuplicateIds = 0;
    bool mPointerOverArea = false;

    std::array<std::vector<ClippedShape>, LAYER_COUNT> mLayers;
    std::unordered_map<std::uint64_t, std::any> mState;
};

}  // namespace grass::ui
