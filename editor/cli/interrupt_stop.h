// Ctrl+C (SIGINT) or SIGTERM during `grass export`: the first asks the work to stop at its next
// stage (a std::stop_token the command passes on), so the export ends with its staged files
// removed, the folder as it was, and says so; a second ends the process at once. Before, the
// process died where it stood: the folder stayed whole (the renames come last) but the staged
// temporaries stayed until the next export there, and nothing said what had happened.
#pragma once

#include <atomic>
#include <csignal>
#include <stop_token>
#include <thread>

namespace grass::cli {

class InterruptStop {
public:
    // Blocks SIGINT and SIGTERM in the calling thread (and so in the threads it starts later)
    // and waits for them on a thread of its own. Threads started before keep their mask: a
    // signal one of them takes ends the process as before.
    InterruptStop();
    ~InterruptStop();  // the signals' mask as it was
    InterruptStop(const InterruptStop&) = delete;
    InterruptStop& operator=(const InterruptStop&) = delete;

    std::stop_token token() const { return mStop.get_token(); }
    // The signal that asked for the stop (0: none yet).
    int signal() const { return mSignal.load(); }
    // What a command stopped by it exits with: 128 + the signal, as the shell reports a death
    // by it.
    int exitCode() const { return 128 + signal(); }

private:
    std::stop_source mStop;
    std::atomic<int> mSignal{0};
    std::atomic<bool> mDone{false};
    sigset_t mPrevious{};
    std::thread mWatcher;
};

}  // namespace grass::cli
