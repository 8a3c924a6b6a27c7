// A progress line rewritten in place on a terminal ("\r…" with no newline until the work ends)
// leaves stderr in the middle of a line: a message written meanwhile by another part (the
// interrupt's note, from its watcher thread) would land at the line's end. The progress line
// says it is open; whoever writes a message of their own first ends it, and the progress ends it
// only if nobody did.
#pragma once

#include <cstdio>

namespace grass::core {

// Called after writing a progress line that is left open (no newline).
void markProgressLineOpen();
// Ends an open progress line with a newline on `out` (once: the flag is cleared); false when
// none was open.
bool endProgressLine(std::FILE* out = stderr);

}  // namespace grass::core
