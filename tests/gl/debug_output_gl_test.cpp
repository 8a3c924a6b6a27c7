// The GL tests' debug-output check can fail: a real API error reaches the counter that
// GlTest::TearDown asserts on (issue 11: GL debug output reports no errors during the GL tests).
#include <epoxy/gl.h>

#include "gl/debug_output.h"
#include "gl_context_fixture.h"

namespace grass::test {
namespace {

class DebugOutputTest : public GlTest {
protected:
    // This test makes one error on purpose: check it was counted, then let the suite go on.
    void TearDown() override {}
};

TEST_F(DebugOutputTest, AnApiErrorIsCountedAndNamed) {
    const gl::DebugOutputCounts before = gl::debugOutputCounts();
    GLuint neverCreated = 0;
    glCreateBuffers(0, &neverCreated);  // zero buffers: no error
    glNamedBufferData(4242424, 16, nullptr, GL_STATIC_DRAW);  // not a buffer name
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
    const gl::DebugOutputCounts after = gl::debugOutputCounts();
    EXPECT_EQ(after.errors, before.errors + 1);
    EXPECT_FALSE(after.lastError.empty());
    EXPECT_EQ(after.compilerMessages, before.compilerMessages);
}

}  // namespace
}  // namespace grass::test
