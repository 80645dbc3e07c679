#include <set>
#include <sstream>
#include <stdexcept>

#include "effects/gl/ShaderSource.h"

namespace effects::gl {

namespace {
void expand(std::string_view path, std::set<std::string, std::less<>>& seen, std::string& out, int depth) {
    if (depth > 16) throw std::runtime_error("shaders/" + std::string(path) + ": includes nest too deeply");
    if (!seen.insert(std::string(path)).second) return;
    std::istringstream in{std::string(shader_source(path))};
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.rfind("#include", 0) == 0) {
            auto a = line.find('"'), b = line.rfind('"');
            if (a == std::string::npos || b <= a)
                throw std::runtime_error("shaders/" + std::string(path) + ":" + std::to_string(number) +
                                         ": malformed #include");
            expand(std::string_view(line).substr(a + 1, b - a - 1), seen, out, depth + 1);
            out += "#line " + std::to_string(number + 1) + "\n";
            continue;
        }
        out += line;
        out += '\n';
    }
}
}  // namespace

std::string shader_text(std::string_view path) {
    std::set<std::string, std::less<>> seen;
    std::string out;
    expand(path, seen, out, 0);
    return out;
}

std::string shader_text(std::string_view path, const std::vector<std::string>& defines) {
    std::string text = shader_text(path);
    if (defines.empty()) return text;
    const size_t version = text.rfind("#version", 0) == 0 ? text.find('\n') : std::string::npos;
    if (version == std::string::npos)
        throw std::runtime_error("shaders/" + std::string(path) + ": defines need a #version first line");
    std::string lines;
    for (const std::string& d : defines) lines += "#define " + d + "\n";
    text.insert(version + 1, lines + "#line 2\n");
    return text;
}

}  // namespace effects::gl
