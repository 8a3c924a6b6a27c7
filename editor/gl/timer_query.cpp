#include "gl/timer_query.h"

namespace grass::gl {

GpuTimer::GpuTimer() {
    GLuint id = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &id);
    mQuery = QueryHandle(id);
}

void GpuTimer::begin() {
    mLastSynchronous = mSynchronous;
    if (mSynchronous) {
        glFinish();
        mStart = std::chrono::steady_clock::now();
        return;
    }
    glBeginQuery(GL_TIME_ELAPSED, mQuery.id());
}

void GpuTimer::end() {
    mUsed = true;
    if (mLastSynchronous) {
        glFinish();
        mWallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mStart)
                      .count();
        return;
    }
    glEndQuery(GL_TIME_ELAPSED);
}

double GpuTimer::milliseconds() const {
    if (!mUsed)
        return 0.0;
    if (mLastSynchronous)
        return mWallMs;
    GLuint64 ns = 0;
    glGetQueryObjectui64v(mQuery.id(), GL_QUERY_RESULT, &ns);
    return static_cast<double>(ns) * 1e-6;
}

}  // namespace grass::gl
