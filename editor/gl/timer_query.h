// GpuTimer: GL_TIME_ELAPSED queries around a pass. Results are read when asked (after the
// frame), so the frame loop never stalls on them (issue 5: statistics a frame late).
#pragma once

#include "gl/gl_handle.h"

namespace grass::gl {

class GpuTimer {
public:
    GpuTimer();
    void begin();
    void end();
    // Milliseconds of the last begin/end pair; waits for the result if it is not ready.
    double milliseconds() const;

private:
    QueryHandle mQuery;
    bool mUsed = false;
};

}  // namespace grass::gl
