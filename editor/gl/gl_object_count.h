// Live GL objects per kind (issue 11): every GL name editor/gl and editor/render create is owned
// by one GlHandle (STYLE.md §5), which counts it here when it takes a name and when it deletes it.
// `grass soak` and the GL tests compare the counts before and after a run to find leaks. GL has no
// query for the number of live objects, and probing names with glIsBuffer & co. is unreliable
// (names are reused, and a name reserved by glGen* is not yet an object), so these counters are
// the measure: they see every object our wrappers own, and nothing created outside them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace grass::gl {

enum class GlObjectKind : std::uint8_t {
    Buffer,
    VertexArray,
    Texture,
    Framebuffer,
    Renderbuffer,
    Program,
    Shader,
    Query,
};
inline constexpr std::size_t GL_OBJECT_KIND_COUNT = 8;

// "buffers", "vertex arrays", ... (plural, for tables).
const char* glObjectKindName(GlObjectKind kind);

struct GlObjectCounts {
    std::array<std::int64_t, GL_OBJECT_KIND_COUNT> live{};

    std::int64_t operator[](GlObjectKind kind) const {
        return live[static_cast<std::size_t>(kind)];
    }
    std::int64_t total() const;
    // True when no kind has more live objects than in `before`.
    bool noMoreThan(const GlObjectCounts& before) const;
    // "3 buffers, 1 vertex array, ..." (kinds with a count only; "none" when all are 0).
    std::string str() const;
    bool operator==(const GlObjectCounts&) const = default;
};

// The objects alive now, in this process (all contexts together).
GlObjectCounts liveGlObjects();

// Called by GlHandle only.
void countGlObjectCreated(GlObjectKind kind);
void countGlObjectDeleted(GlObjectKind kind);

}  // namespace grass::gl
