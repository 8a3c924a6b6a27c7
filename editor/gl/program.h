// Program: a linked GL program built from .glsl files under shaders/ (STYLE.md §1: GLSL lives
// in files, never in C++ strings). `#include "file.glsl"` is resolved against shaders/include
// and the including file's folder; compile errors are reported as "shaders/x.glsl:LINE: msg"
// by mapping the driver's source-string numbers back to files through #line directives.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl_handle.h"
#include "util/assert.h"
#include "util/result.h"

namespace grass::gl {

struct ShaderStage {
    GLenum stage;      // GL_VERTEX_SHADER, GL_TESS_CONTROL_SHADER, ...
    std::string file;  // relative to the shader folder, e.g. "blade_strip.vert"
};

// Preprocessed source: the text handed to GL and the file behind each source-string number.
struct ExpandedSource {
    std::string text;
    std::vector<std::filesystem::path> files;
};

// The shader folder: $GRASS_SHADER_DIR, else <exe>/../share/grass/shaders, else the source tree.
std::filesystem::path shaderDirectory();

// Resolves #include recursively (an include cycle is an error) and inserts `defines` after
// #version. Pure text work, no GL: unit-tested.
Result<ExpandedSource> expandShaderSource(const std::filesystem::path& shaderDir,
                                          const std::string& file,
                                          const std::vector<std::string>& defines);

// Rewrites a driver log ("0:12(5): error: ..." Mesa, "0(12) : error ..." NVIDIA) so every
// location names the file and line.
std::string mapShaderLog(const std::string& log, const std::vector<std::filesystem::path>& files);

class Program {
public:
    static Result<Program> load(std::initializer_list<ShaderStage> stages, std::string_view label,
                                const std::vector<std::string>& defines = {});
    GLuint id() const { return mHandle.id(); }
    void use() const { glUseProgram(mHandle.id()); }

    void set(const char* name, float value) const;
    void set(const char* name, int value) const;
    void set(const char* name, unsigned value) const;
    void set(const char* name, glm::vec2 value) const;
    void set(const char* name, glm::vec3 value) const;
    void set(const char* name, glm::vec4 value) const;
    void set(const char* name, const glm::mat4& value) const;

private:
    GLint location(const char* name) const { return glGetUniformLocation(mHandle.id(), name); }
    ProgramHandle mHandle;
};

// The program in `slot`, made by `load()` (a Result<Program>) the first time it is asked for:
// variants a frame may never need cost nothing until one does. The shaders ship with the
// program, so a load failure here is a bug, not an input error.
template <class Load>
const Program& loadOnFirstUse(Program& slot, Load&& load) {
    if (slot.id() == 0) {
        auto loaded = load();
        GRASS_ASSERT(loaded.ok());
        slot = std::move(*loaded);
    }
    return slot;
}

}  // namespace grass::gl
