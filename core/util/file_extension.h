// A file's extension as a reader decides by it: lower case, with its dot (".glb" for
// "Rock.GLB"), so that a name written on another system still finds its reader.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace grass {

inline std::string asciiLowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

inline std::string lowerExtension(const std::filesystem::path& file) {
    return asciiLowerCase(file.extension().string());
}

// The extensions of the image formats maps and textures are read from (util/image_open.h: PNG,
// JPEG, TIFF, OpenEXR, TGA, BMP, GIF, WebP, Radiance HDR, PNM): what a file browser offers.
inline const std::vector<std::string>& readableImageExtensions() {
    static const std::vector<std::string> EXTENSIONS{
        ".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr", ".tga", ".bmp",
        ".gif", ".webp", ".hdr", ".pgm", ".ppm", ".pbm", ".pnm", ".pfm"};
    return EXTENSIONS;
}

}  // namespace grass
