// File › New, Open, New from mesh, Import mesh and the recovered autosave grow the next field on
// a worker thread: a large mesh takes seconds to read and grow (8 s for an 8-million-triangle
// ground), and the window froze on its last frame meanwhile, with no word of what it was doing
// and no way back. The job's work is GL-free (live_scene.h growField); the Editor brings the
// grown field up on the GPU once done() and only then replaces anything, so a failure leaves the
// document as it was. While a job runs the document stays as it is (EditorState::loading()):
// the panels show what the job is doing, with a Cancel that lets the window go on at once.
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>

#include "app/live_scene.h"
#include "util/result.h"

namespace grass::editor {

// What the grown field becomes once the job is done.
// Regrow: the open project's field grown again after an edit of its layers (Editor::startRegrow).
enum class DocumentAction { New, Open, NewFromMesh, ImportMesh, Recover, Regrow };

struct GrownDocument {
    GrownField field;
    std::string note;  // Import mesh: what was copied into the project
};

class DocumentJob {
public:
    using Work = std::function<Result<GrownDocument>(DocumentJob&)>;
    // Starts `work` on a worker thread after `delay` (--load-delay-ms: tests of a slow load).
    // `file`: what it opens or imports (empty for New), `stage`: what it does first.
    // `whenDone` is called on the worker once done() is true (EditorState::wakeFrame).
    DocumentJob(DocumentAction action, std::filesystem::path file, std::string stage, Work work,
                std::chrono::milliseconds delay = {}, std::function<void()> whenDone = {});
    ~DocumentJob();  // waits for the worker
    DocumentJob(const DocumentJob&) = delete;
    DocumentJob& operator=(const DocumentJob&) = delete;

    DocumentAction action() const { return mAction; }
    const std::filesystem::path& file() const { return mFile; }
    // "Opening meadow", "Importing rock.glb": what the window and the log call it.
    std::string title() const;
    bool done() const { return mDone.load(); }
    void wait();  // until done()
    // What the work is doing now ("reading grid8m.glb"), and how long the job has run.
    std::string stage() const;
    double elapsedS() const;
    // For the work: says what it does next.
    void setStage(std::string stage);
    // Asks the work to stop: it looks between its stages (cancelled(), or the growing through
    // stopToken()), and the delay ends at once. A cancelled job's result is an error nobody
    // shows.
    void cancel() { mStop.request_stop(); }
    bool cancelled() const { return mStop.stop_requested(); }
    std::stop_token stopToken() const { return mStop.get_token(); }
    // Once done(): the grown document or why it could not be grown; taken once.
    Result<GrownDocument> take();

private:
    DocumentAction mAction;
    std::filesystem::path mFile;
    std::chrono::steady_clock::time_point mStart;
    std::atomic<bool> mDone{false};
    std::stop_source mStop;
    mutable std::mutex mMutex;
    std::string mStage;
    std::optional<Result<GrownDocument>> mResult;
    std::thread mWorker;
};

}  // namespace grass::editor
