#include "effects/water/WaterShading.h"

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

namespace {
// Mask depths: cleared far where there is no water. Each shading pass draws at a depth
// in front of the kinds it shades (GL_GREATER passes where the mask is nearer).
constexpr float kSheetMask = 0.2f, kSeaMask = 0.6f;
constexpr float kSheetPassDepth = 0.4f, kSeaPassDepth = 0.8f;  // the sea pass also sees sheets, and discards them
}  // namespace

WaterShading::WaterShading()
    : sea_("water.shade_sea", {"water/screen.vert.glsl", "water/shade_sea.frag.glsl"}),
      sheet_("water.shade_sheet", {"water/screen.vert.glsl", "water/shade_sheet.frag.glsl"}),
      mask_(gl::Program::from_files("water.mask", {"water/screen.vert.glsl", "water/mask.frag.glsl"})) {
    select_programs(quality_settings(Quality::High), false);
}

void WaterShading::select_programs(const QualitySettings& quality, bool line_lights) {
    sea_program_ = &sea_.get(quality, line_lights);
    sheet_program_ = &sheet_.get(quality, line_lights);
}

void WaterShading::begin_geometry(const SceneTargets& t) {
    if (t.colour().id() != colour_id_ || t.normal().id() != normal_id_ || t.depth().id() != depth_id_ ||
        kind_.width() != t.width() || kind_.height() != t.height()) {
        kind_ = gl::Texture::create_2d("water.kind", GL_RGBA8, t.width(), t.height());
        kind_.set_filter(GL_NEAREST, GL_NEAREST);
        kind_.set_wrap(GL_CLAMP_TO_EDGE);
        mask_depth_ = gl::Texture::create_2d("water.mask", GL_DEPTH_COMPONENT32F, t.width(), t.height());
        geometry_fbo_ = gl::Framebuffer::create("water.geometry");
        geometry_fbo_.attach_colour(0, t.normal());
        geometry_fbo_.attach_colour(1, kind_);
        geometry_fbo_.attach_depth(t.depth());
        geometry_fbo_.set_draw_buffers({0, 1});
        geometry_fbo_.check_complete();
        // Shading samples the scene's depth and normals, so they are not attached here.
        shade_fbo_ = gl::Framebuffer::create("water.shade");
        shade_fbo_.attach_colour(0, t.colour());
        shade_fbo_.attach_depth(mask_depth_);
        shade_fbo_.set_draw_buffers({0});
        shade_fbo_.check_complete();
        colour_id_ = t.colour().id();
        normal_id_ = t.normal().id();
        depth_id_ = t.depth().id();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, geometry_fbo_.id());
    glViewport(0, 0, t.width(), t.height());
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 1, none);
}

void WaterShading::shade(const SceneTargets& t, bool sheets, glm::ivec4 rect) {
    if (rect.z <= rect.x || rect.w <= rect.y) return;
    glBindFramebuffer(GL_FRAMEBUFFER, shade_fbo_.id());
    glViewport(0, 0, t.width(), t.height());
    t.depth().bind(kDepthUnit);
    t.normal().bind(kNormalUnit);
    kind_.bind(kKindUnit);
    gl::bind_empty_vertex_array();

    // The mask, depth only.
    gl::apply({.depth_test = true, .depth_write = true, .depth_func = GL_ALWAYS, .colour_write = false, .scissor = true});
    glScissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);
    const float far = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far);
    mask_.use();
    mask_.set("u_kind", int(kKindUnit));
    mask_.set("u_sea_depth", kSeaMask);
    mask_.set("u_sheet_depth", kSheetMask);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // The shading passes, where the mask lets them through.
    gl::apply({.depth_test = true, .depth_func = GL_GREATER, .scissor = true});
    glScissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);
    auto pass = [&](const gl::Program& p, float depth) {
        p.use();
        p.set("u_window_depth", depth);
        p.set("u_depth", int(kDepthUnit));
        p.set("u_normals", int(kNormalUnit));
        p.set("u_kind", int(kKindUnit));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };
    pass(*sea_program_, kSeaPassDepth);
    if (sheets) pass(*sheet_program_, kSheetPassDepth);
}

}  // namespace effects
