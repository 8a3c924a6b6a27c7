// GL debug output to the log (stderr): errors and performance warnings from the driver, with
// the labels we gave objects. Enabled by --gl-debug and in the debug preset. The messages are
// also counted, so the GL tests can assert that none was an error (issue 11).
#pragma once

#include <cstdint>
#include <string>

namespace grass::gl {

void enableDebugOutput();

// What debug output reported since the process started (every context, every thread).
struct DebugOutputCounts {
    // GL_DEBUG_TYPE_ERROR and GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR from the API, the window system
    // and the driver. The shader compiler's messages are counted apart: a shader that does not
    // compile is reported through its info log, which Program turns into an error of ours.
    std::uint64_t errors = 0;
    std::uint64_t compilerMessages = 0;
    std::uint64_t warnings = 0;  // every other type, notifications left out
    std::string lastError;       // the driver's text of the latest error
};
DebugOutputCounts debugOutputCounts();

// Debug builds (the `debug` preset) turn GL debug output on by default.
#ifdef GRASS_GL_DEBUG_DEFAULT
inline constexpr bool GL_DEBUG_BY_DEFAULT = true;
#else
inline constexpr bool GL_DEBUG_BY_DEFAULT = false;
#endif

}  // namespace grass::gl
