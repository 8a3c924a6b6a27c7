#include "gl/headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstring>

#include "gl/debug_output.h"
#include "util/software_renderer.h"

namespace grass::gl {

namespace {

std::string eglErrorName(EGLint code) {
    switch (code) {
        case EGL_NOT_INITIALIZED:
            return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_CONFIG:
            return "EGL_BAD_CONFIG";
        case EGL_BAD_ATTRIBUTE:
            return "EGL_BAD_ATTRIBUTE";
        default:
            return "EGL error " + std::to_string(code);
    }
}

bool hasExtension(const char* list, const char* name) {
    if (!list)
        return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    return false;
}

}  // namespace

Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create(bool debugOutput) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
        return makeError("EGL",
                         "EGL_MESA_platform_surfaceless is not available: install Mesa's "
                         "EGL (apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri)");
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
        return makeError("EGL", "cannot initialise the surfaceless display (" +
                                    eglErrorName(eglGetError()) +
                                    "): is libgl1-mesa-dri installed?");
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(display);
        return makeError("EGL", "desktop OpenGL is not available through EGL");
    }
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_CONTEXT_OPENGL_DEBUG,
                                 debugOutput ? EGL_TRUE : EGL_FALSE,
                                 EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        const std::string why = eglErrorName(eglGetError());
        eglTerminate(display);
        return makeError("EGL", "cannot create an OpenGL 4.5 core context (" + why +
                                    "): the driver is too old (Mesa 20+ llvmpipe works)");
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        eglTerminate(display);
        return makeError("EGL", "cannot make the context current");
    }
    std::unique_ptr<HeadlessContext> result(new HeadlessContext());
    result->mDisplay = display;
    result->mContext = context;
    if (debugOutput)
        enableDebugOutput();
    return result;
}

HeadlessContext::~HeadlessContext() {
    auto display = static_cast<EGLDisplay>(mDisplay);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(mContext));
    eglTerminate(display);
}

std::string rendererDescription() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return std::string(renderer ? renderer : "?") + " | " + (version ? version : "?");
}

bool isSoftwareRenderer() {
    return core::isSoftwareRendererName(reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
}

}  // namespace grass::gl
