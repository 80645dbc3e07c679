#pragma once
// An off-screen target the renderer's output goes to, read back as an image, and
// the renderer's HDR targets written as a layered EXR for debugging.
#include <filesystem>

#include "effects/Renderer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Texture.h"
#include "game/capture/Image.h"

namespace game {

class FrameCapture {
public:
    FrameCapture(int width, int height);

    effects::RenderOutput output() const { return {fbo_.id(), width_, height_}; }
    ImageRGBA8 read() const;
    // Colour (HDR, linear), depth (linear metres from the eye) and world normals; throws
    // CaptureError if the targets do not draw normals (SceneTargets::write_normals).
    static void write_scene_exr(const std::filesystem::path& path, const effects::SceneTargets& targets, float near_m,
                          float far_m);

private:
    int width_, height_;
    effects::gl::Texture colour_;
    effects::gl::Framebuffer fbo_;
};

}  // namespace game
