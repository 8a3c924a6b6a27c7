#include "edit/history.h"

namespace grass::core {

namespace {

template <typename T>
std::size_t payload(const std::vector<T>& values) {
    return values.capacity() * sizeof(T);
}

std::size_t projectBytes(const Project& project) {
    std::size_t bytes = sizeof(Project) + project.name.capacity() + project.mesh.file.capacity();
    for (const GrassLayer& layer : project.layers)
        bytes += sizeof(GrassLayer) + layer.name.capacity() + layer.densityMap.capacity() +
                 layer.soilMap.capacity() + layer.lightMap.capacity() +
                 layer.cutMap.capacity();
    for (const WindDesc& wind : project.wind)
        bytes += sizeof(WindDesc) + wind.name.capacity() + payload(wind.source.path);
    for (const ColliderDesc& collider : project.colliders)
        bytes += sizeof(ColliderDesc) + collider.name.capacity() + collider.file.capacity() +
                 payload(collider.path);
    bytes += payload(project.cameras);
    return bytes;
}

}  // namespace

std::size_t editBytes(const Edit& edit) {
    std::size_t bytes = sizeof(Edit) + edit.label.capacity();
    if (const auto* project = std::get_if<ProjectEdit>(&edit.change))
        return bytes + projectBytes(project->before) + projectBytes(project->after);
    const PaintRecord& record = std::get<PaintEdit>(edit.change).record;
    return bytes + payload(record.texelIndex) + payload(record.before) + payload(record.after);
}

void EditHistory::push(Edit edit) {
    // The saved state lay in the redo branch this edit drops: it cannot be reached again.
    if (mSavedAt && *mSavedAt > mDropped + mCursor)
        mSavedAt.reset();
    while (mEdits.size() > mCursor) {
        mBytes -= mEditBytes.back();
        mEdits.pop_back();
        mEditBytes.pop_back();
    }
    mEditBytes.push_back(editBytes(edit));
    mBytes += mEditBytes.back();
    mEdits.push_back(std::move(edit));
    mCursor = mEdits.size();
    while (mEdits.size() > 1 && (mEdits.size() > mLimits.maxSteps || mBytes > mLimits.maxBytes)) {
        mBytes -= mEditBytes.front();
        mEdits.pop_front();
        mEditBytes.pop_front();
        --mCursor;
        ++mDropped;
    }
    if (mSavedAt && *mSavedAt < mDropped)
        mSavedAt.reset();  // undoing can no longer go back that far
}

const Edit* EditHistory::undo() {
    if (!canUndo())
        return nullptr;
    return &mEdits[--mCursor];
}

const Edit* EditHistory::redo() {
    if (!canRedo())
        return nullptr;
    return &mEdits[mCursor++];
}

void EditHistory::clear() {
    mEdits.clear();
    mEditBytes.clear();
    mCursor = 0;
    mBytes = 0;
    mDropped = 0;
    mSavedAt.reset();
}

void EditHistory::markSaved() {
    mSavedAt = mDropped + mCursor;
}

bool EditHistory::atSavePoint() const {
    return mSavedAt && *mSavedAt == mDropped + mCursor;
}

}  // namespace grass::core
