// ThreadPool: worker threads started once and reused for every parallel loop (the CPU physics
// runs one loop per step, 60 a second: starting threads each step cost more than small fields'
// work). run() splits [0, count) into `tasks` contiguous ranges, runs them on the workers and the
// calling thread, and returns when all are done. One run at a time per pool: a run called while
// another thread's run holds the workers (the editor's worker growing a field while the frame
// steps the CPU physics) does its tasks on its own thread instead of waiting.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace grass::core {

class ThreadPool {
public:
    // `workers` threads besides the caller's (0: the caller does everything).
    explicit ThreadPool(unsigned workers);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    unsigned workerCount() const { return static_cast<unsigned>(mWorkers.size()); }
    // fn(begin, end) over `tasks` contiguous ranges of [0, count) (tasks ≥ 1; more than the
    // workers + 1 run in turn). fn must not throw.
    void run(std::size_t count, std::size_t tasks,
             const std::function<void(std::size_t begin, std::size_t end)>& fn);

    // The pool the physics shares: hardware concurrency − 1 workers, at most 7, started on first
    // use.
    static ThreadPool& shared();

private:
    // Task `task` of `tasks` over [0, count): contiguous, in order.
    static std::pair<std::size_t, std::size_t> taskRange(std::size_t count, std::size_t tasks,
                                                         std::size_t task);
    void workerLoop();
    bool takeTask(std::size_t& task);
    std::vector<std::thread> mWorkers;
    std::mutex mRunning;  // held by the run that has the workers
    std::mutex mMutex;
    std::condition_variable mWake;
    std::condition_variable mDone;
    const std::function<void(std::size_t, std::size_t)>* mFn = nullptr;
    std::size_t mCount = 0;
    std::size_t mTasks = 0;
    std::size_t mNextTask = 0;
    std::size_t mFinished = 0;
    std::size_t mGeneration = 0;
    bool mStop = false;
};

}  // namespace grass::core
