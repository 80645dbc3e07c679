#pragma once
// How the sim's weather (sim/weather/Weather.h) looks, worked out once a frame: the sun
// and sky every lit pass binds, the road's wetness for the ground, and how much rain the
// streak layer draws. Clear weather when the world has no weather.
#include <glm/vec3.hpp>

#include "sim/weather/Weather.h"
#include "sim/world/World.h"

namespace effects {

struct WeatherLook {
    float overcast = 0.0f;      // 0 clear .. 1 a grey cloud deck (sky.glsl's u_overcast)
    float sunlight = 1.0f;      // the fraction of the clear sun that gets through
    float sky_intensity = 1.0f; // the sky's brightness: cloud is darker than a clear sky
    float road_wetness = 0.0f;  // 0 dry .. 1 running with water (mesh.frag.glsl's u_wetness)
    float rain_rate = 0.0f;     // 0..1: what falls now
    bool operator==(const WeatherLook&) const = default;
};

// Steps of this size only, so that the environment cube, which is rebuilt whenever the
// sky changes, is not rebuilt for changes nobody can see.
inline constexpr float kWeatherLookStep = 1.0f / 64.0f;

// The sky's brightness under full cloud, of a clear sky's.
inline constexpr float kOvercastSkyIntensity = 0.6f;

WeatherLook weather_look(const sim::Weather& weather);
WeatherLook weather_look(const sim::World& world);

}  // namespace effects
