#pragma once
// The fixed-function state a draw runs under, set whole by apply(): every pass (and each
// step of a pass that changes it) says what it needs, so no pass depends on what another
// left behind. Stencil is off everywhere (no pass uses it); a pass that sets anything
// else (per-buffer blending, a scissor rectangle) sets it after apply().
#include "effects/gl/Gl.h"

namespace effects::gl {

struct BlendState {
    bool on = false;
    GLenum src_rgb = GL_ONE, dst_rgb = GL_ZERO, src_alpha = GL_ONE, dst_alpha = GL_ZERO;
    GLenum equation = GL_FUNC_ADD;
    bool operator==(const BlendState&) const = default;
};

inline constexpr BlendState kNoBlend{};
// Light added: glow, thickness, drop heights.
inline constexpr BlendState kAdd{true, GL_ONE, GL_ONE, GL_ONE, GL_ONE};
// Straight alpha over what is there, alpha too.
inline constexpr BlendState kAlphaOver{true, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA};
// Premultiplied colour over what is there; the target's alpha kept.
inline constexpr BlendState kPremultipliedOver{true, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE};

struct PipelineState {
    bool depth_test = false;
    bool depth_write = false;
    GLenum depth_func = GL_LESS;
    BlendState blend = kNoBlend;
    bool cull_back_faces = false;
    bool colour_write = true;
    bool scissor = false;  // the rectangle is the pass's (glScissor)
    // Depth pulled towards the eye (glPolygonOffset's factor and units), fills only.
    float offset_factor = 0.0f, offset_units = 0.0f;
    bool program_point_size = false;
    bool operator==(const PipelineState&) const = default;
};

// A full-screen triangle over what is there: nothing tested, blended or culled.
inline constexpr PipelineState kFullScreen{};

// GL's own initial state (depth written but not tested, nothing blended or culled): the
// state between passes, which clears and the HUD find.
inline constexpr PipelineState kInitialState{.depth_write = true};

// Sets all of `state`.
void apply(const PipelineState& state);

// A pass's state: applied now, and GL's initial state again when the pass ends.
class PipelineScope {
public:
    explicit PipelineScope(const PipelineState& state) { apply(state); }
    ~PipelineScope() { apply(kInitialState); }
    PipelineScope(const PipelineScope&) = delete;
    PipelineScope& operator=(const PipelineScope&) = delete;
};

}  // namespace effects::gl
