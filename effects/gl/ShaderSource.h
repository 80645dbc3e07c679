#pragma once
#include <string>
#include <string_view>

namespace effects::gl {

// GLSL text of shaders/<path>, e.g. "scene/mesh.vert.glsl", embedded at build time.
// Throws std::runtime_error naming the path if there is no such shader.
std::string_view shader_source(std::string_view path);

// The same text with every `#include "other/file.glsl"` line replaced by that file's
// text (recursively; a file is included once), and #line directives so compiler
// messages point at the right line.
std::string shader_text(std::string_view path);

}  // namespace effects::gl
