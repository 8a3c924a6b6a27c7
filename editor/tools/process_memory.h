// What this process holds in memory, for `grass soak` (growth over hours) and `grass bench`
// (peak memory per blade at scale, issue 29). Linux: /proc and getrusage; 0 where unknown.
#pragma once

#include <cstdint>

namespace grass::tools {

// The resident set size now (/proc/self/statm).
std::uint64_t residentBytes();
// The largest resident set size this process has had so far (getrusage ru_maxrss).
std::uint64_t peakResidentBytes();
// What malloc has handed out and not had back (glibc's mallinfo2).
std::uint64_t heapInUseBytes();

}  // namespace grass::tools
