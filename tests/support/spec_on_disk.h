// The spec OpenImageIO's reader reports for an image file: what a writer really stored (its
// sample type, channel order, offsets, attributes), for tests that check their input first.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>

namespace grass::test {

// An empty spec (no channels) when the file does not open.
inline OIIO::ImageSpec specOnDisk(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in)
        return {};
    OIIO::ImageSpec spec = in->spec();
    in->close();
    return spec;
}

}  // namespace grass::test
