// Whether a process id found in a file name (a temporary's, an autosave slot's) still runs
// elsewhere: what decides that its files are left behind rather than in use.
#pragma once

#include <signal.h>
#include <unistd.h>

#include <cerrno>

namespace grass {

// True for a positive id other than this process's that runs, or that we may not ask about
// (kill(pid, 0) fails with anything but "no such process").
inline bool processRunsElsewhere(long pid) {
    return pid > 0 && pid != long(::getpid()) && (::kill(pid_t(pid), 0) == 0 || errno != ESRCH);
}

}  // namespace grass
