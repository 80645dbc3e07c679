// Analytic sky shared by the background, the environment cube and the fog: a blue
// gradient that pales to the horizon, a warm glow around the sun and the sun's disk;
// under cloud (the sim's weather, effects/scene/WeatherLook.h) a grey deck, brighter
// overhead than at the horizon, that hides the glow and the disk.
uniform vec3 u_sun_dir;       // towards the sun, normalised
uniform vec3 u_sun_radiance;  // what the sun adds to a lit surface
uniform float u_sky_intensity;
uniform float u_overcast;     // 0 clear .. 1 overcast

// Whole powers by multiplication: pow() is a log and an exponential on a software
// rasteriser, and these run for nearly every pixel (sky, fog, reflections).
float pow5(float x) {
    float x2 = x * x;
    return x2 * x2 * x;
}

vec3 sky_radiance(vec3 dir, bool with_sun_disk) {
    dir = normalize(dir);
    float y = dir.y;
    vec3 zenith = vec3(0.09, 0.22, 0.55);
    vec3 horizon = vec3(0.52, 0.66, 0.85);
    vec3 ground = vec3(0.16, 0.17, 0.18);
    float t = pow5(1.0 - clamp(y, 0.0, 1.0));
    vec3 sky = mix(zenith, horizon, t);
    // The cloud deck: an overcast sky is about twice as bright overhead as at the horizon.
    vec3 cloud = vec3(0.50, 0.52, 0.55) * (0.55 + 0.45 * clamp(y, 0.0, 1.0));
    sky = mix(sky, cloud, u_overcast);
    if (y < 0.0) sky = mix(mix(horizon, cloud, u_overcast), ground, clamp(-y * 6.0, 0.0, 1.0));
    float mu = max(dot(dir, u_sun_dir), 0.0);
    float mu2 = mu * mu, mu8 = mu2 * mu2 * mu2 * mu2, mu16 = mu8 * mu8, mu64 = mu16 * mu16 * mu16 * mu16;
    float clear = 1.0 - u_overcast;
    vec3 glow = vec3(1.0, 0.82, 0.58) * (0.22 * mu2 * mu2 * mu2 + 0.7 * mu64 * mu16 * mu8 * mu2) * clear;
    vec3 result = (sky + glow) * u_sky_intensity;
    if (with_sun_disk) result += smoothstep(0.99965, 0.99985, mu) * u_sun_radiance * (25.0 * clear * clear);
    return result;
}
