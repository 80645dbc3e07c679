#include "effects/energy/EnergyPass.h"

#include <algorithm>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

namespace {

// std430 layout of shaders/energy/field.glsl's EnergySegmentGpu: what depends only on
// the eye and the segment, once per segment (in double) instead of once per pixel.
struct SegmentGpu {
    glm::vec4 eye_sphere, dir_length, across_beam, normal_radius, axial;
};

SegmentGpu segment_gpu(const sim::EnergySegment& s, glm::dvec3 eye) {
    const glm::dvec3 d(s.direction), w = eye - glm::dvec3(s.start);
    const double h0 = glm::dot(w, d);
    const glm::dvec3 across = w - h0 * d;
    return {glm::vec4(glm::vec3(w), s.sphere_strength), glm::vec4(s.direction, s.length_m),
            glm::vec4(glm::vec3(across), s.beam_strength), glm::vec4(glm::vec3(glm::cross(w, d)), s.radius_m),
            glm::vec4(float(h0), float(glm::length(across)), 0.0f, 0.0f)};
}

// The view ray towards the far plane's point at (x, y) in normalised device
// coordinates, scaled by that point's homogeneous w: unnormalised, and affine in x and
// y (both the point's xyz and its w are), so a pixel gets it from its position.
glm::dvec3 scaled_ray(const Camera& camera, double x, double y) {
    const glm::dvec4 p = glm::dmat4(camera.inv_view_proj) * glm::dvec4(x, y, 1.0, 1.0);
    return glm::dvec3(p) - glm::dvec3(camera.eye) * p.w;
}

constexpr GLuint kSegmentBinding = 0, kTileBinding = 1, kTileSegmentBinding = 2;
constexpr GLuint kDepthUnit = 0;

}  // namespace

EnergyPass::EnergyPass()
    : program_(gl::Program::from_files("energy", {"energy/tiles.vert.glsl", "energy/energy.frag.glsl"})),
      blur_(gl::Program::from_files("energy.bloom_blur", {"common/fullscreen.vert.glsl", "energy/bloom_blur.frag.glsl"})),
      add_(gl::Program::from_files("energy.bloom_add", {"common/fullscreen.vert.glsl", "energy/bloom_add.frag.glsl"})) {}

void EnergyPass::register_params(ParamRegistry& params) {
    params.add("energy", "saturation", &look_.saturation, 0.1f, 20.0f);
    params.add("energy", "intensity", &look_.intensity, 0.0f, 40.0f);
    params.add("energy", "bloom", &look_.bloom, 0.0f, 4.0f);
}

void EnergyPass::render(const FrameContext& frame) {
    draw(frame, frame.data.energy.segments);
}

void EnergyPass::draw(const FrameContext& frame, std::span<const sim::EnergySegment> segments) {
    if (segments.empty()) return;
    const SceneTargets& t = frame.targets;
    if (generation_ != t.generation()) {
        // Colour only: the pass samples the scene depth, so it is not attached.
        fbo_ = gl::Framebuffer::create("energy");
        fbo_.attach_colour(0, t.colour());
        fbo_.check_complete();
        generation_ = t.generation();
    }
    fbo_.bind();
    glViewport(0, 0, t.width(), t.height());
    gl::PipelineScope state({.blend = gl::kAdd});
    draw_field(frame.camera, t.depth(), t.width(), t.height(), segments, false);
    gl::apply(gl::kFullScreen);
    if (look_.bloom > 0.0f && frame.resources.quality.bloom) bloom(frame, segments);
}

void EnergyPass::bloom(const FrameContext& frame, std::span<const sim::EnergySegment> segments) {
    const SceneTargets& t = frame.targets;
    const int w = std::max(1, t.width() / 4), h = std::max(1, t.height() / 4);
    if (bloom_a_.width() != w || bloom_a_.height() != h) {
        bloom_a_ = gl::Texture::create_2d("energy.bloom_a", GL_RGBA16F, w, h);
        bloom_b_ = gl::Texture::create_2d("energy.bloom_b", GL_RGBA16F, w, h);
        for (gl::Texture* tex : {&bloom_a_, &bloom_b_}) {
            tex->set_filter(GL_LINEAR, GL_LINEAR);
            tex->set_wrap(GL_CLAMP_TO_EDGE);
        }
        bloom_fbo_a_ = gl::Framebuffer::create("energy.bloom_a");
        bloom_fbo_a_.attach_colour(0, bloom_a_);
        bloom_fbo_a_.check_complete();
        bloom_fbo_b_ = gl::Framebuffer::create("energy.bloom_b");
        bloom_fbo_b_.attach_colour(0, bloom_b_);
        bloom_fbo_b_.check_complete();
    }
    // The glow at quarter resolution, over the same depth.
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(bloom_fbo_a_.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(bloom_fbo_b_.id(), GL_COLOR, 0, zero);
    bloom_fbo_a_.bind();
    glViewport(0, 0, w, h);
    draw_field(frame.camera, t.depth(), w, h, segments, false, bloom_buffers_);
    if (tiles_.tiles.empty()) return;
    // Blur and add only around the tiles with segments (plus the blur's reach).
    glm::ivec2 lo(w, h), hi(0, 0);
    for (const glm::uvec4& tile : tiles_.tiles) {
        lo = glm::min(lo, glm::ivec2(tile.x, tile.y) * EnergyTileGrid::kTilePx);
        hi = glm::max(hi, glm::ivec2(tile.x + 1, tile.y + 1) * EnergyTileGrid::kTilePx);
    }
    constexpr int kReach = 8;  // two 4-texel blurs
    lo = glm::max(lo - kReach, glm::ivec2(0));
    hi = glm::min(hi + kReach, glm::ivec2(w, h));
    gl::apply({.scissor = true});
    glScissor(lo.x, lo.y, hi.x - lo.x, hi.y - lo.y);
    gl::bind_empty_vertex_array();
    blur_.use();
    blur_.set("u_source", 0);
    bloom_fbo_b_.bind();
    bloom_a_.bind(0);
    blur_.set("u_step", glm::vec2(1.0f / float(w), 0.0f));
    glDrawArrays(GL_TRIANGLES, 0, 3);
    bloom_fbo_a_.bind();
    bloom_b_.bind(0);
    blur_.set("u_step", glm::vec2(0.0f, 1.0f / float(h)));
    glDrawArrays(GL_TRIANGLES, 0, 3);

    fbo_.bind();
    glViewport(0, 0, t.width(), t.height());
    const int sx = t.width() / w, sy = t.height() / h;  // rounded down: the scissor gets a texel of slack
    glScissor(lo.x * sx, lo.y * sy, (hi.x - lo.x) * sx + sx, (hi.y - lo.y) * sy + sy);
    gl::apply({.blend = gl::kAdd, .scissor = true});
    add_.use();
    add_.set("u_bloom", 0);
    add_.set("u_strength", look_.bloom);
    bloom_a_.bind(0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void EnergyPass::draw_field(const Camera& camera, const gl::Texture& depth, int width, int height,
                            std::span<const sim::EnergySegment> segments, bool raw) {
    draw_field(camera, depth, width, height, segments, raw, glow_buffers_);
}

void EnergyPass::draw_field(const Camera& camera, const gl::Texture& depth, int width, int height,
                            std::span<const sim::EnergySegment> segments, bool raw, FieldBuffers& buffers) {
    bin_energy_segments(camera, width, height, segments, method_.tile_culling, tiles_);
    if (tiles_.tiles.empty()) return;
    std::vector<SegmentGpu> gpu(segments.size());
    for (size_t i = 0; i < segments.size(); ++i) gpu[i] = segment_gpu(segments[i], glm::dvec3(camera.eye));
    gl::upload_growing(buffers.segments, "energy.segments", std::as_bytes(std::span(gpu)));
    gl::upload_growing(buffers.tiles, "energy.tiles", std::as_bytes(std::span(tiles_.tiles)));
    gl::upload_growing(buffers.tile_segments, "energy.tile_segments", std::as_bytes(std::span(tiles_.indices)));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSegmentBinding, buffers.segments.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileBinding, buffers.tiles.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileSegmentBinding, buffers.tile_segments.id());

    program_.use();
    program_.set("u_viewport", glm::vec2(float(width), float(height)));
    program_.set("u_tile_px", float(EnergyTileGrid::kTilePx));
    program_.set("u_depth", int(kDepthUnit));
    program_.set("u_depth_scale", glm::vec2(float(depth.width()) / float(width), float(depth.height()) / float(height)));
    // The ray at pixel (0, 0) and its steps per pixel.
    const glm::dvec3 r0 = scaled_ray(camera, -1.0, -1.0);
    const glm::dvec3 dx = (scaled_ray(camera, 1.0, -1.0) - r0) / double(width);
    const glm::dvec3 dy = (scaled_ray(camera, -1.0, 1.0) - r0) / double(height);
    program_.set("u_ray_origin", glm::vec3(r0));
    program_.set("u_ray_dx", glm::vec3(dx));
    program_.set("u_ray_dy", glm::vec3(dy));
    program_.set("u_forward", -glm::vec3(camera.view[0][2], camera.view[1][2], camera.view[2][2]));
    program_.set("u_depth_to_view", glm::vec2(camera.proj[3][2], camera.proj[2][2]));
    program_.set("u_max_distance_m", look_.max_distance_m);
    program_.set("u_march_samples", method_.march_samples);
    program_.set("u_raw", int(raw));
    program_.set("u_saturation", look_.saturation);
    program_.set("u_intensity", look_.intensity);
    program_.set("u_glow_colour", look_.glow_colour);
    depth.bind(kDepthUnit);
    gl::bind_empty_vertex_array();
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(tiles_.tiles.size()));
}

}  // namespace effects
