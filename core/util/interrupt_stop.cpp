#include "util/interrupt_stop.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace grass::core {

namespace {

// Set by the handler; a lock-free atomic is safe to store from a signal handler.
std::atomic<int> gCaught{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void onInterrupt(int sig) {
    int none = 0;
    if (!gCaught.compare_exchange_strong(none, sig))
        _exit(128 + sig);  // the second: at once (_exit is async-signal-safe)
}

}  // namespace

InterruptStop::InterruptStop() {
    gCaught.store(0);
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, &mPreviousInt);
    sigaction(SIGTERM, &action, &mPreviousTerm);
    // The stop is asked for here, not in the handler: a stop callback may do anything.
    mWatcher = std::thread([this] {
        while (!mDone.load()) {
            if (const int sig = gCaught.load(); sig != 0 && mSignal.load() == 0) {
                mSignal.store(sig);
                std::fprintf(stderr,
                             "note: %s: stopping at the next stage (again to end at once)\n",
                             sig == SIGINT ? "interrupted" : "terminated");
                mStop.request_stop();
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    });
}

InterruptStop::~InterruptStop() {
    mDone.store(true);
    mWatcher.join();
    sigaction(SIGINT, &mPreviousInt, nullptr);
    sigaction(SIGTERM, &mPreviousTerm, nullptr);
}

}  // namespace grass::core
