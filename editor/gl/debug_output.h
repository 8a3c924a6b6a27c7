// GL debug output to the log (stderr): errors and performance warnings from the driver, with
// the labels we gave objects. Enabled by --gl-debug and in the debug preset.
#pragma once

namespace grass::gl {

void enableDebugOutput();

}  // namespace grass::gl
