// ThreadPool (core/util/thread_pool.h): every index of a run is visited exactly once, in
// contiguous ranges, whatever the task and worker counts, and the pool is reused run after run.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "util/thread_pool.h"

namespace grass::core {
namespace {

void expectEachIndexOnce(ThreadPool& pool, std::size_t count, std::size_t tasks) {
    std::vector<std::atomic<int>> visits(count);
    std::atomic<std::size_t> calls{0};
    pool.run(count, tasks, [&](std::size_t begin, std::size_t end) {
        EXPECT_LE(begin, end);
        EXPECT_LE(end, count);
        for (std::size_t i = begin; i < end; ++i)
            visits[i].fetch_add(1);
        calls.fetch_add(1);
    });
    for (std::size_t i = 0; i < count; ++i)
        ASSERT_EQ(visits[i].load(), 1) << "index " << i << " of " << count << ", " << tasks << " tasks";
    EXPECT_LE(calls.load(), std::max<std::size_t>(tasks, 1));
}

TEST(ThreadPool, VisitsEveryIndexOnceForAnyTaskCount) {
    ThreadPool pool(3);
    EXPECT_EQ(pool.workerCount(), 3u);
    for (const std::size_t count : {0u, 1u, 7u, 1000u, 4099u})
        for (const std::size_t tasks : {0u, 1u, 2u, 4u, 9u, 5000u})
            expectEachIndexOnce(pool, count, tasks);
}

TEST(ThreadPool, WithoutWorkersTheCallerDoesEverything) {
    ThreadPool pool(0);
    expectEachIndexOnce(pool, 100, 4);
}

TEST(ThreadPool, IsReusedRunAfterRun) {
    ThreadPool& pool = ThreadPool::shared();
    std::atomic<long> sum{0};
    for (int run = 0; run < 2000; ++run)
        pool.run(64, pool.workerCount() + 1, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i)
                sum.fetch_add(long(i));
        });
    EXPECT_EQ(sum.load(), 2000L * (63L * 64L / 2L));
}

// Two threads running loops on one pool at once (the editor's worker growing a field, whose
// bending cues use the shared pool, while the frame steps the CPU physics on it): every run
// still visits each of its indices once. Before, the second run took over the first one's tasks
// half way and the runs lost or repeated ranges, or waited for ever.
TEST(ThreadPool, RunsFromTwoThreadsAtOnceEachVisitTheirIndicesOnce) {
    ThreadPool pool(2);
    std::vector<std::thread> callers;
    for (int caller = 0; caller < 2; ++caller)
        callers.emplace_back([&pool] {
            for (int run = 0; run < 300; ++run)
                expectEachIndexOnce(pool, 1000, 4);
        });
    for (std::thread& caller : callers)
        caller.join();
}

}  // namespace
}  // namespace grass::core
