#include "effects/scene/LitProgram.h"

#include <utility>

namespace effects {

LitProgram::LitProgram(std::string label, std::vector<std::string_view> files, std::vector<std::string> defines)
    : label_(std::move(label)), files_(std::move(files)), defines_(std::move(defines)) {}

const gl::Program& LitProgram::get(const QualitySettings& quality, bool line_lights, bool normals) {
    std::vector<std::string> preset = shader_defines(quality, false);
    if (built_for_ != preset) {
        variants_ = {};
        built_for_ = std::move(preset);
    }
    std::optional<gl::Program>& v = variants_[(line_lights ? 1 : 0) + (normals ? 2 : 0)];
    if (!v) {
        std::vector<std::string> defines = shader_defines(quality, line_lights);
        defines.insert(defines.end(), defines_.begin(), defines_.end());
        if (normals) defines.push_back("SCENE_NORMALS");
        v = gl::Program::from_files(label_ + (line_lights ? ".line_lit" : "") + (normals ? ".normals" : ""), files_,
                                    defines);
    }
    return *v;
}

}  // namespace effects
