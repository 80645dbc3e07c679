#include "effects/Quality.h"

namespace effects {

QualitySettings quality_settings(Quality quality) {
    QualitySettings s;
    switch (quality) {
        case Quality::High: break;
        case Quality::Medium:
            s.render_scale = 0.75f;
            s.shadow_map_size = 1024;
            s.env_reflection = false;
            s.fluid_smoothing_max = 2;
            s.fluid_kernel_max = 5;
            s.rain_map_width = 512;
            s.dust_max_shells = 8;
            s.mirror_width = 128;
            break;
        case Quality::Low:
            s.render_scale = 0.5f;
            s.shadow_map_size = 512;
            s.soft_shadows = false;
            s.env_reflection = false;
            s.ground_detail = false;
            s.fluid_smoothing_max = 1;
            s.fluid_kernel_max = 3;
            s.rain_map_width = 256;
            s.bloom = false;
            s.dust_max_shells = 4;
            s.mirror_width = 0;
            break;
    }
    return s;
}

std::string_view quality_name(Quality quality) {
    switch (quality) {
        case Quality::Low: return "low";
        case Quality::Medium: return "medium";
        case Quality::High: return "high";
    }
    return "high";
}

std::optional<Quality> parse_quality(std::string_view name) {
    for (Quality q : {Quality::Low, Quality::Medium, Quality::High})
        if (name == quality_name(q)) return q;
    return std::nullopt;
}

std::vector<std::string> shader_defines(const QualitySettings& quality, bool line_lights) {
    return {std::string("SOFT_SHADOWS ") + (quality.soft_shadows ? "1" : "0"),
            std::string("ENV_REFLECTION ") + (quality.env_reflection ? "1" : "0"),
            std::string("GROUND_DETAIL ") + (quality.ground_detail ? "1" : "0"),
            std::string("LINE_LIGHTS ") + (line_lights ? "1" : "0")};
}

}  // namespace effects
