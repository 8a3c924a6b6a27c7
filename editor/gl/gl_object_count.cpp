#include "gl/gl_object_count.h"

#include <atomic>

namespace grass::gl {

namespace {

// The one mutable global of grass_gl (STYLE.md §7 says none, broken here on purpose): a leak
// counter must see every owner in the process, wherever it was made, like a heap profiler's
// counts. Nothing decides behaviour on it; constant-initialised, so no static constructor runs.
constinit std::array<std::atomic<std::int64_t>, GL_OBJECT_KIND_COUNT> gLive{};

constexpr std::array<const char*, GL_OBJECT_KIND_COUNT> KIND_NAMES{
    "buffers",       "vertex arrays", "textures", "framebuffers",
    "renderbuffers", "programs",      "shaders",  "queries"};

}  // namespace

const char* glObjectKindName(GlObjectKind kind) {
    return KIND_NAMES[static_cast<std::size_t>(kind)];
}

std::int64_t GlObjectCounts::total() const {
    std::int64_t sum = 0;
    for (const std::int64_t count : live)
        sum += count;
    return sum;
}

bool GlObjectCounts::noMoreThan(const GlObjectCounts& before) const {
    for (std::size_t i = 0; i < GL_OBJECT_KIND_COUNT; ++i)
        if (live[i] > before.live[i])
            return false;
    return true;
}

std::string GlObjectCounts::str() const {
    std::string text;
    for (std::size_t i = 0; i < GL_OBJECT_KIND_COUNT; ++i) {
        if (live[i] == 0)
            continue;
        if (!text.empty())
            text += ", ";
        text += std::to_string(live[i]) + " " + KIND_NAMES[i];
    }
    return text.empty() ? "none" : text;
}

GlObjectCounts liveGlObjects() {
    GlObjectCounts counts;
    for (std::size_t i = 0; i < GL_OBJECT_KIND_COUNT; ++i)
        counts.live[i] = gLive[i].load(std::memory_order_relaxed);
    return counts;
}

void countGlObjectCreated(GlObjectKind kind) {
    gLive[static_cast<std::size_t>(kind)].fetch_add(1, std::memory_order_relaxed);
}

void countGlObjectDeleted(GlObjectKind kind) {
    gLive[static_cast<std::size_t>(kind)].fetch_sub(1, std::memory_order_relaxed);
}

}  // namespace grass::gl
