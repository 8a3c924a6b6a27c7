// A GL test's image against its reference under tests/data/golden/ (metric: image_compare.h).
// GRASS_UPDATE_GOLDEN=1 writes the reference instead; look at it before committing it.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "gl/framebuffer.h"
#include "support/image_compare.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {

struct GoldenTolerance {
    int pixelThreshold = 48;           // levels a channel may move before the pixel counts
    double maxDifferingShare = 0.005;  // share of pixels that may count
    double maxMeanAbs = 1.0;           // mean |difference| in levels
};

// Fails the test (naming the reference and where this render was written) when `image` is
// further from tests/data/golden/<name>.png than `tolerance`.
inline void expectMatchesGolden(const std::string& name, const gl::Rgba8Image& image,
                                const GoldenTolerance& tolerance) {
    const auto reference = sourceDir() / "tests/data/golden" / (name + ".png");
    const char* update = std::getenv("GRASS_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        EXPECT_TRUE(writeRgba8Image(reference, image.width, image.height, image.pixels).ok());
        return;
    }
    auto expected = readRgba8Image(reference);
    ASSERT_TRUE(expected.ok()) << expected.error().str()
                               << " (GRASS_UPDATE_GOLDEN=1 writes the reference)";
    const ImageDifference diff =
        compareImages(image.pixels, expected->pixels, tolerance.pixelThreshold);
    std::printf("[ golden ] %s differing %.4f, mean abs %.3f, max %d\n", name.c_str(),
                diff.differingShare, diff.meanAbs, diff.maxChannel);
    if (diff.differingShare > tolerance.maxDifferingShare || diff.meanAbs > tolerance.maxMeanAbs) {
        // Not scratchDir: it empties the folder, and golden tests run side by side would delete
        // each other's failure pictures.
        const auto actual = sharedDir("golden-actual") / (name + ".actual.png");
        EXPECT_TRUE(writeRgba8Image(actual, image.width, image.height, image.pixels).ok());
        ADD_FAILURE() << name << " differs from " << reference << ": share " << diff.differingShare
                      << ", mean " << diff.meanAbs << "; this render is in " << actual;
    }
}

}  // namespace grass::test
