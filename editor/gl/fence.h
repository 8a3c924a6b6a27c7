// Fence: a GL sync object, to learn without waiting whether the commands issued before it are
// done (the live physics asks the GPU whether its steps moved the field only once they ran, so a
// frame never stalls on the answer).
#pragma once

#include <utility>

#include <epoxy/gl.h>

namespace grass::gl {

class Fence {
public:
    Fence() = default;
    ~Fence() { reset(); }
    Fence(Fence&& other) noexcept : mSync(std::exchange(other.mSync, nullptr)) {}
    Fence& operator=(Fence&& other) noexcept {
        if (this != &other) {
            reset();
            mSync = std::exchange(other.mSync, nullptr);
        }
        return *this;
    }
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;

    // After the commands issued so far (a fence placed before is replaced).
    void place() {
        reset();
        mSync = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    }
    bool placed() const { return mSync != nullptr; }
    // Whether the commands before it are done; flushes them so that they will be. Never waits.
    bool passed() const {
        if (mSync == nullptr)
            return false;
        const GLenum state = glClientWaitSync(mSync, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
        return state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED;
    }
    void reset() {
        if (mSync != nullptr)
            glDeleteSync(std::exchange(mSync, nullptr));
    }

private:
    GLsync mSync = nullptr;
};

}  // namespace grass::gl
