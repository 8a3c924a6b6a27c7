// Where tests find the source tree (projects, shaders) and where they may write scratch files.
#pragma once

#include <filesystem>
#include <string>

namespace grass::test {

std::filesystem::path sourceDir();
// A fresh, empty folder for one test: <build>/test-tmp/<name>. CTest runs tests in parallel and
// this empties the folder: two tests must not share a name (FontAtlas.TruncatedFontIsRejected
// lost its file to its neighbour's "font" on a fresh clone).
std::filesystem::path scratchDir(const std::string& name);
// A folder that tests running side by side may share, never emptied: <build>/test-tmp/<name>
// (created if missing). For what a failure leaves for the developer to look at.
std::filesystem::path sharedDir(const std::string& name);

}  // namespace grass::test
