#include "cli/interrupt_stop.h"

#include <pthread.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>

namespace grass::cli {

namespace {

sigset_t interruptSignals() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    return set;
}

}  // namespace

InterruptStop::InterruptStop() {
    const sigset_t set = interruptSignals();
    pthread_sigmask(SIG_BLOCK, &set, &mPrevious);
    mWatcher = std::thread([this, set] {
        // Looks every 0.1 s whether the command is done, since nothing else ends the wait.
        const timespec tick{0, 100'000'000};
        while (!mDone.load()) {
            const int sig = sigtimedwait(&set, nullptr, &tick);
            if (sig <= 0)
                continue;
            if (mSignal.load() != 0)
                std::_Exit(128 + sig);  // the second: at once
            mSignal.store(sig);
            std::fprintf(stderr, "note: %s: stopping at the next stage (again to end at once)\n",
                         sig == SIGINT ? "interrupted" : "terminated");
            mStop.request_stop();
        }
    });
}

InterruptStop::~InterruptStop() {
    mDone.store(true);
    mWatcher.join();
    pthread_sigmask(SIG_SETMASK, &mPrevious, nullptr);
}

}  // namespace grass::cli
