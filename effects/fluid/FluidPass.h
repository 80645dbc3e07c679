#pragma once
// The fluid tank (docs/effects/fluid.md, "What is implemented"), after the water:
// ellipsoid depth maps (front and back, body and splash), smoothing of the body's maps,
// normals, and refraction through up to four surfaces over the scene's colour, then the
// glass. Every step is scissored to the tank's screen rectangle.
#include <glm/vec4.hpp>

#include "effects/fluid/FluidSmoothing.h"
#include "effects/fluid/FluidView.h"
#include "effects/gl/Buffer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/scene/Pass.h"

namespace effects {

// The tweakable look, registered with the debug panel under "fluid".
struct FluidLook {
    glm::vec3 absorption_colour{0.9f, 0.28f, 0.12f};  // C_a: red goes first, the liquid looks blue-green
    float absorption_per_m = 1.6f;                     // a
    float ior = 1.33f;
    float plane_sigma_radii = 3.0f;    // plane fitting's depth weight, in particle radii
    float plane_max_move_radii = 3.0f; // larger moves keep the old depth
    float narrow_band_radii = 2.0f;
};

// Milliseconds per step of the last frame, with glFinish between steps (profiling only).
struct FluidStageTimes {
    double depth_ms = 0.0, smoothing_ms = 0.0, normals_ms = 0.0, refraction_ms = 0.0;
    double total() const { return depth_ms + smoothing_ms + normals_ms + refraction_ms; }
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
    FluidLook& look() { return look_; }

private:
    void resize_targets(int width, int height);
    glm::ivec4 screen_rect(const FrameContext& frame, const FluidView& view, int margin) const;
    void upload(gl::Buffer& buffer, const std::vector<sim::FluidEllipsoid>& ellipsoids);
    const gl::Texture* smooth(const gl::Texture& source, gl::Texture* ping_pong, const FrameContext& frame,
                              float radius);

    gl::Program ellipsoids_, plane_fit_, bilateral_, narrow_range_, normals_, refract_;
    // [0] body, [1] splash: front and back depth maps and their framebuffer.
    gl::Texture front_[2], back_[2];
    gl::Framebuffer depth_fbo_[2];
    gl::Texture front_pp_[2], back_pp_[2];  // smoothing ping-pong for the body's maps
    gl::Framebuffer smooth_fbo_;
    // Normals: [0] body front, [1] body back, [2] splash front, [3] splash back.
    gl::Texture normal_[4];
    gl::Framebuffer normal_fbo_[2];
    gl::Texture background_;
    gl::Framebuffer shade_fbo_;
    GLuint shade_colour_id_ = 0;
    gl::Buffer particles_[2];
    const gl::Texture* smoothed_front_ = nullptr;
    const gl::Texture* smoothed_back_ = nullptr;
    int width_ = 0, height_ = 0;

    FluidView view_;  // reused each frame
    FluidSmoothing smoothing_;
    bool smoothing_set_ = false;  // by the level (first frame) or set_smoothing()
    bool profiling_ = false, probe_ = false;
    FluidStageTimes times_;
    glm::ivec4 rect_{0};
    FluidLook look_;
};

}  // namespace effects
