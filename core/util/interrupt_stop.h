// Ctrl+C (SIGINT) or SIGTERM during a long command (`grass export`, `bench`, `tradeoff`, `soak`,
// `sim`) or the editor: the first asks the work to stop at its next stage (a std::stop_token the
// command passes on), so an export ends with its staged files removed and the folder as it was,
// a bench run with the cases measured so far, the editor with its unsaved changes in the
// autosave, and says so; a second ends the process at once (unless it came within
// SAME_REQUEST_NS of the first: that is the first relayed twice). Before, the process died where it
// stood: an export's staged temporaries stayed until the next export there, a bench run's
// finished cases were lost, the editor's changes since the last autosave were lost, and nothing
// said what had happened.
#pragma once

#include <atomic>
#include <csignal>
#include <cstdint>
#include <stop_token>
#include <thread>

namespace grass::core {

class InterruptStop {
public:
    // A second signal sooner than this after the first is the first relayed again (by
    // `timeout`, say), not a second request: 100 ms is below any two presses of Ctrl+C.
    static constexpr std::int64_t SAME_REQUEST_NS = 100'000'000;

    // Catches SIGINT and SIGTERM (a handler, not a blocked mask: the processes a command starts
    // get the default disposition back when they exec) until destroyed. One at a time.
    InterruptStop();
    ~InterruptStop();  // the previous handlers back
    InterruptStop(const InterruptStop&) = delete;
    InterruptStop& operator=(const InterruptStop&) = delete;

    std::stop_token token() const { return mStop.get_token(); }
    // The signal that asked for the stop (0: none yet).
    int signal() const { return mSignal.load(); }
    // What a command stopped by it exits with: 128 + the signal, as the shell reports a death
    // by it.
    int exitCode() const { return 128 + signal(); }
    // exitCode() once a signal came, else `otherwise` (the command's own status).
    int exitCodeOr(int otherwise) const { return signal() != 0 ? exitCode() : otherwise; }

private:
    std::stop_source mStop;
    std::atomic<int> mSignal{0};
    int mPipe[2] = {-1, -1};  // the handler writes, the watcher sleeps reading
    struct sigaction mPreviousInt = {};
    struct sigaction mPreviousTerm = {};
    std::thread mWatcher;
};

}  // namespace grass::core
