// The version of grass, as CMakeLists.txt's project() states it: what `grass --version`,
// `grass-editor --version` and the editor's Help › About say.
#pragma once

#include <string_view>

namespace grass::core {

std::string_view versionText();

}  // namespace grass::core
