// GL debug output to the log (stderr): errors and performance warnings from the driver, with
// the labels we gave objects. Enabled by --gl-debug and in the debug preset.
#pragma once

namespace grass::gl {

void enableDebugOutput();

// Debug builds (the `debug` preset) turn GL debug output on by default.
#ifdef GRASS_GL_DEBUG_DEFAULT
inline constexpr bool GL_DEBUG_BY_DEFAULT = true;
#else
inline constexpr bool GL_DEBUG_BY_DEFAULT = false;
#endif

}  // namespace grass::gl
