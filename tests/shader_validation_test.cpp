// Every embedded shader through the Khronos reference compiler, glslangValidator
// (Debian's glslang-tools, installed by tools/setup.sh), as the GLSL 4.50 core its
// #version line says: after the project's own #include resolution and with each set of
// #defines a preset compiles it with, so that drivers stricter than Mesa's keep
// accepting them. Needs no GL context. SPINDRIFT_GLSLANG names another validator.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "effects/Quality.h"
#include "effects/gl/ShaderSource.h"

namespace {

namespace fs = std::filesystem;

std::string validator() {
    const char* v = std::getenv("SPINDRIFT_GLSLANG");
    return v && *v ? v : "glslangValidator";
}

struct Validation {
    int status = -1;  // the validator's exit status; 0: accepted
    std::string output;
};

// Runs the validator with `arguments`, its output and errors captured.
Validation run_validator(const std::string& arguments) {
    const std::string command = validator() + " " + arguments + " 2>&1";
    Validation v;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) {
        v.output = "cannot run: " + command;
        return v;
    }
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) v.output.append(buf, n);
    const int status = ::pclose(pipe);
    v.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return v;
}

// Validates `files` as `stage` (vert, frag, comp, ...): GLSL for OpenGL, the version and
// profile each #version line names. One run for many files: the validator takes a
// third of a second to start.
Validation validate(const std::vector<fs::path>& files, std::string_view stage) {
    std::string arguments = "-S " + std::string(stage);
    for (const fs::path& f : files) arguments += " '" + f.string() + "'";
    return run_validator(arguments);
}

// "fluid/refract.frag.glsl" -> "frag".
std::string stage_of(std::string_view path) {
    std::string_view stem = path.substr(0, path.size() - std::string_view(".glsl").size());
    return std::string(stem.substr(stem.rfind('.') + 1));
}

// A fresh folder under the system temp dir, removed afterwards.
struct TempDir {
    fs::path path = fs::temp_directory_path() / ("spindrift_glslang_" + std::to_string(::getpid()));
    TempDir() {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    fs::path write(const std::string& name, const std::string& text) const {
        const fs::path file = path / name;
        fs::create_directories(file.parent_path());
        std::ofstream(file) << text;
        return file;
    }
};

// The #define sets programs compile shaders with: each preset's (shader_defines), with
// and without line lights, and those plus GROUND and a road count, as LitScene builds
// the ground; and the high preset's with the scene's normals written (SCENE_NORMALS).
std::vector<std::vector<std::string>> preset_define_sets() {
    std::vector<std::vector<std::string>> sets;
    for (effects::Quality q : {effects::Quality::Low, effects::Quality::Medium, effects::Quality::High})
        for (bool line_lights : {false, true}) {
            std::vector<std::string> defines = effects::shader_defines(effects::quality_settings(q), line_lights);
            sets.push_back(defines);
            defines.push_back("GROUND");
            defines.push_back("ROAD_COUNT 2");
            sets.push_back(defines);
        }
    std::vector<std::string> normals = effects::shader_defines(effects::quality_settings(effects::Quality::High), false);
    normals.insert(normals.end(), {"GROUND", "ROAD_COUNT 2", "SCENE_NORMALS"});
    sets.push_back(normals);
    return sets;
}

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Whether `text` uses any of the defines' names (as a whole word): only then can they
// change what it compiles to.
bool uses_any(const std::string& text, const std::vector<std::string>& defines) {
    for (const std::string& d : defines) {
        const std::string name = d.substr(0, d.find(' '));
        for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
            const size_t end = at + name.size();
            if ((at == 0 || !is_name_char(text[at - 1])) && (end == text.size() || !is_name_char(text[end])))
                return true;
        }
    }
    return false;
}

// The validator's output for several files cut down to the files it refused: each
// file's name on a line of its own, followed by its messages.
std::string refusals(const std::string& output, const std::vector<fs::path>& files) {
    std::string kept, block;
    bool refused = false;
    auto flush = [&] {
        if (refused) kept += block;
        block.clear();
        refused = false;
    };
    for (size_t start = 0; start < output.size();) {
        const size_t end = std::min(output.find('\n', start), output.size());
        const std::string line = output.substr(start, end - start);
        if (std::find(files.begin(), files.end(), fs::path(line)) != files.end()) flush();
        refused |= line.starts_with("ERROR");
        block += line + "\n";
        start = end + 1;
    }
    flush();
    return kept.empty() ? output : kept;
}

std::string describe(const std::vector<std::string>& defines) {
    if (defines.empty()) return "no defines";
    std::string text;
    for (const std::string& d : defines) text += (text.empty() ? "#define " : ", ") + d;
    return text;
}

TEST(ShaderValidation, TheReferenceCompilerIsInstalled) {
    const Validation v = run_validator("--version");
    EXPECT_NE(v.output.find("glslang"), std::string::npos)
        << validator() << " did not run (install Debian's glslang-tools: tools/setup.sh):\n" << v.output;
}

// The harness itself: a shader that is not GLSL 4.50 core is refused, and the message
// says where.
TEST(ShaderValidation, ABrokenShaderIsRefused) {
    TempDir dir;
    const fs::path good = dir.write("good.frag.glsl", "#version 450 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n");
    EXPECT_EQ(validate({good}, "frag").status, 0) << validate({good}, "frag").output;
    // texture2D is compatibility-profile GLSL: llvmpipe lets some such things pass.
    const fs::path bad = dir.write("bad.frag.glsl",
                                   "#version 450 core\nuniform sampler2D t;\nout vec4 c;\n"
                                   "void main() { c = texture2D(t, vec2(0.5)); }\n");
    const Validation v = validate({bad}, "frag");
    EXPECT_NE(v.status, 0);
    EXPECT_NE(v.output.find("bad.frag.glsl"), std::string::npos) << v.output;
    EXPECT_NE(v.output.find("ERROR: 0:4: 'texture2D'"), std::string::npos) << v.output;
}

TEST(ShaderValidation, EveryShaderCompilesAsGlsl450CoreWithEachPresetsDefines) {
    TempDir dir;
    const std::vector<std::vector<std::string>> presets = preset_define_sets();
    std::string legend = "variant0: no defines\n";
    for (size_t p = 0; p < presets.size(); ++p)
        legend += "variant" + std::to_string(p + 1) + ": " + describe(presets[p]) + "\n";
    // Each stage with no defines (variant0), and with each preset's set that it uses
    // (variant1..), written out resolved and grouped by shader stage.
    std::map<std::string, std::vector<fs::path>> by_stage;
    int stages = 0;
    for (std::string_view path : effects::gl::shader_paths()) {
        const std::string_view source = effects::gl::shader_source(path);
        if (!source.starts_with("#version")) continue;  // an include: checked where it is included
        ++stages;
        EXPECT_TRUE(source.starts_with("#version 450 core\n")) << "shaders/" << path << " is not GLSL 4.50 core";
        const std::string resolved = effects::gl::shader_text(path);
        std::vector<fs::path>& files = by_stage[stage_of(path)];
        files.push_back(dir.write("variant0/" + std::string(path), resolved));
        for (size_t p = 0; p < presets.size(); ++p)
            if (uses_any(resolved, presets[p]))
                files.push_back(dir.write("variant" + std::to_string(p + 1) + "/" + std::string(path),
                                          effects::gl::shader_text(path, presets[p])));
    }
    size_t files = 0;
    for (const auto& [stage, paths] : by_stage) {
        const Validation result = validate(paths, stage);
        EXPECT_EQ(result.status, 0) << "the ." << stage << " shaders:\n" << refusals(result.output, paths) << legend;
        files += paths.size();
    }
    // The embedded table is there (45 stages when this was written), and the variants too.
    EXPECT_GE(stages, 40);
    EXPECT_GT(files, size_t(stages));
    std::printf("%d shader stages, %zu files validated\n", stages, files);
}

}  // namespace
