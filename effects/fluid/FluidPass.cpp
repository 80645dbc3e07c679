#include "effects/fluid/FluidPass.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/glm.hpp>

#include "effects/gl/DebugGroup.h"
#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"
#include "effects/scene/Frustum.h"
#include "effects/scene/ScreenRect.h"
#include "sim/fluid/FluidTank.h"

namespace effects {

namespace {

// The std430 layout of shaders/fluid/ellipsoid.vert.glsl's particles.
struct GpuEllipsoid {
    glm::vec4 centre, axis0, axis1, axis2;
};

using Clock = std::chrono::steady_clock;

constexpr GLuint kSceneDepthUnit = 0, kMapUnit = 1;

gl::Texture depth_map(const char* label, int w, int h) {
    gl::Texture t = gl::Texture::create_2d(label, GL_R32F, w, h);
    t.set_filter(GL_NEAREST, GL_NEAREST);
    t.set_wrap(GL_CLAMP_TO_EDGE);
    return t;
}

void set_ivec4(const gl::Program& p, std::string_view name, glm::ivec4 v) {
    glProgramUniform4i(p.id(), p.location(name), v.x, v.y, v.z, v.w);
}

// Milliseconds since `t` after the GPU is done, and restarts `t` (profiling only).
double lap(Clock::time_point& t) {
    glFinish();
    auto now = Clock::now();
    double ms = std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
    return ms;
}

}  // namespace

FluidPass::FluidPass()
    : ellipsoids_(gl::Program::from_files("fluid.ellipsoids", {"fluid/ellipsoid.vert.glsl", "fluid/ellipsoid.frag.glsl"})),
      plane_fit_(gl::Program::from_files("fluid.plane_fit", {"fluid/screen.vert.glsl", "fluid/plane_fit.frag.glsl"})),
      bilateral_(gl::Program::from_files("fluid.bilateral", {"fluid/screen.vert.glsl", "fluid/bilateral.frag.glsl"})),
      narrow_range_(
          gl::Program::from_files("fluid.narrow_range", {"fluid/screen.vert.glsl", "fluid/narrow_range.frag.glsl"})),
      normals_(gl::Program::from_files("fluid.normals", {"fluid/screen.vert.glsl", "fluid/normals.frag.glsl"})),
      refract_(gl::Program::from_files("fluid.refract", {"fluid/screen.vert.glsl", "fluid/refract.frag.glsl"})),
      splash_thickness_(gl::Program::from_files(
          "fluid.splash_thickness", {"fluid/splash_thickness.vert.glsl", "fluid/splash_thickness.frag.glsl"})),
      splash_layer_(
          gl::Program::from_files("fluid.splash_layer", {"fluid/screen.vert.glsl", "fluid/splash_layer.frag.glsl"})) {}

void FluidPass::register_params(ParamRegistry& params) {
    params.add("fluid", "absorption per m", &look_.absorption_per_m, 0.0f, 10.0f);
    params.add("fluid", "index of refraction", &look_.ior, 1.0f, 2.0f);
    params.add("fluid", "plane sigma (radii)", &look_.plane_sigma_radii, 0.5f, 10.0f);
    params.add("fluid", "plane max move (radii)", &look_.plane_max_move_radii, 0.5f, 10.0f);
    params.add("fluid", "smoothing iterations", &smoothing_.iterations, 1, 64);
    params.add("fluid", "splash opacity per m", &look_.splash_opacity_per_m, 0.0f, 100.0f);
    params.add("fluid", "splash softness (px)", &look_.splash_soft_pixels, 0.5f, 4.0f);
}

void FluidPass::set_smoothing(const FluidSmoothing& smoothing) {
    smoothing.validate();
    smoothing_ = smoothing;
    smoothing_set_ = true;
}

void FluidPass::render(const FrameContext& frame) {
    const sim::FluidTank* tank = frame.world.find<sim::FluidTank>();
    if (!tank) return;
    // Out of view, the ellipsoids are not worth building: skip on the bounds of
    // everything they can reach (each stays within 11 particle radii of its particle:
    // centre smoothing moves it at most the 8-radius neighbourhood, stretch keeps its
    // axes under 2.6 radii) and of the glass, up to twice its height.
    const float r = tank->fluid().params().particle_radius_m;
    glm::vec3 lo(0.0f), hi(tank->inner_size() * glm::vec3(1.0f, 2.0f, 1.0f));
    for (const glm::vec3& p : tank->fluid().positions()) {
        lo = glm::min(lo, p - 11.0f * r);
        hi = glm::max(hi, p + 11.0f * r);
    }
    glm::vec3 wlo(1e30f), whi(-1e30f);
    const glm::mat4 to_world = tank->tank_to_world();
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 w(to_world * glm::vec4((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z, 1.0f));
        wlo = glm::min(wlo, w);
        whi = glm::max(whi, w);
    }
    if (Frustum(frame.camera.view_proj).outside(wlo, whi)) {
        rect_ = glm::ivec4(0);
        times_ = {};
        return;
    }
    gather_fluid_view(frame.world, view_, &kernel_jobs_);
    if (!smoothing_set_) {  // the level's settings, once: the debug panel may change them after
        const sim::FluidTankDesc& d = frame.world.level().fluid;
        FluidSmoothing s;
        s.method = smoothing_method(d.smoothing);
        s.kernel_size = d.kernel_size;
        s.iterations = d.smoothing_iterations;
        s.validate();
        smoothing_ = s;
        smoothing_set_ = true;
    }
    draw(frame, view_);
}

void FluidPass::resize_targets(int w, int h) {
    if (w == width_ && h == height_) return;
    width_ = w;
    height_ = h;
    front_ = depth_map("fluid.body_front", w, h);
    back_ = depth_map("fluid.body_back", w, h);
    depth_fbo_ = gl::Framebuffer::create("fluid.body_depths");
    depth_fbo_.attach_colour(0, front_);
    depth_fbo_.attach_colour(1, back_);
    depth_fbo_.check_complete();
    front_pp_[0] = depth_map("fluid.smooth_front_a", w, h);
    front_pp_[1] = depth_map("fluid.smooth_front_b", w, h);
    back_pp_[0] = depth_map("fluid.smooth_back_a", w, h);
    back_pp_[1] = depth_map("fluid.smooth_back_b", w, h);
    smooth_fbo_ = gl::Framebuffer::create("fluid.smooth");
    const char* normal_names[2] = {"fluid.body_front_normal", "fluid.body_back_normal"};
    for (int k = 0; k < 2; ++k) {
        normal_[k] = gl::Texture::create_2d(normal_names[k], GL_RGBA16F, w, h);
        normal_[k].set_filter(GL_NEAREST, GL_NEAREST);
    }
    normal_fbo_ = gl::Framebuffer::create("fluid.body_normals");
    normal_fbo_.attach_colour(0, normal_[0]);
    normal_fbo_.attach_colour(1, normal_[1]);
    normal_fbo_.check_complete();
    // Filtered: the layer reads it bilinearly at full resolution.
    thickness_ = gl::Texture::create_2d("fluid.splash_thickness", GL_R16F, (w + kSplashScale - 1) / kSplashScale,
                                        (h + kSplashScale - 1) / kSplashScale);
    thickness_.set_filter(GL_LINEAR, GL_LINEAR);
    thickness_.set_wrap(GL_CLAMP_TO_EDGE);
    thickness_fbo_ = gl::Framebuffer::create("fluid.splash_thickness");
    thickness_fbo_.attach_colour(0, thickness_);
    thickness_fbo_.check_complete();
    smoothed_front_ = &front_;
}

glm::ivec4 FluidPass::screen_rect(const FrameContext& frame, const FluidView& view, int margin) const {
    // World bounds of the glass box (up to twice its height, where splashes fly) and
    // of every ellipsoid.
    glm::vec3 lo(1e30f), hi(-1e30f);
    if (view.tank_size != glm::vec3(0.0f))
        for (int k = 0; k < 8; ++k) {
            glm::vec3 c((k & 1) ? view.tank_size.x : 0.0f, (k & 2) ? 2.0f * view.tank_size.y : 0.0f,
                        (k & 4) ? view.tank_size.z : 0.0f);
            glm::vec3 w(view.tank_to_world * glm::vec4(c, 1.0f));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
    for (const auto* group : {&view.body, &view.splash})
        for (const sim::FluidEllipsoid& e : *group) {
            float r = std::max({glm::length(e.axis[0]), glm::length(e.axis[1]), glm::length(e.axis[2])});
            lo = glm::min(lo, e.centre - r);
            hi = glm::max(hi, e.centre + r);
        }
    if (lo.x > hi.x) return glm::ivec4(0);
    return screen_rect_of_box(frame.camera.view_proj, frame.camera.near_m, lo, hi, width_, height_, margin);
}

void FluidPass::upload(gl::Buffer& buffer, const std::vector<sim::FluidEllipsoid>& ellipsoids) {
    if (ellipsoids.empty()) return;
    std::vector<GpuEllipsoid> gpu(ellipsoids.size());
    for (size_t i = 0; i < ellipsoids.size(); ++i) {
        const sim::FluidEllipsoid& e = ellipsoids[i];
        gpu[i] = {glm::vec4(e.centre, 1.0f), glm::vec4(e.axis[0], 0.0f), glm::vec4(e.axis[1], 0.0f),
                  glm::vec4(e.axis[2], 0.0f)};
    }
    const GLsizeiptr bytes = GLsizeiptr(gpu.size() * sizeof(GpuEllipsoid));
    if (buffer.size() < bytes)
        buffer = gl::Buffer::create<GpuEllipsoid>(&buffer == &particles_[0] ? "fluid.body_particles" : "fluid.splash_particles",
                                                  std::span<const GpuEllipsoid>(gpu));
    else
        buffer.update<GpuEllipsoid>(0, std::span<const GpuEllipsoid>(gpu));
}

const gl::Texture* FluidPass::smooth(const gl::Texture& source, gl::Texture* ping_pong, const FrameContext& frame,
                                     float radius) {
    const gl::Program* p = &plane_fit_;
    if (smoothing_.method == SmoothingMethod::Bilateral) p = &bilateral_;
    if (smoothing_.method == SmoothingMethod::NarrowRange) p = &narrow_range_;
    p->use();
    set_ivec4(*p, "u_rect", rect_);
    p->set("u_proj", frame.camera.proj);
    p->set("u_viewport", glm::vec2(float(width_), float(height_)));
    p->set("u_depth", int(kMapUnit));
    // A preset may narrow the kernel: close to the tank its cost is per pixel of the screen.
    const int kernel = std::min(smoothing_.kernel_size, frame.resources.quality.fluid_kernel_max | 1);
    p->set("u_half", (kernel - 1) / 2);
    p->set("u_sigma", look_.plane_sigma_radii * radius);
    p->set("u_max_move", look_.plane_max_move_radii * radius);
    // The seed's bilateral parameters: sigma_1 = w / (2 sqrt 2), sigma_2 = 2 sqrt 2 r.
    p->set("u_sigma_space", float(kernel) / (2.0f * std::sqrt(2.0f)));
    p->set("u_sigma_depth", 2.0f * std::sqrt(2.0f) * radius);
    p->set("u_band", look_.narrow_band_radii * radius);
    const gl::Texture* in = &source;
    const int iterations = std::min(smoothing_.iterations, frame.resources.quality.fluid_smoothing_max);
    for (int it = 0; it < iterations; ++it) {
        gl::Texture* out = &ping_pong[it % 2];
        smooth_fbo_.attach_colour(0, *out);
        smooth_fbo_.bind();
        in->bind(kMapUnit);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        in = out;
    }
    return in;
}

void FluidPass::draw_splash(const FrameContext& frame, const FluidView& view) {
    const Camera& cam = frame.camera;
    const int s = kSplashScale;
    const glm::ivec4 low(rect_.x / s, rect_.y / s, (rect_.z + s - 1) / s, (rect_.w + s - 1) / s);
    const glm::vec2 low_size{float(thickness_.width()), float(thickness_.height())};

    // Thickness: soft sprites added up at a sixteenth of the pixels.
    thickness_fbo_.bind();
    glViewport(0, 0, thickness_.width(), thickness_.height());
    glScissor(low.x, low.y, low.z - low.x, low.w - low.y);
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    upload(particles_[1], view.splash);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, particles_[1].id());
    splash_thickness_.use();
    set_ivec4(splash_thickness_, "u_rect", low);
    splash_thickness_.set("u_proj", cam.proj);
    splash_thickness_.set("u_view", cam.view);
    splash_thickness_.set("u_viewport", low_size);
    splash_thickness_.set("u_soft_pixels", look_.splash_soft_pixels);
    splash_thickness_.set("u_scale", s);
    frame.targets.depth().bind(kSceneDepthUnit);
    splash_thickness_.set("u_scene_depth", int(kSceneDepthUnit));
    smoothed_front_->bind(kMapUnit);
    splash_thickness_.set("u_body_front", int(kMapUnit));
    gl::apply({.blend = gl::kAdd, .scissor = true, .program_point_size = true});
    glDrawArrays(GL_POINTS, 0, GLsizei(view.splash.size()));

    // The layer over the refracted liquid, premultiplied; the scene's alpha stays.
    shade_fbo_.bind();
    glViewport(0, 0, width_, height_);
    glScissor(rect_.x, rect_.y, rect_.z - rect_.x, rect_.w - rect_.y);
    const gl::Program& p = splash_layer_;
    SceneLighting::apply_sky(p, frame.data.sky);
    p.use();
    set_ivec4(p, "u_rect", rect_);
    p.set("u_proj", cam.proj);
    p.set("u_viewport", glm::vec2(float(width_), float(height_)));
    p.set("u_view_to_world", glm::mat3(glm::inverse(cam.view)));
    p.set("u_opacity_per_m", look_.splash_opacity_per_m);
    thickness_.bind(kMapUnit);
    p.set("u_thickness", int(kMapUnit));
    gl::apply({.blend = gl::kPremultipliedOver, .scissor = true});
    glDrawArrays(GL_TRIANGLES, 0, 3);
    gl::apply({.scissor = true});
}

void FluidPass::draw(const FrameContext& frame, const FluidView& view) {
    SceneTargets& t = frame.targets;
    const Camera& cam = frame.camera;
    resize_targets(t.width(), t.height());
    rect_ = screen_rect(frame, view, (FluidSmoothing::kMaxKernel - 1) / 2 + 2);
    times_ = {};
    if (rect_.z <= rect_.x || view.empty()) {
        rect_ = glm::ivec4(0);
        return;
    }
    auto clock = Clock::now();
    if (profiling_) lap(clock);
    const glm::vec2 viewport{float(width_), float(height_)};
    const float radius = view.particle_radius_m;

    // The scene so far (water included), around the rectangle: what refracted rays see,
    // copied into the shared scene copy there.
    const glm::ivec2 grow = (glm::ivec2(rect_.z - rect_.x, rect_.w - rect_.y)) / 2;
    const glm::ivec4 bg = glm::clamp(glm::ivec4(rect_.x - grow.x, rect_.y - grow.y, rect_.z + grow.x, rect_.w + grow.y),
                                     glm::ivec4(0), glm::ivec4(width_, height_, width_, height_));
    t.refresh_colour_copy(bg);

    gl::PipelineScope state({.scissor = true});
    glScissor(rect_.x, rect_.y, rect_.z - rect_.x, rect_.w - rect_.y);
    glViewport(0, 0, width_, height_);
    gl::bind_empty_vertex_array();

    {
        gl::DebugGroup group("fluid.depth_maps");
        gl::apply({.scissor = true, .program_point_size = true});
        ellipsoids_.use();
        set_ivec4(ellipsoids_, "u_rect", rect_);
        ellipsoids_.set("u_proj", cam.proj);
        ellipsoids_.set("u_view", cam.view);
        ellipsoids_.set("u_viewport", viewport);
        ellipsoids_.set("u_scene_depth", int(kSceneDepthUnit));
        t.depth().bind(kSceneDepthUnit);
        const float far_front[4] = {1.0e6f, 0, 0, 0}, zero[4] = {0, 0, 0, 0};
        depth_fbo_.bind();
        glClearBufferfv(GL_COLOR, 0, far_front);
        glClearBufferfv(GL_COLOR, 1, zero);
        if (!view.body.empty()) {
            upload(particles_[0], view.body);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, particles_[0].id());
            for (GLuint i = 0; i < 2; ++i) {
                glEnablei(GL_BLEND, i);
                glBlendFunci(i, GL_ONE, GL_ONE);
            }
            glBlendEquationi(0, GL_MIN);
            glBlendEquationi(1, GL_MAX);
            glDrawArrays(GL_POINTS, 0, GLsizei(view.body.size()));
        }
        gl::apply({.scissor = true});  // the per-buffer blending off again
    }
    if (profiling_) times_.depth_ms = lap(clock);

    {
        gl::DebugGroup group("fluid.smoothing");
        smoothed_front_ = smooth(front_, front_pp_, frame, radius);
        smoothed_back_ = smooth(back_, back_pp_, frame, radius);
    }
    if (profiling_) times_.smoothing_ms = lap(clock);

    {
        gl::DebugGroup group("fluid.normals");
        normals_.use();
        set_ivec4(normals_, "u_rect", rect_);
        normals_.set("u_proj", cam.proj);
        normals_.set("u_viewport", viewport);
        normals_.set("u_front", 1);
        normals_.set("u_back", 2);
        normal_fbo_.bind();
        smoothed_front_->bind(1);
        smoothed_back_->bind(2);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    if (profiling_) times_.normals_ms = lap(clock);

    {
        gl::DebugGroup group("fluid.refraction");
        if (shade_generation_ != t.generation()) {
            shade_fbo_ = gl::Framebuffer::create("fluid.shade");
            shade_fbo_.attach_colour(0, t.colour());
            shade_fbo_.check_complete();
            shade_generation_ = t.generation();
        }
        shade_fbo_.bind();
        const gl::Program& p = refract_;
        SceneLighting::apply_sky(p, frame.data.sky);
        p.use();
        set_ivec4(p, "u_rect", rect_);
        p.set("u_proj", cam.proj);
        p.set("u_viewport", viewport);
        set_ivec4(p, "u_background_rect", bg);
        p.set("u_view_to_world", glm::mat3(glm::inverse(cam.view)));
        p.set("u_view_to_tank", glm::inverse(cam.view * view.tank_to_world));
        p.set("u_tank_size", view.tank_size);
        p.set("u_absorption", look_.absorption_per_m * look_.absorption_colour);
        p.set("u_ior", look_.ior);
        p.set("u_epsilon", 0.25f * radius);
        p.set("u_frame_width", 0.025f);
        p.set("u_probe", probe_ ? 1 : 0);
        const gl::Texture* maps[4] = {smoothed_front_, smoothed_back_, &normal_[0], &normal_[1]};
        const char* names[4] = {"u_body_front", "u_body_back", "u_body_front_normal", "u_body_back_normal"};
        for (int k = 0; k < 4; ++k) {
            maps[k]->bind(GLuint(1 + k));
            p.set(names[k], 1 + k);
        }
        t.colour_copy().bind(9);  // read with texelFetch: the copy's filter does not matter
        p.set("u_background", 9);
        t.depth().bind(10);
        p.set("u_scene_depth", 10);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    if (profiling_) times_.refraction_ms = lap(clock);

    if (!view.splash.empty()) {
        gl::DebugGroup group("fluid.splash");
        draw_splash(frame, view);
    }
    if (profiling_) times_.splash_ms = lap(clock);
}

}  // namespace effects
