#include "sim/weather/Weather.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/player/Player.h"
#include "sim/world/World.h"

namespace sim {
namespace {

float unit(float x) { return std::clamp(x, 0.0f, 1.0f); }

// A first-order lag of `time_s` over one step of `dt`: basic operations only, so every
// build and machine gets the same bits. Within a hair of the target it lands on it: a
// lag alone would creep towards zero through the denormals and never stop raining.
float approach(float value, float target, float time_s, float dt) {
    if (std::fabs(target - value) < 1e-4f) return target;
    return value + (target - value) * std::min(1.0f, dt / time_s);
}

}  // namespace

float Weather::settled_cloud(float rain_intensity) {
    const float r = unit(rain_intensity);
    return r > 0.0f ? kDrizzleCloud + (1.0f - kDrizzleCloud) * r : 0.0f;
}

float Weather::settled_wetness(float rain_intensity) {
    // Where wetting, r * kWet * (1 - w), balances drying, kDry * (1 - r).
    const float r = unit(rain_intensity);
    if (!(r > 0.0f)) return 0.0f;
    return unit(1.0f - kDryPerS * (1.0f - r) / (r * kWetPerS));
}

Weather::Weather(float rain_intensity) {
    if (!std::isfinite(rain_intensity) || rain_intensity < 0.0f || rain_intensity > 1.0f)
        throw std::invalid_argument("weather: the rain intensity must be within 0..1, got " +
                                    std::to_string(rain_intensity));
    rain_rate_ = rain_intensity;
    cloud_cover_ = settled_cloud(rain_intensity);
    road_wetness_ = settled_wetness(rain_intensity);
}

void Weather::connect(const SubsystemLinks& links) { player_ = links.may<Player>(); }

void Weather::step(StepContext& ctx) { advance(player_ ? player_->rain_intensity() : 0.0f, ctx.dt); }

void Weather::advance(float rain_intensity, float dt) {
    if (!std::isfinite(rain_intensity) || !(dt > 0.0f))
        throw std::invalid_argument("weather: the rain intensity must be finite and dt positive");
    const float target = unit(rain_intensity);
    rain_rate_ = unit(approach(rain_rate_, target, target > rain_rate_ ? kRainRiseTime_s : kRainFallTime_s, dt));
    const float cloud = settled_cloud(target);
    cloud_cover_ = unit(approach(cloud_cover_, cloud, cloud > cloud_cover_ ? kCloudRiseTime_s : kCloudClearTime_s, dt));
    const float r = rain_rate_;
    road_wetness_ = unit(road_wetness_ + dt * (r * kWetPerS * (1.0f - road_wetness_) - kDryPerS * (1.0f - r)));
}


}  // namespace sim
