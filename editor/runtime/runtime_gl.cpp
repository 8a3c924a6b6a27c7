#include "runtime/runtime_gl.h"

#include <algorithm>
#include <sstream>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "runtime/embedded_shaders.h"

namespace grass::runtime {

namespace {

// `#include "x.glsl"` lines replaced by the embedded file, recursively (each file once: the
// includes carry their own guards, and a cycle would otherwise never end).
bool expandIncludes(std::string_view name, std::string& out, std::vector<std::string>& open,
                    std::string& error) {
    const std::string_view text = embeddedShader(name);
    if (text.empty()) {
        error = "shader \"" + std::string(name) + "\" is not embedded in the runtime";
        return false;
    }
    if (std::find(open.begin(), open.end(), name) != open.end()) {
        error = "shader \"" + std::string(name) + "\" includes itself";
        return false;
    }
    open.emplace_back(name);
    std::istringstream lines{std::string(text)};
    std::string line;
    while (std::getline(lines, line)) {
        const auto hash = line.find_first_not_of(" \t");
        if (hash != std::string::npos && line.compare(hash, 8, "#include") == 0) {
            const auto first = line.find('"');
            const auto last = line.rfind('"');
            if (first == std::string::npos || last <= first) {
                error = std::string(name) + ": malformed #include line \"" + line + "\"";
                return false;
            }
            if (!expandIncludes(line.substr(first + 1, last - first - 1), out, open, error))
                return false;
            continue;
        }
        out += line;
        out += '\n';
    }
    open.pop_back();
    return true;
}

// The source of a stage: its #version line, the defines, then the rest with includes expanded.
bool stageSource(const std::string& name, const std::vector<std::string>& defines,
                 std::string& source, std::string& error) {
    std::string expanded;
    std::vector<std::string> open;
    if (!expandIncludes(name, expanded, open, error))
        return false;
    const auto versionEnd = expanded.find('\n');
    source = expanded.substr(0, versionEnd + 1);
    for (const std::string& define : defines)
        source += "#define " + define + "\n";
    source += expanded.substr(versionEnd + 1);
    return true;
}

std::string infoLog(GLuint object, bool program) {
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    program ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
    return log.c_str();
}

}  // namespace

GlProgram::GlProgram(const std::vector<std::pair<GLenum, std::string>>& stages,
                     const std::vector<std::string>& defines, std::string& error) {
    std::vector<GLuint> shaders;
    const GLuint program = glCreateProgram();
    bool ok = true;
    for (const auto& [stage, name] : stages) {
        std::string source;
        if (!stageSource(name, defines, source, error)) {
            ok = false;
            break;
        }
        const GLuint shader = glCreateShader(stage);
        const char* text = source.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint compiled = 0;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
        shaders.push_back(shader);
        if (!compiled) {
            error = name + ": " + infoLog(shader, false);
            ok = false;
            break;
        }
        glAttachShader(program, shader);
    }
    if (ok) {
        glLinkProgram(program);
        GLint linked = 0;
        glGetProgramiv(program, GL_LINK_STATUS, &linked);
        if (!linked) {
            error = "linking " + stages.front().second + ": " + infoLog(program, true);
            ok = false;
        }
    }
    for (GLuint shader : shaders)
        glDeleteShader(shader);
    if (ok)
        mId = program;
    else
        glDeleteProgram(program);
}

GlProgram::GlProgram(GlProgram&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
GlProgram& GlProgram::operator=(GlProgram&& other) noexcept {
    std::swap(mId, other.mId);
    return *this;
}
GlProgram::~GlProgram() {
    if (mId != 0)
        glDeleteProgram(mId);
}

void GlProgram::set(const char* name, int value) const {
    glProgramUniform1i(mId, glGetUniformLocation(mId, name), value);
}
void GlProgram::set(const char* name, unsigned value) const {
    glProgramUniform1ui(mId, glGetUniformLocation(mId, name), value);
}
void GlProgram::set(const char* name, float value) const {
    glProgramUniform1f(mId, glGetUniformLocation(mId, name), value);
}
void GlProgram::set(const char* name, glm::vec2 value) const {
    glProgramUniform2fv(mId, glGetUniformLocation(mId, name), 1, glm::value_ptr(value));
}
void GlProgram::set(const char* name, glm::vec3 value) const {
    glProgramUniform3fv(mId, glGetUniformLocation(mId, name), 1, glm::value_ptr(value));
}
void GlProgram::set(const char* name, const glm::mat4& value) const {
    glProgramUniformMatrix4fv(mId, glGetUniformLocation(mId, name), 1, GL_FALSE,
                              glm::value_ptr(value));
}

GlBuffer::GlBuffer(std::span<const std::byte> bytes) {
    mSize = std::max<std::size_t>(bytes.size(), 4);
    glCreateBuffers(1, &mId);
    std::vector<std::byte> padded;
    const void* data = bytes.data();
    if (bytes.size() < mSize) {
        padded.assign(mSize, std::byte{0});
        std::copy(bytes.begin(), bytes.end(), padded.begin());
        data = padded.data();
    }
    glNamedBufferStorage(mId, static_cast<GLsizeiptr>(mSize), data, GL_DYNAMIC_STORAGE_BIT);
}

GlBuffer::GlBuffer(GlBuffer&& other) noexcept
    : mId(std::exchange(other.mId, 0)), mSize(std::exchange(other.mSize, 0)) {}
GlBuffer& GlBuffer::operator=(GlBuffer&& other) noexcept {
    std::swap(mId, other.mId);
    std::swap(mSize, other.mSize);
    return *this;
}
GlBuffer::~GlBuffer() {
    if (mId != 0)
        glDeleteBuffers(1, &mId);
}

GlTexelView::GlTexelView(const GlBuffer& buffer, GLenum internalFormat) {
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &mId);
    glTextureBuffer(mId, internalFormat, buffer.id());
}
GlTexelView::GlTexelView(GlTexelView&& other) noexcept : mId(std::exchange(other.mId, 0)) {}
GlTexelView& GlTexelView::operator=(GlTexelView&& other) noexcept {
    std::swap(mId, other.mId);
    return *this;
}
GlTexelView::~GlTexelView() {
    if (mId != 0)
        glDeleteTextures(1, &mId);
}

}  // namespace grass::runtime
