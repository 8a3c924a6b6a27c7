// Whether a GL_RENDERER string names a software rasterizer (Mesa's llvmpipe and softpipe,
// SwiftShader, lavapipe, ...): where the editor and the runtime pick strips over tessellation
// and the CPU over the compute shader for the physics. Header-only, GL-free.
#pragma once

#include <cstring>

namespace grass::core {

inline bool isSoftwareRendererName(const char* renderer) {
    if (renderer == nullptr)
        return true;
    for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "lavapipe", "Software"})
        if (std::strstr(renderer, name) != nullptr)
            return true;
    return false;
}

}  // namespace grass::core
