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
    const effects::gl::Texture colour = effects::gl::Texture::create_2d("trivial_fill", GL_RGBA8, width, height);
    effects::gl::Framebuffer target = effects::gl::Framebuffer::create("trivial_fill");
    target.attach_colour(0, colour);
    target.check_complete();
    target.bind();
    glViewport(0, 0, width, height);
    effects::gl::PipelineScope state(effects::gl::kFullScreen);
    fill.use();
    effects::gl::bind_empty_vertex_array();
    glDrawArrays(GL_TRIANGLES, 0, 3);  // the first draw compiles llvmpipe's variant
    glFinish();
    std::vector<double> ms;
    for (int i = 0; i < std::max(1, repeats); ++i) {
        const auto start = std::chrono::steady_clock::now();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
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
