// HeadlessContext: an OpenGL 4.5 core context without a window or display, through EGL on
// Mesa's surfaceless platform (llvmpipe works with no GPU) or on a GPU found through
// EGL_EXT_platform_device (NVIDIA). Used by `grass` and the GL tests.
// Rendering goes to framebuffer objects; the context has no default framebuffer.
#pragma once

#include <memory>
#include <string>

#include "util/result.h"

namespace grass::gl {

class HeadlessContext {
public:
    // Creates the context and makes it current on this thread. The error says what failed and
    // which package provides it (libegl1, libgl1-mesa-dri) so the user can fix it.
    static Result<std::unique_ptr<HeadlessContext>> create(bool debugOutput = false);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

private:
    HeadlessContext() = default;
    void* mDisplay = nullptr;
    void* mContext = nullptr;
};

// "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6"
std::string rendererDescription();
// True for CPU rasterizers (llvmpipe, softpipe, SwiftShader, lavapipe), which are slow at
// tessellation (SPEC §7): the Auto geometry path picks strips there.
bool isSoftwareRenderer();

}  // namespace grass::gl
