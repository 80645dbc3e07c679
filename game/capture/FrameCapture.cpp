#include "game/capture/FrameCapture.h"

#include "game/capture/CaptureError.h"
#include "game/capture/ExrWriter.h"
#include "game/capture/Readback.h"

namespace game {

FrameCapture::FrameCapture(int width, int height)
    : width_(width),
      height_(height),
      colour_(effects::gl::Texture::create_2d("capture.colour", GL_RGBA8, width, height)),
      fbo_(effects::gl::Framebuffer::create("capture")) {
    fbo_.attach_colour(0, colour_);
    fbo_.set_draw_buffers({0});
    fbo_.check_complete();
}

ImageRGBA8 FrameCapture::read() const { return read_framebuffer_rgba8(fbo_.id(), width_, height_); }

void FrameCapture::write_scene_exr(const std::filesystem::path& path, const effects::SceneTargets& t, float near_m,
                             float far_m) {
    if (!t.writes_normals())
        throw CaptureError("cannot write " + path.string() +
                           ": the scene's normals are not drawn (Renderer::write_normals(true) before rendering)");
    const int w = t.width(), h = t.height();
    ImageRGBA32F colour = read_framebuffer_rgba32f(t.hdr().id(), GL_COLOR_ATTACHMENT0, w, h);
    ImageRGBA32F normal = read_framebuffer_rgba32f(t.hdr().id(), GL_COLOR_ATTACHMENT1, w, h);
    std::vector<float> depth = read_depth(t.hdr().id(), w, h);
    // Window depth to eye distance along the view axis, for a perspective projection.
    for (float& d : depth) {
        float ndc = d * 2.0f - 1.0f;
        d = 2.0f * near_m * far_m / (far_m + near_m - ndc * (far_m - near_m));
    }
    std::vector<float> n3;
    n3.reserve(size_t(w) * size_t(h) * 3);
    for (size_t i = 0; i < size_t(w) * size_t(h); ++i)
        n3.insert(n3.end(), {normal.pixels[i * 4], normal.pixels[i * 4 + 1], normal.pixels[i * 4 + 2]});
    game::write_exr(path, w, h,
              {ExrLayer{"", 4, std::move(colour.pixels)}, ExrLayer{"depth", 1, std::move(depth)},
               ExrLayer{"normal", 3, std::move(n3)}});
}

}  // namespace game
