#pragma once
// The fluid tank (docs/effects/fluid.md, "What is implemented"), after the water:
// ellipsoid depth maps of the body (front and back), their smoothing, normals, and
// refraction through both surfaces over the scene's colour, then the glass; the splash
// as a soft layer over it (gaussian sprites into a small thickness target). Every step
// is scissored to the tank's screen rectangle.
#include <glm/vec4.hpp>

#include "effects/fluid/FluidSmoothing.h"
#include "effects/fluid/FluidView.h"
#include "effects/gl/Buffer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/scene/Pass.h"
#include "sim/core/JobPool.h"

namespace effects {

// The tweakable look, registered with the debug panel under "fluid".
struct FluidLook {
    glm::vec3 absorption_colour{0.9f, 0.28f, 0.12f};  // C_a: red goes first, the liquid looks blue-green
    float absorption_per_m = 1.6f;                     // a
    float ior = 1.33f;
    float plane_sigma_radii = 3.0f;    // plane fitting's depth weight, in particle radii
    float plane_max_move_radii = 3.0f; // larger moves keep the old depth
    float narrow_band_radii = 2.0f;
    // The splash layer's opacity, 1 - exp(-k thickness): k per metre of water along the
    // ray. A lone drop (about 2/3 of its radius thick at its centre) stays faint.
    float splash_opacity_per_m = 14.0f;
    float splash_soft_pixels = 1.2f;  // the least gaussian sigma, in thickness-target pixels
};

// Milliseconds per step of the last frame, with glFinish between steps (profiling only).
struct FluidStageTimes {
    double depth_ms = 0.0, smoothing_ms = 0.0, normals_ms = 0.0, refraction_ms = 0.0, splash_ms = 0.0;
    double total() const { return depth_ms + smoothing_ms + normals_ms + refraction_ms + splash_ms; }
};

class FluidPass final : public Pass {
public:
    FluidPass();
    std::string_view name() const override { return "fluid"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

    // Draws a given view (render() gathers the world's tank and its level settings).
    void draw(const FrameContext& frame, const FluidView& view);

    // Overrides the level's smoothing; throws std::invalid_argument for bad settings.
    void set_smoothing(const FluidSmoothing& smoothing);
    const FluidSmoothing& smoothing() const { return smoothing_; }
    void set_profiling(bool on) { profiling_ = on; }
    const FluidStageTimes& stage_times() const { return times_; }
    // Writes the body's exit ray (view space, w = 1 where the secant search converged)
    // into the scene colour instead of shading: the quality harness's probe.
    void set_exit_ray_probe(bool on) { probe_ = on; }
    // The last frame's rectangle (x0, y0, x1, y1), GL pixel rows; empty if nothing drawn.
    glm::ivec4 last_rect() const { return rect_; }
    const gl::Texture& body_front() const { return *smoothed_front_; }  // smoothed
    const gl::Texture& body_front_normal() const { return normal_[0]; }
    // The splash's thickness (metres of water along the ray), 1/kSplashScale of the
    // screen each way.
    const gl::Texture& splash_thickness() const { return thickness_; }
    static constexpr int kSplashScale = 4;
    FluidLook& look() { return look_; }

private:
    void resize_targets(int width, int height);
    glm::ivec4 screen_rect(const FrameContext& frame, const FluidView& view, int margin) const;
    void upload(gl::Buffer& buffer, const std::vector<sim::FluidEllipsoid>& ellipsoids);
    void draw_splash(const FrameContext& frame, const FluidView& view);
    const gl::Texture* smooth(const gl::Texture& source, gl::Texture* ping_pong, const FrameContext& frame,
                              float radius);

    gl::Program ellipsoids_, plane_fit_, bilateral_, narrow_range_, normals_, refract_, splash_thickness_,
        splash_layer_;
    // The body's front and back depth maps and their framebuffer.
    gl::Texture front_, back_;
    gl::Framebuffer depth_fbo_;
    gl::Texture front_pp_[2], back_pp_[2];  // smoothing ping-pong
    gl::Framebuffer smooth_fbo_;
    gl::Texture normal_[2];  // [0] front, [1] back
    gl::Framebuffer normal_fbo_;
    gl::Texture thickness_;  // the splash's, low resolution
    gl::Framebuffer thickness_fbo_;
    gl::Framebuffer shade_fbo_;      // over the scene colour
    uint64_t shade_generation_ = 0;  // SceneTargets::generation() it was built for
    gl::Buffer particles_[2];  // [0] body, [1] splash
    const gl::Texture* smoothed_front_ = nullptr;
    const gl::Texture* smoothed_back_ = nullptr;
    int width_ = 0, height_ = 0;

    FluidView view_;  // reused each frame
    // The kernels' rebuild on both cores: it runs on the frame's critical path (a few ms
    // of the tank's frame at a low render scale).
    sim::JobPool kernel_jobs_{2};
    FluidSmoothing smoothing_;
    bool smoothing_set_ = false;  // by the level (first frame) or set_smoothing()
    bool profiling_ = false, probe_ = false;
    FluidStageTimes times_;
    glm::ivec4 rect_{0};
    FluidLook look_;
};

}  // namespace effects
