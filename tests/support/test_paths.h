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

}  // namespace grass::test
