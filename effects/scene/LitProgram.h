#pragma once
// A program that includes shaders/common/lighting.glsl, built in the variants its
// lighting takes: the preset's (shader_defines) and with or without the energy
// beams' line lights, and with or without the scene's normals output (SCENE_NORMALS,
// when SceneTargets draws them). The line lights are compiled in or out rather than
// looped over: a software rasteriser runs a loop's body once even when it has nothing
// to do, which on most frames (no shot in flight) would cost every lit pixel the whole
// line-light sum.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "effects/Quality.h"
#include "effects/gl/Program.h"

namespace effects {

class LitProgram {
public:
    LitProgram(std::string label, std::vector<std::string_view> files, std::vector<std::string> defines = {});

    // The variant for this preset, with the line-light sum if `line_lights` and writing
    // the normals draw buffer if `normals`; built on first use, and all variants dropped
    // when the preset's shader #defines change (not for what no shader compiles in, such
    // as the anti-aliasing toggle).
    const gl::Program& get(const QualitySettings& quality, bool line_lights, bool normals = false);

private:
    std::string label_;
    std::vector<std::string_view> files_;
    std::vector<std::string> defines_;
    std::optional<std::vector<std::string>> built_for_;  // the preset's defines
    std::array<std::optional<gl::Program>, 4> variants_;  // by line lights + 2 * normals
};

}  // namespace effects
