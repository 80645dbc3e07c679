#pragma once
#include "effects/gl/Gl.h"
#include "effects/gl/Handle.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace effects::gl {

// One shader stage's GLSL text; `name` is what errors call it (a file name).
struct StageSource {
    StageSource(GLenum stage_, std::string_view text_, std::string_view name_ = {})
        : stage(stage_), text(text_), name(name_) {}
    GLenum stage;
    std::string_view text;
    std::string name;
};

// Linked GLSL program. Compile and link errors throw std::runtime_error with the
// shader's file name, the driver's log and the source lines the log points at.
class Program {
public:
    Program() = default;

    // Embedded shaders by path under shaders/, stage from the suffix:
    // "scene/mesh.vert.glsl" -> vertex (.vert .frag .comp .geom .tesc .tese).
    // `defines` ("NAME" or "NAME VALUE") go in as #define lines after #version: one
    // source, variants compiled for what is known before the frame (a preset's choices)
    // instead of branches, of which a CPU rasteriser runs both sides.
    static Program from_files(std::string_view label, const std::vector<std::string_view>& paths,
                              const std::vector<std::string>& defines = {});
    static Program from_sources(std::string_view label, const std::vector<StageSource>& stages);

    // Throws std::invalid_argument naming the path if it has no stage suffix.
    static GLenum stage_from_path(std::string_view path);

    void use() const { glUseProgram(id()); }

    // Uniform setters (glProgramUniform*, no need to use() first). A name the program
    // does not have (or the compiler removed) is ignored; lookups are cached.
    void set(std::string_view name, int value) const;
    void set(std::string_view name, unsigned value) const;
    void set(std::string_view name, float value) const;
    void set(std::string_view name, const glm::vec2& value) const;
    void set(std::string_view name, const glm::vec3& value) const;
    void set(std::string_view name, const glm::vec4& value) const;
    void set(std::string_view name, const glm::ivec2& value) const;
    void set(std::string_view name, const glm::mat3& value) const;
    void set(std::string_view name, const glm::mat4& value) const;

    // Location of an active uniform, -1 if none (cached either way).
    GLint location(std::string_view name) const;

    GLuint id() const { return handle_.get(); }
    const std::string& label() const { return label_; }

private:
    struct NameHash {
        using is_transparent = void;
        std::size_t operator()(std::string_view s) const {
            return std::hash<std::string_view>{}(s);
        }
    };

    Handle<ProgramDeleter> handle_;
    std::string label_;
    mutable std::unordered_map<std::string, GLint, NameHash, std::equal_to<>> locations_;
};

}  // namespace effects::gl
