#include "app/export_job.h"

#include <cstdio>

namespace grass::editor {

ExportJob::ExportJob(core::LoadedProject loaded, const core::Scene& scene,
                     core::ExportOptions options, std::function<void()> whenDone)
    : mLoaded(std::move(loaded)), mScene(&scene), mOptions(std::move(options)) {
    mOptions.stop = mStop.get_token();
    mWorker = std::thread([this, whenDone = std::move(whenDone)] {
        auto result = core::exportProject(mLoaded, *mScene, mOptions,
                                          [this](float fraction, std::string_view stage) {
                                              mFraction.store(fraction);
                                              std::lock_guard lock(mMutex);
                                              mStage = stage;
                                          });
        // A full bar only for an export that was written: a stopped or failed one keeps where
        // it ended.
        if (result)
            mFraction.store(1.0f);
        {
            std::lock_guard lock(mMutex);
            mResult.emplace(std::move(result));
        }
        mDone.store(true);
        if (whenDone)
            whenDone();
    });
}

ExportJob::~ExportJob() {
    wait();
}

void ExportJob::wait() {
    if (mWorker.joinable())
        mWorker.join();
}

std::string ExportJob::stage() const {
    std::lock_guard lock(mMutex);
    return mStage;
}

bool ExportJob::succeeded() const {
    std::lock_guard lock(mMutex);
    return mResult && mResult->ok();
}

std::string ExportJob::summary() const {
    std::lock_guard lock(mMutex);
    if (!mResult)
        return "exporting…";
    if (!mResult->ok() && mStop.stop_requested())
        return "export stopped: nothing was written to " + mOptions.outDir.string();
    if (!mResult->ok())
        return "export failed: " + mResult->error().str();
    const core::ExportReport& report = mResult->value();
    std::size_t instances = 0;
    for (const core::ExportedLayer& layer : report.layers)
        instances += layer.instances;
    // The folder after the figures, whole: a path of any length.
    char figures[128];
    std::snprintf(figures, sizeof figures, "exported %zu file%s (%.1f MB, %zu instances) to ",
                  report.files.size(), report.files.size() == 1 ? "" : "s",
                  double(report.totalBytes()) / 1e6, instances);
    return figures + mOptions.outDir.string();
}

std::optional<std::string> ExportJob::takeEndNotice() {
    if (!done() || mEndNoticeTaken)
        return std::nullopt;
    mEndNoticeTaken = true;
    return summary();
}

}  // namespace grass::editor
