// EditHistory: the editor's undo and redo (issue 8). Two kinds of edit: a change of the project's
// parameters (a panel drag, a moved wind source, an added collider), kept as the whole project
// before and after (a project without its maps is a few kilobytes), and a paint stroke, kept as
// the texels it changed (PaintRecord: index, before, after; 12 bytes a changed texel, nothing
// for untouched ones), so undo is bit-exact and memory grows with what was painted, not with the
// map size. The history keeps at most `maxSteps` edits and `maxBytes` of them, dropping the
// oldest first (the newest edit is always kept, however large).
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <variant>

#include "maps/brush.h"
#include "project/project.h"
#include "scene/layer_growth.h"

namespace grass::core {

struct ProjectEdit {
    Project before;
    Project after;
    // Whether the live field is grown from what the step changed (layers' scatter, the surface,
    // wind, colliders): undoing or redoing it grows the field again. Not for a step of render
    // settings, light, colours, shapes or names, which the field shows as they are: before
    // 2026-12-07 every undo grew the whole field again, and its blades restarted from rest.
    bool regrows = true;
};

struct PaintEdit {
    std::size_t layer = 0;
    LayerMap map = LayerMap::Density;
    PaintRecord record;
};

struct Edit {
    std::string label;  // what the Edit menu and the status bar show: "paint density", "wind"
    std::variant<ProjectEdit, PaintEdit> change;
};

// Memory an edit holds, approximately (containers' payloads plus the structs themselves).
std::size_t editBytes(const Edit& edit);

class EditHistory {
public:
    struct Limits {
        std::size_t maxSteps = 1000;
        std::size_t maxBytes = std::size_t{512} << 20;
    };
    EditHistory() = default;
    explicit EditHistory(Limits limits) : mLimits(limits) {}

    // Records a done edit: the redo branch is dropped, then the oldest edits beyond the limits.
    void push(Edit edit);
    // The edit to revert (the caller applies its `before`) and steps back; null when none.
    const Edit* undo();
    // The edit to re-apply (its `after`) and steps forward; null when none.
    const Edit* redo();

    bool canUndo() const { return mCursor > 0; }
    bool canRedo() const { return mCursor < mEdits.size(); }
    const Edit* nextUndo() const { return canUndo() ? &mEdits[mCursor - 1] : nullptr; }
    const Edit* nextRedo() const { return canRedo() ? &mEdits[mCursor] : nullptr; }
    std::size_t undoSteps() const { return mCursor; }
    std::size_t redoSteps() const { return mEdits.size() - mCursor; }
    std::size_t bytes() const { return mBytes; }
    // Forgets every edit and the save point.
    void clear();

    // The document was saved (or opened) as it stands: undoing or redoing back to here brings
    // back what the file holds, so the title's * can go (atSavePoint).
    void markSaved();
    // Whether the done edits are those of the last markSaved. False once an edit it needs was
    // dropped (a new edit after undoing past it, or the oldest beyond the limits), and after
    // clear until markSaved.
    bool atSavePoint() const;

private:
    Limits mLimits;
    std::deque<Edit> mEdits;
    std::deque<std::size_t> mEditBytes;
    std::size_t mCursor = 0;  // edits before it are done, from it on undone
    std::size_t mBytes = 0;
    std::size_t mDropped = 0;  // edits dropped from the front since clear
    // Edits done at the save point, counted from clear (mDropped + mCursor then); none: unsaved.
    std::optional<std::size_t> mSavedAt;
};

}  // namespace grass::core
