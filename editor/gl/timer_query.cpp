#include "gl/timer_query.h"

namespace grass::gl {

GpuTimer::GpuTimer() {
    GLuint id = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &id);
    mQuery = QueryHandle(id);
}

void GpuTimer::begin() {
    glBeginQuery(GL_TIME_ELAPSED, mQuery.id());
}

void GpuTimer::end() {
    glEndQuery(GL_TIME_ELAPSED);
    mUsed = true;
}

double GpuTimer::milliseconds() const {
    if (!mUsed)
        return 0.0;
    GLuint64 ns = 0;
    glGetQueryObjectui64v(mQuery.id(), GL_QUERY_RESULT, &ns);
    return static_cast<double>(ns) * 1e-6;
}

}  // namespace grass::gl
