#pragma once
// The energy wave (docs/effects/energy.md, "What is implemented"): after the water,
// each pixel of the tiles some segment covers integrates the field in closed form
// between the eye and the first opaque surface of the scene depth (which the water pass
// has written), and adds the glow to the HDR scene colour before tone mapping; then a
// bloom: the glow at quarter resolution, blurred, added over the same part of the
// screen.
#include <span>
#include <string_view>

#include <glm/vec3.hpp>

#include "effects/energy/EnergyTiles.h"
#include "effects/energy/EnergyView.h"
#include "effects/gl/Buffer.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

// The tweakable look, registered with the debug panel under "energy".
struct EnergyLook {
    float saturation = 2.0f;                   // k of 1 - exp(-k H)
    float intensity = 2.5f;                    // HDR radiance where the glow saturates
    glm::vec3 glow_colour{0.1f, 0.4f, 1.0f};   // the falloff's colour; the core goes white
    float max_distance_m = 2000.0f;            // how far rays into the sky integrate
    float bloom = 0.5f;                        // strength of the blurred glow added on top
};

// How the field is integrated: closed form (march_samples 0) or the ray-marching
// baseline; with or without per-tile culling.
struct EnergyMethod {
    int march_samples = 0;
    bool tile_culling = true;
};

class EnergyPass final : public Pass {
public:
    EnergyPass();
    std::string_view name() const override { return "energy"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

    // Adds the glow of these segments to the scene colour, occluded by the scene depth.
    void draw(const FrameContext& frame, std::span<const sim::EnergySegment> segments);
    // Draws into the bound framebuffer (viewport 0,0,width,height, under the caller's
    // gl::PipelineState: no depth test, blended or not): the glow, or with `raw` H in red and the ray's end distance in
    // green, for float targets. `depth` is the scene depth the rays stop at.
    void draw_field(const Camera& camera, const gl::Texture& depth, int width, int height,
                    std::span<const sim::EnergySegment> segments, bool raw);

    // The GPU lists one draw of the field reads: its segments, tiles and tiles' segments.
    struct FieldBuffers {
        gl::Buffer segments, tiles, tile_segments;
    };
    // The full-resolution glow's (draw_field's); the bloom has its own.
    const FieldBuffers& glow_buffers() const { return glow_buffers_; }

    EnergyLook& look() { return look_; }
    EnergyMethod& method() { return method_; }
    const EnergyTileGrid& tiles() const { return tiles_; }  // of the last draw

private:
    void bloom(const FrameContext& frame, std::span<const sim::EnergySegment> segments);
    void draw_field(const Camera& camera, const gl::Texture& depth, int width, int height,
                    std::span<const sim::EnergySegment> segments, bool raw, FieldBuffers& buffers);

    gl::Program program_, blur_, add_;
    gl::Texture bloom_a_, bloom_b_;  // quarter resolution: the glow, and the half-blurred glow
    gl::Framebuffer bloom_fbo_a_, bloom_fbo_b_;
    // Apart, so that the bloom's upload does not rewrite lists the glow's draw may still be
    // reading: llvmpipe rasterises that draw after the call returns and did not wait for
    // it before the update, so now and then a tile shaded with the bloom's segments.
    FieldBuffers glow_buffers_, bloom_buffers_;
    gl::Framebuffer fbo_;
    uint64_t generation_ = 0;  // SceneTargets::generation() fbo_ was built for
    EnergyTileGrid tiles_;
    EnergyLook look_;
    EnergyMethod method_;
};

}  // namespace effects
