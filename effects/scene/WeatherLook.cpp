#include "effects/scene/WeatherLook.h"

#include <cmath>


namespace effects {
namespace {

float stepped(float x) { return std::round(x / kWeatherLookStep) * kWeatherLookStep; }

}  // namespace

WeatherLook weather_look(const sim::Weather& weather) {
    WeatherLook look;
    look.overcast = stepped(weather.cloud_cover());
    look.sunlight = stepped(weather.sunlight());
    look.sky_intensity = 1.0f - (1.0f - kOvercastSkyIntensity) * look.overcast;
    look.road_wetness = stepped(weather.road_wetness());
    look.rain_rate = weather.rain_rate();
    return look;
}

WeatherLook weather_look(const sim::World& world) {
    const sim::Weather* weather = world.find<sim::Weather>();
    return weather ? weather_look(*weather) : WeatherLook{};
}

}  // namespace effects
