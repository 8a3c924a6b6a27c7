#include "util/interrupt_stop.h"

#include "util/terminal_line.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

namespace grass::core {

namespace {

// Set by the handler; a lock-free atomic is safe to store from a signal handler.
std::atomic<int> gCaught{0};
static_assert(std::atomic<int>::is_always_lock_free);
// The handler's word to the watcher: a byte written to this pipe (write is async-signal-safe),
// so the watcher sleeps in read() instead of polling (the editor at rest must not wake).
int gWakeFd = -1;

extern "C" void onInterrupt(int sig) {
    int none = 0;
    if (!gCaught.compare_exchange_strong(none, sig))
        _exit(128 + sig);  // the second: at once (_exit is async-signal-safe)
    const char byte = 1;
    [[maybe_unused]] const ssize_t written = ::write(gWakeFd, &byte, 1);
}

}  // namespace

InterruptStop::InterruptStop() {
    gCaught.store(0);
    if (::pipe2(mPipe, O_CLOEXEC) != 0) {
        mPipe[0] = mPipe[1] = -1;  // no watcher: the signals keep their default
        return;
    }
    gWakeFd = mPipe[1];
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, &mPreviousInt);
    sigaction(SIGTERM, &action, &mPreviousTerm);
    // The stop is asked for here, not in the handler: a stop callback may do anything.
    mWatcher = std::thread([this] {
        char byte = 0;
        ssize_t got = 0;
        do
            got = ::read(mPipe[0], &byte, 1);
        while (got < 0 && errno == EINTR);
        // The handler's byte, or the destructor's (no signal: the command is done).
        if (const int sig = gCaught.load(); got == 1 && sig != 0) {
            mSignal.store(sig);
            endProgressLine();
            std::fprintf(stderr, "note: %s: stopping at the next stage (again to end at once)\n",
                         sig == SIGINT ? "interrupted" : "terminated");
            mStop.request_stop();
        }
    });
}

InterruptStop::~InterruptStop() {
    if (mPipe[0] < 0)
        return;
    sigaction(SIGINT, &mPreviousInt, nullptr);
    sigaction(SIGTERM, &mPreviousTerm, nullptr);
    const char byte = 0;
    [[maybe_unused]] const ssize_t written = ::write(mPipe[1], &byte, 1);
    mWatcher.join();
    gWakeFd = -1;
    ::close(mPipe[0]);
    ::close(mPipe[1]);
}

}  // namespace grass::core
