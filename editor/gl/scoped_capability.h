// ScopedCapability: sets a GL capability (glEnable/glDisable) for a scope and puts back the
// previous setting on exit, so a pass that needs blending or no culling leaves the state as it
// found it for the next one.
#pragma once

#include <epoxy/gl.h>

namespace grass::gl {

class ScopedCapability {
public:
    ScopedCapability(GLenum capability, bool enable)
        : mCapability(capability), mWasEnabled(glIsEnabled(capability) == GL_TRUE) {
        if (enable)
            glEnable(capability);
        else
            glDisable(capability);
    }
    ~ScopedCapability() {
        if (mWasEnabled)
            glEnable(mCapability);
        else
            glDisable(mCapability);
    }
    ScopedCapability(const ScopedCapability&) = delete;
    ScopedCapability& operator=(const ScopedCapability&) = delete;

private:
    GLenum mCapability;
    bool mWasEnabled;
};

}  // namespace grass::gl
