// Shader loading: #include resolution, defines, and compile errors that name file and line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <cstdlib>
#include <fstream>

#include "gl_context_fixture.h"
#include "gl/program.h"
#include "support/test_paths.h"

namespace grass::test {
namespace {

void writeText(const std::filesystem::path& file, const std::string& text) {
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

TEST(ShaderSource, IncludesAreExpandedWithLineDirectives) {
    const auto dir = scratchDir("shader_include");
    writeText(dir / "include/common.glsl", "float helper() { return 1.0; }\n");
    writeText(dir / "main.vert", "#version 450 core\n#include \"common.glsl\"\nvoid main() {}\n");
    auto expanded = gl::expandShaderSource(dir, "main.vert", {"FOO 1"});
    ASSERT_TRUE(expanded.ok()) << expanded.error().str();
    EXPECT_NE(expanded->text.find("float helper()"), std::string::npos);
    EXPECT_NE(expanded->text.find("#define FOO 1"), std::string::npos);
    EXPECT_EQ(expanded->text.find("#include"), std::string::npos);
    ASSERT_EQ(expanded->files.size(), 2u);
    EXPECT_EQ(expanded->files[1], dir / "include/common.glsl");
}

TEST(ShaderSource, MissingIncludeNamesFileAndLine) {
    const auto dir = scratchDir("shader_missing_include");
    writeText(dir / "main.vert", "#version 450 core\n\n#include \"nope.glsl\"\n");
    auto expanded = gl::expandShaderSource(dir, "main.vert", {});
    ASSERT_FALSE(expanded.ok());
    EXPECT_NE(expanded.error().str().find("main.vert:3"), std::string::npos)
        << expanded.error().str();
    EXPECT_NE(expanded.error().str().find("nope.glsl"), std::string::npos);
}

TEST(ShaderSource, IncludeCycleIsAnError) {
    const auto dir = scratchDir("shader_cycle");
    writeText(dir / "include/a.glsl", "#include \"b.glsl\"\n");
    writeText(dir / "include/b.glsl", "#include \"a.glsl\"\n");
    writeText(dir / "main.vert", "#version 450 core\n#include \"a.glsl\"\n");
    auto expanded = gl::expandShaderSource(dir, "main.vert", {});
    ASSERT_FALSE(expanded.ok());
    EXPECT_NE(expanded.error().message.find("cycle"), std::string::npos);
}

TEST(ShaderLog, MesaAndNvidiaLocationsMapToFiles) {
    const std::vector<std::filesystem::path> files{"shaders/x.vert", "shaders/include/y.glsl"};
    EXPECT_EQ(gl::mapShaderLog("1:7(3): error: bad\n", files),
              "shaders/include/y.glsl:7:3: error: bad\n");
    EXPECT_EQ(gl::mapShaderLog("0(12) : error C0000: bad\n", files),
              "shaders/x.vert:12 : error C0000: bad\n");
}

using ProgramTest = GlTest;

TEST_F(ProgramTest, CompileErrorInAnIncludeNamesThatFileAndLine) {
    const auto dir = scratchDir("shader_compile_error");
    writeText(dir / "include/broken.glsl",
              "// line 1\nfloat broken() { return undefined_name; }\n");
    writeText(dir / "broken.frag",
              "#version 450 core\n#include \"broken.glsl\"\nout vec4 c;\nvoid main() { c = "
              "vec4(broken()); }\n");
    ::setenv("GRASS_SHADER_DIR", dir.c_str(), 1);
    auto program = gl::Program::load({{GL_FRAGMENT_SHADER, "broken.frag"}}, "broken");
    ::unsetenv("GRASS_SHADER_DIR");
    ASSERT_FALSE(program.ok());
    const std::string message = program.error().str();
    EXPECT_NE(message.find((dir / "include/broken.glsl").string() + ":2"), std::string::npos)
        << message;
}

TEST_F(ProgramTest, EveryShippedProgramCompiles) {
    EXPECT_TRUE(gl::Program::load(
                    {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}}, "mesh")
                    .ok());
    EXPECT_TRUE(
        gl::Program::load(
            {{GL_VERTEX_SHADER, "blade_strip.vert"}, {GL_FRAGMENT_SHADER, "blade.frag"}}, "strips")
            .ok());
    auto tess = gl::Program::load({{GL_VERTEX_SHADER, "blade_tess.vert"},
                                   {GL_TESS_CONTROL_SHADER, "blade.tesc"},
                                   {GL_TESS_EVALUATION_SHADER, "blade.tese"},
                                   {GL_FRAGMENT_SHADER, "blade.frag"}},
                                  "tess");
    EXPECT_TRUE(tess.ok()) << (tess.ok() ? "" : tess.error().str());
}

// The hybrid's fade-out is a variant of its own: a blade program without it has no fade uniform
// (and, lit per vertex, no position varying for the fragments, which software GL would set up
// and interpolate for every triangle); the hybrid's pictures (GoldenTest) show the fade works.
TEST_F(ProgramTest, OnlyTheFadingBladeProgramCarriesTheFade) {
    for (const bool tessellate : {false, true}) {
        const auto load = [tessellate](std::vector<std::string> defines) {
            if (tessellate)
                return gl::Program::load({{GL_VERTEX_SHADER, "blade_tess.vert"},
                                          {GL_TESS_CONTROL_SHADER, "blade.tesc"},
                                          {GL_TESS_EVALUATION_SHADER, "blade.tese"},
                                          {GL_FRAGMENT_SHADER, "blade.frag"}},
                                         "tess", defines);
            return gl::Program::load(
                {{GL_VERTEX_SHADER, "blade_strip.vert"}, {GL_FRAGMENT_SHADER, "blade.frag"}},
                "strips", defines);
        };
        auto plain = load({"GRASS_LIGHT_PER_VERTEX"});
        auto fading = load({"GRASS_LIGHT_PER_VERTEX", "GRASS_BLADE_FADE_OUT"});
        ASSERT_TRUE(plain.ok()) << plain.error().str();
        ASSERT_TRUE(fading.ok()) << fading.error().str();
        EXPECT_EQ(glGetUniformLocation(plain->id(), "uFadeOut"), -1) << tessellate;
        EXPECT_GE(glGetUniformLocation(fading->id(), "uFadeOut"), 0) << tessellate;
    }
}

}  // namespace
}  // namespace grass::test
