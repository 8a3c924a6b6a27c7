#include "gl_context_fixture.h"

#include <fstream>
#include <string>

#include "gl/debug_output.h"

namespace grass::test {

std::unique_ptr<gl::HeadlessContext>& GlTest::context() {
    static std::unique_ptr<gl::HeadlessContext> instance;
    return instance;
}

std::string& GlTest::contextError() {
    static std::string error;
    return error;
}

void GlTest::SetUpTestSuite() {
    if (context() || !contextError().empty())
        return;
    auto created = gl::HeadlessContext::create(/*debugOutput=*/true);
    if (created)
        context() = std::move(*created);
    else
        contextError() = created.error().str();
}

void GlTest::SetUp() {
    ASSERT_TRUE(context()) << "no headless OpenGL 4.5 context: " << contextError();
    mDebugErrorsAtStart = gl::debugOutputCounts().errors;
}

void GlTest::TearDown() {
    const gl::DebugOutputCounts counts = gl::debugOutputCounts();
    EXPECT_EQ(counts.errors, mDebugErrorsAtStart)
        << "GL debug output reported errors during the test; the latest: " << counts.lastError;
}

void expectNoGlErrorLines(const std::filesystem::path& log) {
    std::ifstream file(log);
    EXPECT_TRUE(file.good()) << "cannot read " << log;
    for (std::string line; std::getline(file, line);)
        EXPECT_EQ(line.find("GL error:"), std::string::npos) << log << ": " << line;
}

double grassPixelShare(const std::vector<std::uint8_t>& rgba) {
    std::size_t grass = 0;
    const std::size_t pixels = rgba.size() / 4;
    for (std::size_t i = 0; i < pixels; ++i) {
        const int r = rgba[4 * i], g = rgba[4 * i + 1], b = rgba[4 * i + 2];
        // Blades are shaded green from dark roots to light tips; sky is blue-dominant and the
        // soil red-dominant, so "green exceeds both by 10 %" separates them with margin.
        if (g * 10 > r * 11 && g * 10 > b * 11)
            ++grass;
    }
    return pixels ? static_cast<double>(grass) / static_cast<double>(pixels) : 0.0;
}

}  // namespace grass::test
