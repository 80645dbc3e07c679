#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace effects::gl {

// GLSL text of shaders/<path>, e.g. "scene/mesh.vert.glsl", embedded at build time.
// Throws std::runtime_error naming the path if there is no such shader.
std::string_view shader_source(std::string_view path);

// The same text with every `#include "other/file.glsl"` line replaced by that file's
// text (recursively; a file is included once), and #line directives so compiler
// messages point at the right line.
std::string shader_text(std::string_view path);

// shader_text with `defines` ("NAME" or "NAME VALUE") as #define lines right after the
// #version line, followed by "#line 2": the text Program::from_files compiles. Throws
// std::runtime_error naming the path if there are defines and no #version first line.
std::string shader_text(std::string_view path, const std::vector<std::string>& defines);

// The path under shaders/ of every embedded shader, sorted.
std::vector<std::string_view> shader_paths();

}  // namespace effects::gl
