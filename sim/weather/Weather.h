#pragma once
// The weather (docs/effects/weather.md): one small deterministic state that follows the
// player's rain intensity with smooth transitions, and that everything wet reads: the
// windshield's drops and the sea's dimples fall at its rain rate, the renderer greys the
// sky, dims the sun and wets the road from it. Clouds gather before the rain comes and
// clear after it stops; the road wets while it rains and dries slowly after.
#include <cstdint>

#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Player;

class Weather final : public DescribedSubsystem<Weather> {
public:
    // Seconds for a lag to close (1 - 1/e of) a gap: first-order, stepped per tick.
    static constexpr float kRainRiseTime_s = 2.0f;
    static constexpr float kRainFallTime_s = 3.0f;
    static constexpr float kCloudRiseTime_s = 3.0f;
    static constexpr float kCloudClearTime_s = 12.0f;
    // Any rain brings at least this much cloud; full rain a fully overcast sky.
    static constexpr float kDrizzleCloud = 0.6f;
    // Wetting per second at full rain (of what is still dry), drying per second in the dry
    // (of a fully wet road): wet in a few seconds of a downpour, dry after about a minute.
    static constexpr float kWetPerS = 0.25f;
    static constexpr float kDryPerS = 1.0f / 60.0f;
    // The sun's strength lost under a full overcast.
    static constexpr float kOvercastSunLoss = 0.8f;

    // Starts settled at `rain_intensity` (a level that opens in the rain opens overcast
    // and wet). Throws std::invalid_argument unless it is finite and within 0..1.
    explicit Weather(float rain_intensity);

    static constexpr std::string_view kName = "weather";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.f32(rain_rate_);
        ar.f32(cloud_cover_);
        ar.f32(road_wetness_);
    }

    // One tick of `dt` seconds towards `rain_intensity` (0..1, clamped): step() reads it
    // from the player.
    void advance(float rain_intensity, float dt);

    float rain_rate() const { return rain_rate_; }      // 0..1: what falls now
    float cloud_cover() const { return cloud_cover_; }  // 0 clear .. 1 overcast
    float road_wetness() const { return road_wetness_; }  // 0 dry .. 1 running with water
    // The fraction of the sun's light that gets through the cloud.
    float sunlight() const { return 1.0f - kOvercastSunLoss * cloud_cover_; }

    // The cloud a steady rain of `rain_intensity` settles to, and the wetness of the road.
    static float settled_cloud(float rain_intensity);
    static float settled_wetness(float rain_intensity);

private:
    float rain_rate_ = 0.0f;
    float cloud_cover_ = 0.0f;
    float road_wetness_ = 0.0f;

    // Connected at assembly (connect); nullptr where the world has none.
    const Player* player_ = nullptr;
};

}  // namespace sim
