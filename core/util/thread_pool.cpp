#include "util/thread_pool.h"

#include <algorithm>

namespace grass::core {

ThreadPool::ThreadPool(unsigned workers) {
    mWorkers.reserve(workers);
    for (unsigned i = 0; i < workers; ++i)
        mWorkers.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(mMutex);
        mStop = true;
    }
    mWake.notify_all();
    for (std::thread& worker : mWorkers)
        worker.join();
}

ThreadPool& ThreadPool::shared() {
    static ThreadPool pool(std::clamp(std::thread::hardware_concurrency(), 1u, 8u) - 1u);
    return pool;
}

std::pair<std::size_t, std::size_t> ThreadPool::taskRange(std::size_t count, std::size_t tasks,
                                                          std::size_t task) {
    const std::size_t chunk = (count + tasks - 1) / tasks;
    const std::size_t begin = std::min(count, task * chunk);
    return {begin, std::min(count, begin + chunk)};
}

// Under the lock: the next task of the current run, if any is left.
bool ThreadPool::takeTask(std::size_t& task) {
    if (mFn == nullptr || mNextTask >= mTasks)
        return false;
    task = mNextTask++;
    return true;
}

void ThreadPool::run(std::size_t count, std::size_t tasks,
                     const std::function<void(std::size_t, std::size_t)>& fn) {
    tasks = std::max<std::size_t>(std::min(tasks, std::max<std::size_t>(count, 1)), 1);
    const auto range = [count, tasks](std::size_t task) { return taskRange(count, tasks, task); };
    std::unique_lock running(mRunning, std::try_to_lock);
    if (tasks == 1 || mWorkers.empty() || !running.owns_lock()) {
        for (std::size_t task = 0; task < tasks; ++task) {
            const auto [begin, end] = range(task);
            fn(begin, end);
        }
        return;
    }
    std::unique_lock lock(mMutex);
    mFn = &fn;
    mCount = count;
    mTasks = tasks;
    mNextTask = 0;
    mFinished = 0;
    ++mGeneration;
    mWake.notify_all();
    // The caller works too, then waits for the stragglers.
    std::size_t task = 0;
    while (takeTask(task)) {
        lock.unlock();
        const auto [begin, end] = range(task);
        fn(begin, end);
        lock.lock();
        ++mFinished;
    }
    mDone.wait(lock, [this] { return mFinished == mTasks; });
    mFn = nullptr;
}

void ThreadPool::workerLoop() {
    std::size_t seen = 0;
    std::unique_lock lock(mMutex);
    while (true) {
        mWake.wait(lock, [&] { return mStop || (mGeneration != seen && mFn != nullptr); });
        if (mStop)
            return;
        seen = mGeneration;
        std::size_t task = 0;
        while (takeTask(task)) {
            const std::function<void(std::size_t, std::size_t)>& fn = *mFn;
            const std::size_t count = mCount, tasks = mTasks;
            lock.unlock();
            const auto [begin, end] = taskRange(count, tasks, task);
            fn(begin, end);
            lock.lock();
            if (++mFinished == mTasks)
                mDone.notify_one();
        }
    }
}

}  // namespace grass::core
