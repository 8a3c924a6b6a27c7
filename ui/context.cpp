#include "ui/context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace grass::ui {

namespace {

// Checked stacks as in rxi/microui's mu_end: an unbalanced pushId is a bug in the caller, and
// continuing would give every later widget a wrong id.
void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "grass::ui: %s\n", what);
        std::abort();
    }
}

std::size_t index(PointerButton b) {
    return std::size_t(b);
}

}  // namespace

Context::Context(const FontAtlas& fonts, Style style) : mFonts(fonts), mStyle(std::move(style)) {
    mIdStack.push_back(Id::fromString("grass::ui"));
}

void Context::beginFrame(Input input) {
    mInput = std::move(input);
    ++mFrame;
    for (std::size_t b = 0; b < POINTER_BUTTON_COUNT; ++b) {
        const bool down = mInput.buttonDown[b];
        mInput.buttonPressed[b] = mInput.buttonPressed[b] || (down && !mPrevDown[b]);
        mInput.buttonReleased[b] = mInput.buttonReleased[b] || (!down && mPrevDown[b]);
        mPrevDown[b] = down;
    }
    // The first frame has no previous position: no jump.
    mPointerDelta = mFrame == 1 ? Vec2(0.0f) : mInput.pointerPos - mPrevPointer;
    mPrevPointer = mInput.pointerPos;
    if (buttonPressed()) {
        mPressOrigin = mInput.pointerPos;
        mPressMovedFar = false;
    }
    if (mPressOrigin && glm::length(mInput.pointerPos - *mPressOrigin) > mStyle.clickMaxDistance) {
        mPressMovedFar = true;
    }

    mHitsLastFrame = std::move(mHitsThisFrame);
    mHitsThisFrame.clear();
    mTopAtPointer = mInput.hasPointer ? topmostAt(mHitsLastFrame, mInput.pointerPos) : Id{};
    mActiveSeen = false;
    mFocusAtBegin = mFocusId;
    mFocusSeen = false;
    mFocusTakenThisFrame = false;
    mFocusable.clear();
    mSeenIds.clear();
    mDuplicateIds = 0;
    mAutoIds = 0;
    mPointerOverArea = false;
    for (auto& layer : mLayers) {
        layer.clear();
    }
    mOutput = Output{};
}

void Context::requestRepaintAfter(double seconds) {
    seconds = std::max(seconds, 0.0);
    mOutput.repaintAfterS = std::min(mOutput.repaintAfterS.value_or(seconds), seconds);
}

const Output& Context::endFrame() {
    check(mIdStack.size() == 1, "pushId without popId (or the reverse) this frame");

    // Tab / Shift+Tab move focus through this frame's focusable widgets, in layout order.
    if (mFocusId.value != 0 && !mFocusable.empty()) {
        for (const bool back : {false, true}) {
            if (!consumeKey(Key::Tab, Modifiers{back, false, false})) {
                continue;
            }
            std::size_t i = 0;
            while (i < mFocusable.size() && !(mFocusable[i] == mFocusId)) {
                ++i;
            }
            const std::size_t n = mFocusable.size();
            const std::size_t next = i == n ? 0 : (back ? (i + n - 1) % n : (i + 1) % n);
            requestFocus(mFocusable[next]);
            mFocusSeen = true;
        }
    }
    // A press that no focusable widget took, or a focused widget that is gone, drops focus.
    if ((buttonPressed() && !mFocusTakenThisFrame) || !mFocusSeen) {
        clearFocus();
    }
    if (buttonReleased() || !mActiveSeen) {
        mActiveId = Id{};
    }
    if (!buttonDown()) {
        mPressOrigin.reset();
    }
    // A lost-focus notice waits one frame for its widget, which may have run before the change.
    if (mLostFocusId.value != 0 && mFrame > mLostFocusFrame) {
        mLostFocusId = Id{};
    }

    const bool overWidget =
        mInput.hasPointer && topmostAt(mHitsThisFrame, mInput.pointerPos).value != 0;
    mOutput.wantsPointer = mActiveId.value != 0 || overWidget || mPointerOverArea;
    mOutput.wantsKeyboard = mFocusId.value != 0 || mFocusAtBegin.value != 0;
    mOutput.pixelsPerPoint = mInput.pixelsPerPoint;
    std::size_t total = 0;
    for (const auto& layer : mLayers) {
        total += layer.size();
    }
    mOutput.shapes.reserve(total);
    for (auto& layer : mLayers) {
        for (auto& shape : layer) {
            mOutput.shapes.push_back(std::move(shape));
        }
        layer.clear();
    }
    return mOutput;
}

bool Context::buttonDown(PointerButton b) const {
    return mInput.buttonDown[index(b)];
}

bool Context::buttonPressed(PointerButton b) const {
    return mInput.buttonPressed[index(b)];
}

bool Context::buttonReleased(PointerButton b) const {
    return mInput.buttonReleased[index(b)];
}

bool Context::keyPressed(Key key) const {
    for (const KeyEvent& e : mInput.keys) {
        if (e.key == key) {
            return true;
        }
    }
    return false;
}

bool Context::consumeKey(Key key, Modifiers modifiers) {
    for (auto it = mInput.keys.begin(); it != mInput.keys.end(); ++it) {
        if (it->key == key && it->modifiers == modifiers) {
            mInput.keys.erase(it);
            return true;
        }
    }
    return false;
}

Vec2 Context::consumeScroll() {
    return std::exchange(mInput.scrollDelta, Vec2(0.0f));
}

void Context::popId() {
    check(mIdStack.size() > 1, "popId without pushId");
    mIdStack.pop_back();
}

void Context::requestFocus(Id id) {
    if (!(mFocusId == id) && mFocusId.value != 0) {
        mLostFocusId = mFocusId;
        mLostFocusFrame = mFrame;
    }
    if (!(mFocusId == id)) {
        mGainedFocusId = id;
    }
    mFocusId = id;
    mFocusTakenThisFrame = true;
}

void Context::clearFocus() {
    if (mFocusId.value != 0) {
        mLostFocusId = mFocusId;
        mLostFocusFrame = mFrame;
    }
    mFocusId = Id{};
    mGainedFocusId = Id{};
}

bool Context::pointerBesideOpenPopup() const {
    if (mOpenPopup.value == 0)
        return false;
    return std::none_of(mHitsLastFrame.begin(), mHitsLastFrame.end(), [&](const Hit& hit) {
        return hit.layer == Layer::Popups && mInput.hasPointer &&
               hit.rect.contains(mInput.pointerPos);
    });
}

void Context::registerArea(Rect rect) {
    if (mInput.hasPointer && rect.contains(mInput.pointerPos)) {
        mPointerOverArea = true;
    }
}

Id Context::topmostAt(const std::vector<Hit>& hits, Vec2 pos) {
    // Hits are recorded in paint order within a layer; the last one containing pos of the
    // highest layer is on top.
    Id top;
    int topLayer = -1;
    for (const Hit& hit : hits) {
        if (hit.rect.contains(pos) && int(hit.layer) >= topLayer) {
            top = hit.id;
            topLayer = int(hit.layer);
        }
    }
    return top;
}

Response Context::interact(Rect rect, Rect clip, Layer layer, Id id, Sense sense) {
    Response r;
    r.mCtx = this;
    r.mRect = rect;
    r.mId = id;
    if (!mSeenIds.insert(id.value).second) {
        ++mDuplicateIds;
    }
    const Rect hitRect = rect.intersect(clip);
    mHitsThisFrame.push_back({id, hitRect, layer});
    if (sense.focusable) {
        mFocusable.push_back(id);
    }

    const Vec2 p = mInput.pointerPos;
    const bool inside = mInput.hasPointer && !hitRect.empty() && hitRect.contains(p);
    const bool othersActive = mActiveId.value != 0 && !(mActiveId == id);
    const bool onTop = mTopAtPointer.value == 0 || mTopAtPointer == id;
    r.mHovered = inside && onTop && !othersActive;
    r.mPointerPos = p;

    const bool interactive = sense.click || sense.drag || sense.focusable;
    if (interactive && r.mHovered && buttonPressed()) {
        mActiveId = id;
        if (sense.drag) {
            r.mDragStarted = true;
        }
        if (sense.focusable) {
            requestFocus(id);
        }
    }
    r.mSecondaryClicked = sense.click && r.mHovered && buttonReleased(PointerButton::Secondary);
    if (mActiveId == id) {
        mActiveSeen = true;
        // A drag's release carries its last stretch of motion: at a low frame rate that comes
        // with the release (the app feeds one pass per button event), and a quick flick's whole
        // motion does. A click (no farther than clickMaxDistance) moves nothing as it ends.
        const bool releasingADrag = buttonReleased() && mPressMovedFar;
        if (sense.drag && (buttonDown() || buttonPressed() || releasingADrag)) {
            r.mDragged = true;
            r.mDragDelta = buttonPressed() ? Vec2(0.0f) : mPointerDelta;
        }
        if (buttonReleased()) {
            r.mDragStopped = sense.drag;
            // Release inside (hit rect, ignoring the one-frame-late topmost test, which the
            // press already passed) and not a drag on a widget that also drags.
            const bool releasedInside = mInput.hasPointer && hitRect.contains(p);
            r.mClicked = sense.click && releasedInside && !(sense.drag && mPressMovedFar);
        }
    }
    if (r.mClicked) {
        // Judged by the clicks' times and places (the app may feed one pass per button event,
        // so these are the events', not the frames').
        r.mDoubleClicked =
            mLastClickId == id && mInput.timeS - mLastClickTimeS <= double(mStyle.doubleClickTimeS) &&
            glm::length(p - mLastClickPos) <= mStyle.clickMaxDistance;
        mLastClickId = r.mDoubleClicked ? Id{} : id;
        mLastClickTimeS = mInput.timeS;
        mLastClickPos = p;
    }
    if (mFocusId == id) {
        mFocusSeen = true;
        r.mHasFocus = true;
    }
    if (mGainedFocusId == id) {
        r.mGainedFocus = true;
        mGainedFocusId = Id{};
    }
    if (mLostFocusId == id) {
        r.mLostFocus = true;
        mLostFocusId = Id{};
    }
    if (r.mHovered && (sense.click || sense.drag) && mOutput.cursor == CursorIcon::Default) {
        mOutput.cursor = CursorIcon::PointingHand;
    }
    return r;
}

}  // namespace grass::ui
