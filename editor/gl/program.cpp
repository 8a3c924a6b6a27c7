#include "gl/program.h"

#include <unistd.h>

#include <regex>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "util/atomic_file.h"

namespace grass::gl {

namespace fs = std::filesystem;

fs::path shaderDirectory() {
    if (const char* env = std::getenv("GRASS_SHADER_DIR"))
        return env;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "share/grass/shaders";
        if (fs::exists(installed / "include", ec))
            return installed;
    }
    return fs::path(GRASS_SOURCE_DIR) / "shaders";
}

namespace {

struct Expander {
    const fs::path& shaderDir;
    ExpandedSource out;
    std::vector<fs::path> stack;

    Result<void> expand(const fs::path& file, bool isRoot,
                        const std::vector<std::string>& defines) {
        for (const auto& open : stack)
            if (open == file)
                return makeError(file.string(), "#include cycle");
        auto text = readFile(file);
        if (!text)
            return text.error();
        stack.push_back(file);
        const int index = static_cast<int>(out.files.size());
        out.files.push_back(file);
        std::istringstream lines(*text);
        std::string line;
        int lineNo = 0;
        static const std::regex includeRe(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
        if (!isRoot)
            out.text += "#line 1 " + std::to_string(index) + "\n";
        while (std::getline(lines, line)) {
            ++lineNo;
            std::smatch match;
            if (std::regex_match(line, match, includeRe)) {
                const fs::path local = file.parent_path() / match[1].str();
                const fs::path shared = shaderDir / "include" / match[1].str();
                std::error_code ec;
                const fs::path target = fs::exists(local, ec) ? local : shared;
                if (!fs::exists(target, ec))
                    return makeError(file.string() + ":" + std::to_string(lineNo),
                                     "cannot find include \"" + match[1].str() + "\"");
                if (auto r = expand(target, false, {}); !r)
                    return r;
                out.text +=
                    "#line " + std::to_string(lineNo + 1) + " " + std::to_string(index) + "\n";
                continue;
            }
            out.text += line + "\n";
            if (isRoot && line.rfind("#version", 0) == 0) {
                for (const auto& define : defines)
                    out.text += "#define " + define + "\n";
                out.text +=
                    "#line " + std::to_string(lineNo + 1) + " " + std::to_string(index) + "\n";
            }
        }
        stack.pop_back();
        return {};
    }
};

}  // namespace

Result<ExpandedSource> expandShaderSource(const fs::path& shaderDir, const std::string& file,
                                          const std::vector<std::string>& defines) {
    Expander expander{shaderDir, {}, {}};
    if (auto r = expander.expand(shaderDir / file, true, defines); !r)
        return r.error();
    return std::move(expander.out);
}

std::string mapShaderLog(const std::string& log, const std::vector<fs::path>& files) {
    // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ...".
    static const std::regex mesaRe(R"((\d+):(\d+)\((\d+)\))");
    static const std::regex nvidiaRe(R"(^(\d+)\((\d+)\))");
    std::istringstream lines(log);
    std::string line, result;
    while (std::getline(lines, line)) {
        std::smatch match;
        auto name = [&](const std::string& index) {
            const auto i = static_cast<std::size_t>(std::stoul(index));
            return i < files.size() ? files[i].string() : "source " + index;
        };
        if (std::regex_search(line, match, mesaRe) && match.position(0) == 0)
            line =
                name(match[1]) + ":" + match[2].str() + ":" + match[3].str() + match.suffix().str();
        else if (std::regex_search(line, match, nvidiaRe))
            line = name(match[1]) + ":" + match[2].str() + match.suffix().str();
        if (!line.empty())
            result += line + "\n";
    }
    return result;
}

static std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    if (isProgram)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n'))
        log.pop_back();
    return log;
}

Result<Program> Program::load(std::initializer_list<ShaderStage> stages, std::string_view label,
                              const std::vector<std::string>& defines) {
    const fs::path dir = shaderDirectory();
    Program program;
    program.mHandle = ProgramHandle(glCreateProgram());
    std::vector<ShaderHandle> shaders;
    for (const auto& stage : stages) {
        auto source = expandShaderSource(dir, stage.file, defines);
        if (!source)
            return source.error();
        ShaderHandle shader(glCreateShader(stage.stage));
        const char* text = source->text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE)
            return makeError(
                (dir / stage.file).string(),
                "compile failed:\n" + mapShaderLog(infoLog(shader.id(), false), source->files));
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.id());
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE)
        return makeError(std::string(label), "link failed:\n" + infoLog(program.id(), true));
    for (const auto& shader : shaders)
        glDetachShader(program.id(), shader.id());
    program.mHandle.setLabel(label);
    return program;
}

void Program::set(const char* name, float value) const {
    glProgramUniform1f(id(), location(name), value);
}
void Program::set(const char* name, int value) const {
    glProgramUniform1i(id(), location(name), value);
}
void Program::set(const char* name, unsigned value) const {
    glProgramUniform1ui(id(), location(name), value);
}
void Program::set(const char* name, glm::vec2 value) const {
    glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, glm::vec3 value) const {
    glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, glm::vec4 value) const {
    glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, const glm::mat4& value) const {
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace grass::gl
