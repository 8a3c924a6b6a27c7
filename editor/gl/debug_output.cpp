#include "gl/debug_output.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <mutex>

namespace grass::gl {

namespace {

std::mutex& countsMutex() {
    static std::mutex mutex;
    return mutex;
}

DebugOutputCounts& counts() {
    static DebugOutputCounts instance;
    return instance;
}

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint, GLenum severity, GLsizei,
                               const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION)
        return;
    const bool compiler = source == GL_DEBUG_SOURCE_SHADER_COMPILER;
    const bool error =
        !compiler && (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR);
    std::fprintf(stderr, "GL %s: %s\n", compiler ? "shader compiler" : error ? "error" : "warning",
                 message);
    const std::lock_guard lock(countsMutex());
    if (compiler) {
        ++counts().compilerMessages;
    } else if (error) {
        ++counts().errors;
        counts().lastError = message;
    } else {
        ++counts().warnings;
    }
}

}  // namespace

void enableDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
}

DebugOutputCounts debugOutputCounts() {
    const std::lock_guard lock(countsMutex());
    return counts();
}

}  // namespace grass::gl
