#include "effects/rain/RainPass.h"

#include <algorithm>
#include <cmath>

#include "sim/rain/GlassSurface.h"

namespace effects {

RainPass::RainPass(int height_map_width, int height_map_height)
    : height_map_(height_map_width, height_map_height),
      made_width_(height_map_width),
      made_height_(height_map_height),
      shade_(gl::Program::from_files("rain.windshield", {"rain/windshield.vert.glsl", "rain/windshield.frag.glsl"})) {}

void RainPass::register_params(ParamRegistry& params) {
    params.add("rain", "draw", &look_.enabled);
    params.add("rain", "drop size on screen", &look_.radius_scale, 1.0f, 4.0f);
    params.add("rain", "refraction", &look_.refraction, 0.0f, 0.2f);
    params.add("rain", "background blur (mip)", &look_.blur_lod, 0.0f, 5.0f);
    params.add("rain", "rim darkening", &look_.rim, 0.0f, 1.0f);
    params.add("rain", "height compression steps", &look_.compression_steps, 0, 5);
}

void RainPass::render(const FrameContext& frame) {
    gather_rain_view(frame.world, view_);
    view_.car_to_world = frame.poses.car.matrix();  // the glass moves with the car as drawn
    draw(frame, view_);
}

void RainPass::draw(const FrameContext& frame, const RainView& view) {
    drew_ = false;
    if (!look_.enabled || view.idle()) return;
    drew_ = true;
    const sim::GlassSurface& glass = *view.glass;
    if (!mesh_ || mesh_->glass() != &glass) mesh_ = std::make_unique<WindshieldMesh>(glass);
    // The preset's map size scaled with the scene (the drops need no finer map than the
    // pixels they cover), in steps of 64 texels, at most the size the pass was made with.
    const float scene_scale = float(frame.scene.targets.width()) / float(std::max(frame.output.width, 1));
    const int scaled = int(std::lround(float(frame.scene.quality.rain_map_width) * std::min(scene_scale, 1.0f) / 64.0f)) * 64;
    const int map_width = std::min(std::max(scaled, 128), made_width_);
    if (height_map_.width() != map_width) height_map_ = DropHeightMap(map_width, map_width * made_height_ / made_width_);
    const glm::vec2 glass_size(glass.width_m(), glass.height_m());
    HeightCompression compression;
    compression.steps = look_.compression_steps;
    height_map_.update(view.metaballs, glass_size, look_.radius_scale, compression);

    // What lies behind the glass now (water and all), with mips: the copy SceneTargets
    // keeps predates the water and has none.
    const SceneTargets& t = frame.scene.targets;
    if (behind_w_ != t.width() || behind_h_ != t.height()) {
        behind_w_ = t.width();
        behind_h_ = t.height();
        behind_ = gl::Texture::create_2d("rain.behind", GL_RGBA16F, behind_w_, behind_h_,
                                         gl::Texture::full_mip_levels(behind_w_, behind_h_));
        behind_.set_filter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
        behind_.set_wrap(GL_MIRRORED_REPEAT);  // the seed folds lookups that leave the image back in
        behind_fbo_ = gl::Framebuffer::create("rain.behind");
        behind_fbo_.attach_colour(0, behind_);
        behind_fbo_.check_complete();
        scene_colour_fbo_ = gl::Framebuffer::create("rain.scene_colour");
        scene_colour_fbo_.attach_colour(0, t.colour());
        scene_colour_fbo_.attach_depth(t.depth());
        scene_colour_fbo_.check_complete();
    }
    glNamedFramebufferReadBuffer(t.scene().id(), GL_COLOR_ATTACHMENT0);
    glBlitNamedFramebuffer(t.scene().id(), behind_fbo_.id(), 0, 0, behind_w_, behind_h_, 0, 0, behind_w_, behind_h_,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
    behind_.generate_mipmaps();

    glBindFramebuffer(GL_FRAMEBUFFER, scene_colour_fbo_.id());
    glViewport(0, 0, behind_w_, behind_h_);
    // Tested, not written, against the scene's depth: the roof lining and the pillars
    // between the driver and the glass hide it; the offset keeps the glass's own depth
    // (where the scene drew it) from fighting with the drops.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -4.0f);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);

    shade_.use();
    frame.scene.lighting.apply_sky(shade_);
    shade_.set("u_model", view.car_to_world);
    shade_.set("u_view_proj", frame.camera.view_proj);
    shade_.set("u_eye", frame.camera.eye);
    shade_.set("u_glass_size_m", glass_size);
    shade_.set("u_inv_viewport", glm::vec2(1.0f / float(behind_w_), 1.0f / float(behind_h_)));
    shade_.set("u_aspect", float(behind_w_) / float(behind_h_));
    shade_.set("u_refraction", look_.refraction);
    shade_.set("u_blur_lod", std::max(look_.blur_lod + std::log2(float(behind_h_) / 360.0f), 0.0f));
    shade_.set("u_rim", look_.rim);
    shade_.set("u_surface", 0);
    shade_.set("u_behind", 1);
    const int blades = int(std::min<size_t>(view.blades.size(), 2));
    static constexpr const char* kPivot[2] = {"u_blade_pivot[0]", "u_blade_pivot[1]"};
    static constexpr const char* kDir[2] = {"u_blade_dir[0]", "u_blade_dir[1]"};
    static constexpr const char* kSpan[2] = {"u_blade_span[0]", "u_blade_span[1]"};
    for (int b = 0; b < blades; ++b) {
        const WiperBladeView& w = view.blades[size_t(b)];
        shade_.set(kPivot[b], w.pivot_m);
        shade_.set(kDir[b], w.direction);
        shade_.set(kSpan[b], glm::vec2(w.inner_m, w.outer_m));
    }
    for (int b = blades; b < 2; ++b) shade_.set(kSpan[b], glm::vec2(0.0f));
    height_map_.surface().bind(0);
    behind_.bind(1);
    mesh_->draw();
    glDisable(GL_BLEND);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
}

}  // namespace effects
