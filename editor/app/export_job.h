// The editor's export (File → Export…): core::exportProject on a worker thread, so the window
// keeps drawing and shows a progress bar. While the job runs the scene must not change: the
// editor holds back painting and re-growing until done() (EditorState::busy()).
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>

#include "export/export.h"

namespace grass::editor {

class ExportJob {
public:
    // Starts exporting `scene` (which must stay unchanged until done()) with a copy of `loaded`.
    // `whenDone` is called on the worker once done() is true (EditorState::wakeFrame).
    ExportJob(core::LoadedProject loaded, const core::Scene& scene, core::ExportOptions options,
              std::function<void()> whenDone = {});
    ~ExportJob();  // waits for the worker
    ExportJob(const ExportJob&) = delete;
    ExportJob& operator=(const ExportJob&) = delete;

    bool done() const { return mDone.load(); }
    void wait();  // until done()
    // Asks the export to end at its next stage, before anything is renamed into place (the
    // dialog's Stop): the folder stays as it was. Too late once the files are being renamed.
    void stop() { mStop.request_stop(); }
    bool stopping() const { return mStop.stop_requested(); }
    float fraction() const { return mFraction.load(); }
    std::string stage() const;
    // After done(): the report's one-line summary, or the error.
    std::string summary() const;
    // The summary the first time it is asked for after done(), then nothing: the status line
    // says the end once, even while the window that shows it stays open.
    std::optional<std::string> takeEndNotice();
    bool succeeded() const;

private:
    core::LoadedProject mLoaded;
    const core::Scene* mScene;
    core::ExportOptions mOptions;
    std::stop_source mStop;
    std::atomic<bool> mDone{false};
    std::atomic<float> mFraction{0.0f};
    mutable std::mutex mMutex;
    std::string mStage = "preparing the folder";  // until the first progress
    std::optional<Result<core::ExportReport>> mResult;
    bool mEndNoticeTaken = false;  // the UI thread's alone
    std::thread mWorker;
};

}  // namespace grass::editor
