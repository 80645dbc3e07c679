#include "effects/rain/RainPass.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "effects/gl/PipelineState.h"
#include "sim/rain/GlassSurface.h"

namespace effects {

namespace {
constexpr float kBladeHalfWidth_m = 0.008f;  // the rubber's, wider than the arm's: the shader draws it this wide
}  // namespace

RainPass::RainPass(int height_map_width, int height_map_height)
    : height_map_(height_map_width, height_map_height),
      made_width_(height_map_width),
      made_height_(height_map_height),
      shade_(gl::Program::from_files("rain.windshield", {"rain/windshield.vert.glsl", "rain/windshield.frag.glsl"})),
      // Mirrored repeat: the seed folds lookups that leave the image back in.
      behind_sampler_(gl::Sampler::create("rain.behind", GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_MIRRORED_REPEAT)) {}

void RainPass::register_params(ParamRegistry& params) {
    params.add("rain", "draw", &look_.enabled);
    params.add("rain", "drop size on screen", &look_.radius_scale, 1.0f, 4.0f);
    params.add("rain", "refraction", &look_.refraction, 0.0f, 0.6f);
    params.add("rain", "refraction reach (drop radii)", &look_.reach, 1.0f, 10.0f);
    params.add("rain", "background blur (mip bias)", &look_.blur_bias, 0.0f, 4.0f);
    params.add("rain", "sun glint", &look_.glint, 0.0f, 4.0f);
    params.add("rain", "wet streaks", &look_.film, 0.0f, 1.0f);
    params.add("rain", "height compression steps", &look_.compression_steps, 0, 5);
    params.add("rain", "shade wet cells only", &look_.wet_cells_only);
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
    // The preset's map, whatever the scene's scale: the drops' sizes are on the glass,
    // not in pixels, and a map coarser than the preset's loses the drops smaller than its
    // texels (auto's scene at 0.5 once took a map half as wide, and harbour_rain 1690
    // lost most of its smallest drops: SSIM 0.788 against native).
    const int map_width = std::min(std::max(frame.resources.quality.rain_map_width, 128), made_width_);
    if (height_map_.width() != map_width) height_map_ = DropHeightMap(map_width, map_width * made_height_ / made_width_);
    const glm::vec2 glass_size(glass.width_m(), glass.height_m());
    HeightCompression compression;
    compression.steps = look_.compression_steps;
    height_map_.update(view.metaballs, glass_size, look_.radius_scale, compression);

    // What lies behind the glass now (water and all), with mips: the scene copy made
    // again whole.
    SceneTargets& t = frame.targets;
    if (scene_generation_ != t.generation()) {
        scene_colour_fbo_ = gl::Framebuffer::create("rain.scene_colour");
        scene_colour_fbo_.attach_colour(0, t.colour());
        scene_colour_fbo_.attach_depth(t.depth());
        scene_colour_fbo_.check_complete();
        scene_generation_ = t.generation();
    }
    t.refresh_colour_copy_with_mips();
    upload_film(view);

    glBindFramebuffer(GL_FRAMEBUFFER, scene_colour_fbo_.id());
    glViewport(0, 0, t.width(), t.height());
    // Tested, not written, against the scene's depth: the roof lining and the pillars
    // between the driver and the glass hide it; the offset keeps the glass's own depth
    // (where the scene drew it) from fighting with the drops.
    // Alpha composited too: the scene's is 1 and stays 1, a cleared 0 keeps the coverage.
    constexpr gl::BlendState kOverWithCoverage{true, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE,
                                               GL_ONE_MINUS_SRC_ALPHA};
    gl::PipelineScope state({.depth_test = true,
                             .depth_func = GL_LEQUAL,
                             .blend = kOverWithCoverage,
                             .offset_factor = -1.0f,
                             .offset_units = -4.0f});

    shade_.use();
    SceneLighting::apply_sky(shade_, frame.data.sky);
    shade_.set("u_model", view.car_to_world);
    shade_.set("u_blade_half_width_m", kBladeHalfWidth_m);
    shade_.set("u_view_proj", frame.camera.view_proj);
    shade_.set("u_eye", frame.camera.eye);
    shade_.set("u_glass_size_m", glass_size);
    shade_.set("u_inv_viewport", glm::vec2(1.0f / float(t.width()), 1.0f / float(t.height())));
    shade_.set("u_aspect", float(t.width()) / float(t.height()));
    shade_.set("u_refraction", look_.refraction);
    shade_.set("u_reach", look_.reach);
    shade_.set("u_blur_bias", look_.blur_bias);
    shade_.set("u_scene_lod", std::log2(std::min(scene_scale(t, frame.output), 1.0f)));
    shade_.set("u_glint", look_.glint);
    shade_.set("u_film", view.film.empty() ? 0.0f : look_.film);
    shade_.set("u_film_scale", view.film_cell_m > 0.0f ? glm::vec2(1.0f / (float(film_cols_) * view.film_cell_m),
                                                                   1.0f / (float(film_rows_) * view.film_cell_m))
                                                       : glm::vec2(0.0f));
    shade_.set("u_sums", 0);
    shade_.set("u_map_texel", glm::vec2(1.0f / float(height_map_.width()), 1.0f / float(height_map_.height())));
    height_map_.set_shape(shade_);
    shade_.set("u_behind", 1);
    shade_.set("u_film_map", 2);
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
    height_map_.sums().bind(0);
    t.colour_copy().bind(1);
    behind_sampler_.bind(1);
    film_.bind(2);
    // Only the cells where the shader can draw: elsewhere it discards every pixel. A
    // blade covers pixels up to its half width plus one pixel's footprint on the glass
    // (fwidth): bounded here by 16 times the glass's mean metres per pixel across the
    // screen, several times what the most oblique corner of the glass gives.
    const float blade_reach_m = kBladeHalfWidth_m + std::max(0.02f, 16.0f * glass_size.x / float(t.width()));
    shown_cells(mesh_->grid(), view,
                {.tiles = &height_map_.tiles(),
                 .map_width = height_map_.width(),
                 .map_height = height_map_.height(),
                 .film_strength = view.film.empty() ? 0.0f : look_.film,
                 .blade_reach_m = blade_reach_m},
                shown_);
    if (!look_.wet_cells_only) std::fill(shown_.begin(), shown_.end(), uint8_t(1));
    mesh_->draw(shown_);
    gl::Sampler::unbind(1);
}

size_t RainPass::cells_drawn() const { return size_t(std::count(shown_.begin(), shown_.end(), uint8_t(1))); }

void RainPass::upload_film(const RainView& view) {
    const int cols = view.film.empty() ? 1 : view.film_cols, rows = view.film.empty() ? 1 : view.film_rows;
    if (film_cols_ != cols || film_rows_ != rows) {
        film_cols_ = cols;
        film_rows_ = rows;
        film_ = gl::Texture::create_2d("rain.film", GL_R8, cols, rows);
        film_.set_filter(GL_LINEAR, GL_LINEAR);
        film_.set_wrap(GL_CLAMP_TO_EDGE);
    }
    static constexpr uint8_t kDry[1] = {0};
    film_.upload(GL_RED, GL_UNSIGNED_BYTE, view.film.empty() ? std::span<const uint8_t>(kDry) : std::span<const uint8_t>(view.film));
}

}  // namespace effects
