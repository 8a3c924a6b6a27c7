#include "util/interrupt_stop.h"

#include "util/terminal_line.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <ctime>

namespace grass::core {

namespace {

// Set by the handler; a lock-free atomic is safe to store from a signal handler.
std::atomic<int> gCaught{0};
static_assert(std::atomic<int>::is_always_lock_free);
// When the first came (CLOCK_MONOTONIC, ns; 0: none yet), to tell a second request from the
// first relayed twice.
std::atomic<std::int64_t> gCaughtAtNs{0};
static_assert(std::atomic<std::int64_t>::is_always_lock_free);
// The handler's word to the watcher: a byte written to this pipe (write is async-signal-safe),
// so the watcher sleeps in read() instead of polling (the editor at rest must not wake).
int gWakeFd = -1;

std::int64_t monotonicNs() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe (POSIX)
    return std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
}

extern "C" void onInterrupt(int sig) {
    const std::int64_t now = monotonicNs();
    std::int64_t first = 0;
    if (!gCaughtAtNs.compare_exchange_strong(first, now)) {
        // One Ctrl+C can arrive twice: `timeout` relays a signal to the command and again to
        // its process group, and a multi-threaded process may take both (one per thread) before
        // they merge. Two within the window are that one request; no hand presses twice so fast.
        if (now - first < InterruptStop::SAME_REQUEST_NS)
            return;
        _exit(128 + sig);  // the second: at once (_exit is async-signal-safe)
    }
    gCaught.store(sig);
    const char byte = 1;
    [[maybe_unused]] const ssize_t written = ::write(gWakeFd, &byte, 1);
}

}  // namespace

InterruptStop::InterruptStop() {
    gCaught.store(0);
    gCaughtAtNs.store(0);
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
