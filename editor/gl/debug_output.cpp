#include "debug_output.h"

#include <epoxy/gl.h>

#include <cstdio>

namespace grass::gl {

static void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                                      const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION)
        return;
    const char* kind = type == GL_DEBUG_TYPE_ERROR ? "error" : "warning";
    std::fprintf(stderr, "GL %s: %s\n", kind, message);
}

void enableDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
}

}  // namespace grass::gl
