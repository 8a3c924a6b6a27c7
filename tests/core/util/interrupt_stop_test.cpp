#include "util/interrupt_stop.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

namespace grass::test {
namespace {

using namespace std::chrono_literals;

// What a child of the death tests exits with when the signals left it running.
constexpr int STILL_RUNNING = 7;

// Waits (10 s at most) for the watcher to turn the signal into the stop.
bool stopArrives(const core::InterruptStop& interrupt) {
    const auto giveUp = std::chrono::steady_clock::now() + 10s;
    while (!interrupt.token().stop_requested() && std::chrono::steady_clock::now() < giveUp)
        std::this_thread::sleep_for(5ms);
    return interrupt.token().stop_requested();
}

// Longer than a relayed signal could lag its first: the next one is a second request.
void waitPastTheSameRequestWindow() {
    std::this_thread::sleep_for(std::chrono::nanoseconds(core::InterruptStop::SAME_REQUEST_NS) +
                                50ms);
}

// `timeout 600 grass bench …` and Ctrl+C: timeout relays the SIGINT to grass and again to its
// process group, and grass, busy on several threads, took both apart. Before, the second ended
// the run at once (exit 130, the cases measured lost: CI's cli.bench_tiny_out_compare, 2026-12-06).
TEST(InterruptStopDeathTest, OneSignalRelayedTwiceIsOneRequest) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            core::InterruptStop interrupt;
            std::raise(SIGINT);
            std::raise(SIGINT);
            std::exit(stopArrives(interrupt) && interrupt.signal() == SIGINT ? STILL_RUNNING : 1);
        },
        testing::ExitedWithCode(STILL_RUNNING), "");
}

// Ctrl+C pressed again, later than a relay could be: the process ends at once with 128 + signal.
TEST(InterruptStopDeathTest, ASecondRequestEndsTheProcessAtOnce) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            core::InterruptStop interrupt;
            std::raise(SIGINT);
            if (!stopArrives(interrupt))
                std::exit(1);
            waitPastTheSameRequestWindow();
            std::raise(SIGINT);
            std::exit(STILL_RUNNING);
        },
        testing::ExitedWithCode(128 + SIGINT), "");
}

// Each InterruptStop starts afresh: a signal caught by the one before is not this one's first.
TEST(InterruptStopDeathTest, ANewStopForgetsTheSignalsOfTheOneBefore) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_EXIT(
        {
            {
                core::InterruptStop first;
                std::raise(SIGINT);
                if (!stopArrives(first))
                    std::exit(1);
            }
            waitPastTheSameRequestWindow();
            core::InterruptStop second;
            std::raise(SIGINT);
            std::exit(stopArrives(second) ? STILL_RUNNING : 1);
        },
        testing::ExitedWithCode(STILL_RUNNING), "");
}

}  // namespace
}  // namespace grass::test
