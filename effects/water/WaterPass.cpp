#include "effects/water/WaterPass.h"

#include "effects/gl/PipelineState.h"
#include "effects/scene/ScreenRect.h"

#include <algorithm>

#include <glm/common.hpp>

namespace effects {

WaterPass::WaterPass() = default;

void WaterPass::register_params(ParamRegistry& params) {
    params.add("water", "foam", &look_.foam, 0.0f, 3.0f);
    params.add("water", "shore foam", &look_.shore_foam, 0.0f, 1.0f);
    params.add("water", "absorption", &look_.absorption, 0.0f, 4.0f);
    params.add("water", "refraction", &look_.refraction, 0.0f, 0.1f);
    params.add("water", "ripples", &look_.ripples, 0.0f, 2.0f);
    params.add("water", "sheet thickness m", &look_.sheet_thickness_m, 0.002f, 0.1f);
    params.add("water", "sheet tear stretch", &look_.sheet_tear_stretch, 1.5f, 50.0f);
    params.add("water", "triangle size px", &look_.triangle_px, 2.0f, 32.0f);
    params.add("water", "splash foam", &look_.splash_foam, 0.0f, 2.0f);
    params.add("water", "rim drops", &look_.rim_drops);
    params.add("water", "splash foam fade s", &look_.splash_foam_look.fade_s, 0.2f, 4.0f);
    params.add("water", "spray opacity", &look_.spray.opacity, 0.0f, 1.0f);
    params.add("water", "spray min pixels", &look_.spray.min_pixels, 0.5f, 4.0f);
    params.add("water", "spray blur (m)", &look_.spray.blur_m, 0.0f, 0.1f);
}

void WaterPass::render(const FrameContext& frame) {
    gather_water_view(frame.world, view_);
    draw(frame, view_);
}

glm::ivec4 WaterPass::water_rect(const Camera& cam, const SceneTargets& t, bool sheets) const {
    glm::vec3 lo, hi;
    surface_.bounds(lo, hi);
    glm::ivec4 rect = screen_rect_of_box(cam.view_proj, cam.near_m, lo, hi, t.width(), t.height(), 1);
    if (sheets && !sheets_.mesh().vertices.empty()) {
        lo = hi = sheets_.mesh().vertices.front().position;
        for (const SheetVertex& v : sheets_.mesh().vertices) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
        const glm::ivec4 r = screen_rect_of_box(cam.view_proj, cam.near_m, lo, hi, t.width(), t.height(), 1);
        if (r.z > r.x && r.w > r.y)
            rect = rect.z > rect.x && rect.w > rect.y ? glm::ivec4(glm::min(glm::ivec2(rect), glm::ivec2(r)),
                                                                   glm::max(glm::ivec2(rect.z, rect.w), glm::ivec2(r.z, r.w)))
                                                      : r;
    }
    return rect;
}

void WaterPass::update_splash_foam(const WaterView& view, const gl::Program& sea) {
    foam_.update(view, look_.splash_foam_look);
    const FoamField& f = foam_.field();
    const int side = std::max(f.size, 1);
    if (side != foam_map_side_) {
        foam_map_ = gl::Texture::create_2d("water.splash_foam", GL_R8, side, side);
        foam_map_.set_filter(GL_LINEAR, GL_LINEAR);
        foam_map_.set_wrap(GL_CLAMP_TO_EDGE);  // the map's border texels are always clear
        foam_map_side_ = side;
        if (f.size == 0) {
            const uint8_t none = 0;
            foam_map_.upload<uint8_t>(GL_RED, GL_UNSIGNED_BYTE, std::span<const uint8_t>(&none, 1));
        }
    }
    if (f.size > 0) foam_map_.upload<uint8_t>(GL_RED, GL_UNSIGNED_BYTE, f.texels);
    foam_map_.bind(kSplashFoamUnit);
    sea.set("u_splash_foam", int(kSplashFoamUnit));
    sea.set("u_splash_foam_origin", f.origin_xz);
    sea.set("u_splash_foam_size_m", float(f.size) * f.texel_m);
    sea.set("u_splash_foam_amount", f.size > 0 ? look_.splash_foam : 0.0f);
}

void WaterPass::draw(const FrameContext& frame, const WaterView& view) {
    view.validate();
    const SceneTargets& t = frame.targets;
    const Camera& cam = frame.camera;
    const float time_s = float(frame.time_s);
    surface_.update(view);  // its own small pass first: it binds another framebuffer

    // Geometry with cheap shaders: the sea's depth, then the airborne sheets' depth,
    // normals and kind, where they stand in front of it.
    gl::PipelineScope state({.depth_test = true, .depth_write = true});
    shading_.begin_sea(t);
    {
        const gl::Program& p = surface_.program();
        p.use();
        p.set("u_view_proj", cam.view_proj);
        p.set("u_sea_level", view.sea_level_m);
        surface_.draw(cam, t.height(), look_.triangle_px);
    }
    const bool sheets = sheets_.update(view, look_.sheet_tear_stretch);
    if (sheets) {
        shading_.begin_sheets(t);
        const gl::Program& p = sheets_.program();
        p.use();
        p.set("u_view_proj", cam.view_proj);
        p.set("u_eye", cam.eye);
        p.set("u_sea_level", view.sea_level_m);
        p.set("u_foam", look_.foam);
        sheets_.draw();
    }

    // Shading, once per water pixel.
    shading_.select_programs(frame.resources.quality, !frame.data.line_lights.empty());
    for (const gl::Program* p : {&shading_.sea_program(), &shading_.sheet_program()}) {
        frame.lighting.apply(*p, frame.data);
        p->set("u_inv_view_proj", cam.inv_view_proj);
        p->set("u_eye", cam.eye);
        p->set("u_time_s", time_s);
        p->set("u_sea_level", view.sea_level_m);
        p->set("u_inv_viewport", glm::vec2(1.0f / float(t.width()), 1.0f / float(t.height())));
        p->set("u_absorption", look_.absorption);
        p->set("u_refraction", look_.refraction);
        p->set("u_foam", look_.foam);
        p->set("u_shore_foam", look_.shore_foam);
        p->set("u_sheet_thickness_m", look_.sheet_thickness_m);
    }
    {
        const gl::Program& p = shading_.sea_program();
        surface_.set_grid(p);
        p.set("u_ripples", look_.ripples);
        p.set("u_pixel_m", 2.0f / (cam.proj[1][1] * float(t.height())));
        update_splash_foam(view, p);
    }
    surface_.bind_grid_textures();
    shading_.shade(t, sheets, water_rect(cam, t, sheets));

    // Spray over the shaded water, into the scene colour (depth-tested, not written).
    // The beads on the sheets' rims and the drops their jets pinch off go with it.
    const std::vector<SprayDrop>& beads = sheets_.mesh().drops;
    if (beads.empty() || !sheets || !look_.rim_drops) {
        spray_.draw(frame, view.spray, look_.spray);
    } else {
        drops_.assign(view.spray.begin(), view.spray.end());
        drops_.insert(drops_.end(), beads.begin(), beads.end());
        spray_.draw(frame, drops_, look_.spray);
    }
}

}  // namespace effects
