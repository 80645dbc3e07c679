#include "effects/water/WaterShading.h"

#include "effects/gl/EmptyVertexArray.h"
#include "effects/gl/PipelineState.h"

namespace effects {

namespace {
// Mask depths, with no water between the sea's and the sheets'. The sea pass draws
// just behind the sea's mask (GL_GREATER: passes where the mask is nearer), the sheet
// pass just in front of the sheets' (GL_LESS), so each sees its own kind only.
constexpr float kSeaMask = 0.2f, kNoneMask = 0.5f, kSheetMask = 0.8f;
constexpr float kSeaPassDepth = 0.35f, kSheetPassDepth = 0.65f;
}  // namespace

WaterShading::WaterShading()
    : sea_("water.shade_sea", {"water/screen.vert.glsl", "water/shade_sea.frag.glsl"}),
      sheet_("water.shade_sheet", {"water/screen.vert.glsl", "water/shade_sheet.frag.glsl"}),
      sea_mask_(gl::Program::from_files("water.mask", {"water/screen.vert.glsl", "water/mask.frag.glsl"})),
      sea_and_sheet_mask_(
          gl::Program::from_files("water.mask.sheets", {"water/screen.vert.glsl", "water/mask.frag.glsl"}, {"SHEETS"})) {
    select_programs(quality_settings(Quality::High), false);
}

void WaterShading::select_programs(const QualitySettings& quality, bool line_lights) {
    sea_program_ = &sea_.get(quality, line_lights);
    sheet_program_ = &sheet_.get(quality, line_lights);
}

void WaterShading::follow_targets(const SceneTargets& t) {
    if (generation_ == t.generation()) return;
    kind_ = gl::Texture::create_2d("water.kind", GL_RGBA8, t.width(), t.height());
    kind_.set_filter(GL_NEAREST, GL_NEAREST);
    kind_.set_wrap(GL_CLAMP_TO_EDGE);
    mask_depth_ = gl::Texture::create_2d("water.mask", GL_DEPTH_COMPONENT32F, t.width(), t.height());
    sea_fbo_ = gl::Framebuffer::create("water.sea");
    sea_fbo_.attach_depth(t.depth());
    sea_fbo_.set_draw_buffers({});
    sea_fbo_.check_complete();
    sheet_fbo_ = gl::Framebuffer::create("water.sheets");
    sheet_fbo_.attach_colour(0, t.normal());
    sheet_fbo_.attach_colour(1, kind_);
    sheet_fbo_.attach_depth(t.depth());
    sheet_fbo_.set_draw_buffers({0, 1});
    sheet_fbo_.check_complete();
    // Shading samples the scene's depth and normals, so they are not attached here.
    shade_fbo_ = gl::Framebuffer::create("water.shade");
    shade_fbo_.attach_colour(0, t.colour());
    shade_fbo_.attach_depth(mask_depth_);
    shade_fbo_.set_draw_buffers({0});
    shade_fbo_.check_complete();
    generation_ = t.generation();
}

void WaterShading::begin_sea(const SceneTargets& t) {
    follow_targets(t);
    glBindFramebuffer(GL_FRAMEBUFFER, sea_fbo_.id());
    glViewport(0, 0, t.width(), t.height());
}

void WaterShading::begin_sheets(const SceneTargets& t) {
    follow_targets(t);
    glBindFramebuffer(GL_FRAMEBUFFER, sheet_fbo_.id());
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

    t.depth_copy().bind(kDepthCopyUnit);
    t.colour_copy().bind(kColourCopyUnit);

    // The mask, depth only, over the whole rectangle.
    gl::apply({.depth_test = true, .depth_write = true, .depth_func = GL_ALWAYS, .colour_write = false, .scissor = true});
    glScissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);
    const gl::Program& mask = sheets ? sea_and_sheet_mask_ : sea_mask_;
    mask.use();
    mask.set("u_depth", int(kDepthUnit));
    mask.set("u_scene_depth", int(kDepthCopyUnit));
    mask.set("u_kind", int(kKindUnit));
    mask.set("u_none_depth", kNoneMask);
    mask.set("u_sea_depth", kSeaMask);
    mask.set("u_sheet_depth", kSheetMask);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    // The shading passes, where the mask lets them through.
    auto pass = [&](const gl::Program& p, float depth, GLenum depth_func) {
        gl::apply({.depth_test = true, .depth_func = depth_func, .scissor = true});
        glScissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);
        p.use();
        p.set("u_window_depth", depth);
        p.set("u_depth", int(kDepthUnit));
        p.set("u_normals", int(kNormalUnit));
        p.set("u_kind", int(kKindUnit));
        p.set("u_scene_colour", int(kColourCopyUnit));
        p.set("u_scene_depth", int(kDepthCopyUnit));
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };
    pass(*sea_program_, kSeaPassDepth, GL_GREATER);
    if (sheets) pass(*sheet_program_, kSheetPassDepth, GL_LESS);
}

}  // namespace effects
