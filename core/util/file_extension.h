// A file's extension as a reader decides by it: lower case, with its dot (".glb" for
// "Rock.GLB"), so that a name written on another system still finds its reader.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace grass {

inline std::string asciiLowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

inline std::string lowerExtension(const std::filesystem::path& file) {
    return asciiLowerCase(file.extension().string());
}

}  // namespace grass
