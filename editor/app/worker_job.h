// A result computed on a worker thread and taken once by the window: the plumbing the editor's
// small background jobs share (packing a collider's spheres, reading a collider's mesh). The
// work must not touch the window's state; it gets copies of what it needs.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <thread>
#include <utility>

namespace grass::editor {

template <class T>
class WorkerJob {
public:
    // Starts `work` on a worker; `whenDone` is called on the worker once done() is true
    // (EditorState::wakeFrame, so a window at rest takes the result in at once).
    explicit WorkerJob(std::function<T()> work, std::function<void()> whenDone = {})
        : mWorker([this, work = std::move(work), whenDone = std::move(whenDone)] {
              mResult.emplace(work());
              mDone.store(true);
              if (whenDone)
                  whenDone();
          }) {}
    ~WorkerJob() { wait(); }
    WorkerJob(const WorkerJob&) = delete;
    WorkerJob& operator=(const WorkerJob&) = delete;

    bool done() const { return mDone.load(); }
    void wait() {
        if (mWorker.joinable())
            mWorker.join();
    }
    // The result, once: waits for it when the work is not done yet.
    T take() {
        wait();
        T result = std::move(*mResult);
        mResult.reset();
        return result;
    }

private:
    std::atomic<bool> mDone{false};
    std::optional<T> mResult;
    std::thread mWorker;  // last: started once the members it writes exist
};

}  // namespace grass::editor
