#include "game/bench/TrivialFill.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/PipelineState.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"

namespace game {

std::vector<double> trivial_fill_samples(int width, int height, int repeats) {
    const effects::gl::Program fill = effects::gl::Program::from_sources(
        "trivial_fill",
        {{GL_VERTEX_SHADER,
          "#version 450 core\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);"
          " gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n",
          "trivial_fill.vert"},
         {GL_FRAGMENT_SHADER, "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(0.2, 0.4, 0.6, 1.0); }\n",
          "trivial_fill.frag"}});
    // Distinct targets: llvmpipe drops a tile's earlier commands when an opaque draw
    // covers it, so fills of one target in one flush would time only the last.
    std::vector<effects::gl::Texture> colours;
    std::vector<effects::gl::Framebuffer> targets;
    for (int i = 0; i < kFillsPerSample; ++i) {
        colours.push_back(effects::gl::Texture::create_2d("trivial_fill", GL_RGBA8, width, height));
        targets.push_back(effects::gl::Framebuffer::create("trivial_fill"));
        targets.back().attach_colour(0, colours.back());
        targets.back().check_complete();
    }
    glViewport(0, 0, width, height);
    effects::gl::PipelineScope state(effects::gl::kFullScreen);
    fill.use();
    effects::gl::bind_empty_vertex_array();
    const auto fill_all = [&] {
        for (const effects::gl::Framebuffer& target : targets) {
            target.bind();
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        glFinish();
    };
    fill_all();  // the first draw compiles llvmpipe's variant; every target is touched once
    std::vector<double> ms;
    for (int i = 0; i < std::max(1, repeats); ++i) {
        const auto start = std::chrono::steady_clock::now();
        fill_all();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() /
                     kFillsPerSample);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return ms;
}

double median_ms(std::vector<double> samples) {
    if (samples.empty()) return 0.0;
    std::nth_element(samples.begin(), samples.begin() + samples.size() / 2, samples.end());
    return samples[samples.size() / 2];
}

}  // namespace game
