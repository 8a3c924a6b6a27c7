#include "app/document_job.h"

#include <algorithm>
#include <utility>

#include "app/recent_files.h"
#include "util/assert.h"

namespace grass::editor {

DocumentJob::DocumentJob(DocumentAction action, std::filesystem::path file, std::string stage,
                         Work work, std::chrono::milliseconds delay, std::function<void()> whenDone)
    : mAction(action),
      mFile(std::move(file)),
      mStart(std::chrono::steady_clock::now()),
      mStage(std::move(stage)) {
    mWorker = std::thread([this, work = std::move(work), delay, whenDone = std::move(whenDone)] {
        // The delay in short sleeps, so that a cancel (or the window closed) ends it.
        const auto until = std::chrono::steady_clock::now() + delay;
        while (!cancelled() && std::chrono::steady_clock::now() < until)
            std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(
                std::chrono::milliseconds(10), until - std::chrono::steady_clock::now()));
        auto result =
            cancelled() ? Result<GrownDocument>(makeError(title(), "cancelled")) : work(*this);
        {
            std::lock_guard lock(mMutex);
            mResult.emplace(std::move(result));
        }
        mDone.store(true);
        if (whenDone)
            whenDone();
    });
}

DocumentJob::~DocumentJob() {
    wait();
}

void DocumentJob::wait() {
    if (mWorker.joinable())
        mWorker.join();
}

std::string DocumentJob::title() const {
    const std::string name = shownFileName(mFile);
    switch (mAction) {
        case DocumentAction::New:
            return "New project";
        case DocumentAction::Open:
            return "Opening " + name;
        case DocumentAction::NewFromMesh:
            return "New project from " + name;
        case DocumentAction::ImportMesh:
            return "Importing " + name;
        case DocumentAction::Recover:
            return "Recovering the autosave";
        case DocumentAction::Regrow:
            return "Growing the field again";
    }
    return {};
}

std::string DocumentJob::stage() const {
    std::lock_guard lock(mMutex);
    return mStage;
}

double DocumentJob::elapsedS() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
}

void DocumentJob::setStage(std::string stage) {
    std::lock_guard lock(mMutex);
    mStage = std::move(stage);
}

Result<GrownDocument> DocumentJob::take() {
    std::lock_guard lock(mMutex);
    GRASS_ASSERT(mResult.has_value());
    Result<GrownDocument> result = std::move(*mResult);
    mResult.reset();
    return result;
}

}  // namespace grass::editor
