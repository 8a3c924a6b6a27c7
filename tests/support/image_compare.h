// The per-pixel metric of the golden-image tests (tests/gl/golden_gl_test.cpp): how many pixels
// differ visibly from the reference, and by how much on average.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace grass::test {

struct ImageDifference {
    double meanAbs = 0.0;        // mean |a − b| over RGB channels, in 0..255 levels
    double differingShare = 0.0; // share of pixels whose largest channel difference > threshold
    int maxChannel = 0;          // largest single channel difference
};

// Both images RGBA8 of the same size; alpha is ignored.
inline ImageDifference compareImages(const std::vector<std::uint8_t>& a,
                                     const std::vector<std::uint8_t>& b, int pixelThreshold) {
    ImageDifference out;
    const std::size_t pixels = std::min(a.size(), b.size()) / 4;
    if (pixels == 0 || a.size() != b.size()) {
        out.meanAbs = 255.0;
        out.differingShare = 1.0;
        out.maxChannel = 255;
        return out;
    }
    std::uint64_t sum = 0;
    std::size_t differing = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        int largest = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int d = std::abs(int(a[4 * p + c]) - int(b[4 * p + c]));
            sum += static_cast<std::uint64_t>(d);
            largest = std::max(largest, d);
        }
        out.maxChannel = std::max(out.maxChannel, largest);
        if (largest > pixelThreshold)
            ++differing;
    }
    out.meanAbs = static_cast<double>(sum) / (3.0 * static_cast<double>(pixels));
    out.differingShare = static_cast<double>(differing) / static_cast<double>(pixels);
    return out;
}

}  // namespace grass::test
