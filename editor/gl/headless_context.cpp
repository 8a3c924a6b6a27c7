#include "gl/headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "gl/debug_output.h"
#include "util/egl_vendor_dirs.h"
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

// Lets glvnd see a GPU driver whose vendor file lies outside its search folders. Must run
// before the first EGL call: glvnd reads the variable once, when libEGL loads.
void addDriverEglVendorFolders() {
    if (const auto dirs = core::eglVendorDirsValue(std::getenv("__EGL_VENDOR_LIBRARY_FILENAMES"),
                                                   std::getenv("__EGL_VENDOR_LIBRARY_DIRS"),
                                                   core::folderHoldsJsonFile))
        setenv("__EGL_VENDOR_LIBRARY_DIRS", dirs->c_str(), 0);
}

bool initialise(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    return display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor);
}

struct EglDevice {
    EGLDeviceEXT handle;
    bool software;  // Mesa marks its software rasteriser with EGL_MESA_device_software
};

// The GPUs and software rasterisers EGL_EXT_platform_device lists.
std::vector<EglDevice> listDevices(const char* clientExtensions) {
    if (!hasExtension(clientExtensions, "EGL_EXT_platform_device") ||
        !hasExtension(clientExtensions, "EGL_EXT_device_enumeration"))
        return {};
    EGLDeviceEXT listed[16];
    EGLint count = 0;
    if (!eglQueryDevicesEXT(16, listed, &count))
        return {};
    const bool queryable = hasExtension(clientExtensions, "EGL_EXT_device_query");
    std::vector<EglDevice> devices;
    for (EGLint i = 0; i < count; ++i)
        devices.push_back(
            {listed[i], queryable && hasExtension(eglQueryDeviceStringEXT(listed[i], EGL_EXTENSIONS),
                                                  "EGL_MESA_device_software")});
    return devices;
}

// A display without a window system: a GPU through EGL_EXT_platform_device (NVIDIA's way; Mesa
// lists its GPUs there too), else Mesa's surfaceless platform (llvmpipe when there is no GPU),
// else a software device. Returns EGL_NO_DISPLAY with `why` filled when none initialises.
// GRASS_EGL_PLATFORM=surfaceless or device tries that platform alone (tests reach the device
// platform on llvmpipe with it).
EGLDisplay openDisplay(const std::string& only, std::string& why) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const std::vector<EglDevice> devices =
        only == "surfaceless" ? std::vector<EglDevice>{} : listDevices(clientExtensions);
    const auto openDevice = [&](bool software) {
        for (const EglDevice& device : devices) {
            if (device.software != software)
                continue;
            EGLDisplay display =
                eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device.handle, nullptr);
            if (initialise(display))
                return display;
        }
        return EGL_NO_DISPLAY;
    };
    if (only != "surfaceless")
        if (EGLDisplay display = openDevice(false); display != EGL_NO_DISPLAY)
            return display;
    if (only != "device" && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (initialise(display))
            return display;
        why = "the surfaceless display (" + eglErrorName(eglGetError()) + ")";
    }
    if (only != "surfaceless") {
        if (EGLDisplay display = openDevice(true); display != EGL_NO_DISPLAY)
            return display;
        if (!devices.empty() || !why.empty())
            why += std::string(why.empty() ? "" : ", ") + std::to_string(devices.size()) +
                   " EGL device" + (devices.size() == 1 ? "" : "s");
    }
    if (why.empty())
        why = only.empty() ? "neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device "
                             "is offered"
                           : "the " + only + " platform is not offered";
    return EGL_NO_DISPLAY;
}

// EGL_KHR_no_config_context lets a context exist without a surface format; where a driver lacks
// it, any config that renders desktop OpenGL does (rendering goes to framebuffer objects).
EGLConfig contextConfig(EGLDisplay display) {
    if (hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
        return EGL_NO_CONFIG_KHR;
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = EGL_NO_CONFIG_KHR;
    EGLint count = 0;
    eglChooseConfig(display, wanted, &config, 1, &count);
    return count > 0 ? config : EGL_NO_CONFIG_KHR;
}

}  // namespace

Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create(bool debugOutput) {
    addDriverEglVendorFolders();
    std::string only = std::getenv("GRASS_EGL_PLATFORM") ? std::getenv("GRASS_EGL_PLATFORM") : "";
    if (only == "auto")
        only.clear();
    if (!only.empty() && only != "surfaceless" && only != "device")
        return makeError("GRASS_EGL_PLATFORM",
                         "'" + only + "' is not a platform: use auto, surfaceless or device");
    std::string why;
    EGLDisplay display = openDisplay(only, why);
    if (display == EGL_NO_DISPLAY)
        return makeError("EGL", "cannot open a headless EGL display: " + why +
                                    ". Install Mesa's EGL (apt-get install libegl1 "
                                    "libegl-mesa0 libgl1-mesa-dri) or a GPU driver's EGL");
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
    EGLContext context =
        eglCreateContext(display, contextConfig(display), EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        const std::string error = eglErrorName(eglGetError());
        eglTerminate(display);
        return makeError("EGL", "cannot create an OpenGL 4.5 core context (" + error +
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
