// One headless GL context for every GL test of the executable. Without one, each test fails
// with the reason (STYLE.md §9: never a silent skip; CI has llvmpipe).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <memory>

#include "gl/headless_context.h"

namespace grass::test {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    void SetUp() override;
    // Fails the test when GL debug output reported an error during it (the context is created
    // with debug output on): a GL error is a bug even when the pixels come out right.
    void TearDown() override;
    static std::unique_ptr<gl::HeadlessContext>& context();
    static std::string& contextError();

private:
    std::uint64_t mDebugErrorsAtStart = 0;
};

// For the editor run as a process with --gl-debug: fails the test for every "GL error:" line
// of its log (debug_output.cpp's format).
void expectNoGlErrorLines(const std::filesystem::path& log);

// Share of pixels whose colour is grass-like: green clearly above red and blue.
double grassPixelShare(const std::vector<std::uint8_t>& rgba);

}  // namespace grass::test
