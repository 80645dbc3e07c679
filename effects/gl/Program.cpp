#include "effects/gl/Program.h"

#include "effects/gl/ShaderSource.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <set>
#include <stdexcept>

namespace effects::gl {
namespace {

const char* stage_suffix(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER: return "vert";
    case GL_FRAGMENT_SHADER: return "frag";
    case GL_COMPUTE_SHADER: return "comp";
    case GL_GEOMETRY_SHADER: return "geom";
    case GL_TESS_CONTROL_SHADER: return "tesc";
    case GL_TESS_EVALUATION_SHADER: return "tese";
    default: return "unknown";
    }
}

std::string shader_log(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

std::string program_log(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log;
}

// Source line a log line refers to, or 0. Handles Mesa "0:12(3): error",
// NVIDIA "0(12) : error" and AMD "ERROR: 0:12: ...".
int referenced_line(std::string_view log_line) {
    for (std::string_view prefix : {"ERROR: ", "WARNING: "})
        if (log_line.starts_with(prefix)) log_line.remove_prefix(prefix.size());
    std::size_t i = 0;
    while (i < log_line.size() && std::isdigit(static_cast<unsigned char>(log_line[i]))) ++i;
    if (i == 0 || i + 1 >= log_line.size() || (log_line[i] != ':' && log_line[i] != '(')) return 0;
    int line = 0;
    for (++i; i < log_line.size() && std::isdigit(static_cast<unsigned char>(log_line[i])); ++i) {
        line = line * 10 + (log_line[i] - '0');
        if (line > 10'000'000) return 0;
    }
    return line;
}

// The log plus the source lines it points at, numbered like the log.
std::string annotate(std::string_view log, std::string_view source) {
    std::vector<std::string_view> lines;
    for (std::size_t start = 0; start <= source.size();) {
        const std::size_t end = std::min(source.find('\n', start), source.size());
        lines.push_back(source.substr(start, end - start));
        start = end + 1;
    }
    std::set<int> referenced;
    for (std::size_t start = 0; start < log.size();) {
        const std::size_t end = std::min(log.find('\n', start), log.size());
        if (int n = referenced_line(log.substr(start, end - start)); n > 0) referenced.insert(n);
        start = end + 1;
    }
    std::string text(log);
    if (!text.empty() && text.back() != '\n') text += '\n';
    int quoted = 0;
    for (int n : referenced) {
        if (n > static_cast<int>(lines.size()) || ++quoted > 12) break;
        text += "  " + std::to_string(n) + " | " + std::string(lines[static_cast<std::size_t>(n - 1)]) +
                "\n";
    }
    return text;
}

Handle<ShaderDeleter> compile(const StageSource& stage, std::string_view program_label) {
    Handle<ShaderDeleter> shader(glCreateShader(stage.stage));
    if (!shader)
        throw std::runtime_error("program '" + std::string(program_label) + "': cannot create a " +
                                 stage_suffix(stage.stage) + " shader for " + stage.name);
    const char* text = stage.text.data();
    const auto length = static_cast<GLint>(stage.text.size());
    glShaderSource(shader.get(), 1, &text, &length);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        throw std::runtime_error("shader compile failed: " + stage.name + " (program '" +
                                 std::string(program_label) + "')\n" +
                                 annotate(shader_log(shader.get()), stage.text));
    label_object(GL_SHADER, shader.get(), stage.name);
    return shader;
}

}  // namespace

GLenum Program::stage_from_path(std::string_view path) {
    std::string_view stem = path;
    if (stem.ends_with(".glsl")) stem.remove_suffix(5);
    const std::size_t dot = stem.rfind('.');
    const std::string_view suffix = dot == std::string_view::npos ? "" : stem.substr(dot + 1);
    for (GLenum stage : {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER,
                         GL_GEOMETRY_SHADER, GL_TESS_CONTROL_SHADER, GL_TESS_EVALUATION_SHADER})
        if (suffix == stage_suffix(stage)) return stage;
    throw std::invalid_argument("shader " + std::string(path) +
                                ": no stage suffix (.vert .frag .comp .geom .tesc .tese)");
}

Program Program::from_files(std::string_view label, const std::vector<std::string_view>& paths,
                            const std::vector<std::string>& defines) {
    std::vector<StageSource> stages;
    std::vector<std::string> texts(paths.size());  // owns what the stages view
    for (size_t i = 0; i < paths.size(); ++i) {
        try {
            texts[i] = shader_text(paths[i], defines);
        } catch (const std::exception& e) {
            throw std::runtime_error("program '" + std::string(label) + "': " + e.what());
        }
        stages.emplace_back(stage_from_path(paths[i]), texts[i], "shaders/" + std::string(paths[i]));
    }
    return from_sources(label, stages);
}

Program Program::from_sources(std::string_view label, const std::vector<StageSource>& stages) {
    if (stages.empty())
        throw std::invalid_argument("program '" + std::string(label) + "': no shader stages");
    std::vector<Handle<ShaderDeleter>> shaders;
    std::string names;
    for (const StageSource& stage : stages) {
        StageSource named = stage;
        if (named.name.empty()) named.name = std::string(label) + "." + stage_suffix(stage.stage);
        shaders.push_back(compile(named, label));
        names += (names.empty() ? "" : ", ") + named.name;
    }

    Program program;
    program.handle_.reset(glCreateProgram());
    program.label_ = label;
    for (const auto& shader : shaders) glAttachShader(program.id(), shader.get());
    glLinkProgram(program.id());
    for (const auto& shader : shaders) glDetachShader(program.id(), shader.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok)
        throw std::runtime_error("program link failed: '" + std::string(label) + "' (" + names +
                                 ")\n" + program_log(program.id()));
    label_object(GL_PROGRAM, program.id(), label);
    return program;
}

GLint Program::location(std::string_view name) const {
    if (auto it = locations_.find(name); it != locations_.end()) return it->second;
    const std::string key(name);
    const GLint loc = glGetUniformLocation(id(), key.c_str());
    locations_.emplace(key, loc);
    return loc;
}

void Program::set(std::string_view name, int value) const {
    if (GLint loc = location(name); loc >= 0) glProgramUniform1i(id(), loc, value);
}
void Program::set(std::string_view name, unsigned value) const {
    if (GLint loc = location(name); loc >= 0) glProgramUniform1ui(id(), loc, value);
}
void Program::set(std::string_view name, float value) const {
    if (GLint loc = location(name); loc >= 0) glProgramUniform1f(id(), loc, value);
}
void Program::set(std::string_view name, const glm::vec2& value) const {
    if (GLint loc = location(name); loc >= 0) glProgramUniform2fv(id(), loc, 1, glm::value_ptr(value));
}
void Program::set(std::string_view name, const glm::vec3& value) const {
    if (GLint loc = location(name); loc >= 0) glProgramUniform3fv(id(), loc, 1, glm::value_ptr(value));
}
void Program::set(std::string_view name, const glm::vec4& value) const {
    if (GLint loc = location(name); loc >= 0) glProgramUniform4fv(id(), loc, 1, glm::value_ptr(value));
}
void Program::set(std::string_view name, const glm::ivec2& value) const {
    if (GLint loc = location(name); loc >= 0) glProgramUniform2iv(id(), loc, 1, glm::value_ptr(value));
}
void Program::set(std::string_view name, const glm::mat3& value) const {
    if (GLint loc = location(name); loc >= 0)
        glProgramUniformMatrix3fv(id(), loc, 1, GL_FALSE, glm::value_ptr(value));
}
void Program::set(std::string_view name, const glm::mat4& value) const {
    if (GLint loc = location(name); loc >= 0)
        glProgramUniformMatrix4fv(id(), loc, 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace effects::gl
