// GpuTimer: GL_TIME_ELAPSED queries around a pass. Results are read when asked (after the
// frame), so the frame loop never stalls on them (issue 5: statistics a frame late).
//
// On a software rasterizer (Mesa llvmpipe) a query does not time its pass: vertex work runs on
// the app's thread as draws are issued, and the query's stamps are taken when the deferred scene
// runs, so one pass's range absorbs the next pass's work. Measured on the meadow (issue 24): the
// cull pass read 170-220 ms while it takes 13-15 ms, and the grass's vertex work was counted as
// culling. A synchronous timer finishes the GL work at begin and at end and reads the wall clock:
// exact on any driver, at the price of a stall, so renderers use it on software GL only, and only
// in frames whose figures are read.
#pragma once

#include <chrono>

#include "gl/gl_handle.h"

namespace grass::gl {

class GpuTimer {
public:
    GpuTimer();
    // Takes effect from the next begin().
    void setSynchronous(bool synchronous) { mSynchronous = synchronous; }
    void begin();
    void end();
    // Milliseconds of the last begin/end pair; waits for the result if it is not ready.
    double milliseconds() const;

private:
    QueryHandle mQuery;
    bool mUsed = false;
    bool mSynchronous = false;
    bool mLastSynchronous = false;  // how the last begin/end pair was timed
    std::chrono::steady_clock::time_point mStart;
    double mWallMs = 0.0;
};

}  // namespace grass::gl
