#version 450 core
#include "common/sky.glsl"
#include "common/lighting.glsl"
#include "water/shading.glsl"
#include "water/waves.glsl"
// Shades each sea pixel once (WaterShading): the geometry step left only its depth;
// the depth test against the water mask leaves only sea pixels. The normal, the crests
// and the wake come from the wave grid's slopes here, once per pixel. Splash sheets
// have their own pass (shade_sheet.frag.glsl): a software rasteriser would run both
// kinds' code for every pixel of one shader.
uniform sampler2D u_depth;  // the scene's depth, water included
uniform float u_shore_foam;
uniform float u_ripples;
uniform float u_pixel_m;    // a pixel's size one metre from the eye
uniform int u_has_grid;
uniform sampler2D u_wave_grid;  // dh/dx, dh/dz, Laplacian, height per grid cell, mipmapped
uniform vec2 u_grid_origin;
uniform float u_grid_spacing;
uniform int u_grid_size;
// White water where splashes fell back (effects/water/SplashFoam): a world-space map of
// u_splash_foam_size_m square from u_splash_foam_origin, 1 where solid foam.
uniform sampler2D u_splash_foam;
uniform vec2 u_splash_foam_origin;
uniform float u_splash_foam_size_m;
uniform float u_splash_foam_amount;
layout(location = 0) out vec4 o_colour;

// Slope (dh/dx, dh/dz) of the wave grid at xz, how much of a breaking crest it is
// (steep, and peaked: negative Laplacian) and how stirred (a wake: slopes and
// curvature far below a crest's, which the mirror alone barely shows from a low
// camera; sharply curved, where a hull is pushing it, churned white). Fades to flat
// over the last cell, where the mesh is held at rest. `lod`: the slopes' mip level.
vec2 grid_slope(vec2 xz, float lod, out float crest, out float stirred) {
    crest = 0.0;
    stirred = 0.0;
    if (u_has_grid == 0) return vec2(0.0);
    float n = float(u_grid_size);
    vec2 cell = (xz - u_grid_origin) / u_grid_spacing;
    float inside = min(min(cell.x, cell.y), min(n - 1.0 - cell.x, n - 1.0 - cell.y));
    if (inside <= 0.0) return vec2(0.0);
    vec3 s = textureLod(u_wave_grid, (cell + 0.5) / n, lod).xyz;
    vec2 slope = s.xy * min(inside, 1.0);
    float steep = length(slope);
    float curved = abs(s.z) * min(inside, 1.0);
    crest = smoothstep(0.25, 0.6, steep) * smoothstep(-0.2, -1.0, s.z) + 0.5 * smoothstep(0.5, 1.0, steep) +
            0.8 * smoothstep(0.09, 0.4, curved);
    stirred = smoothstep(0.006, 0.05, steep + 0.1 * curved);
    return slope;
}

// How much splash foam lies at xz, 0..1.
float splash_foam(vec2 xz) {
    if (u_splash_foam_amount <= 0.0) return 0.0;
    vec2 uv = (xz - u_splash_foam_origin) / u_splash_foam_size_m;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 0.0;
    return clamp(textureLod(u_splash_foam, uv, 0.0).r * u_splash_foam_amount, 0.0, 1.0);
}

vec3 shade_sea(vec3 pos, vec3 n, vec3 v, float sun, float crest, float stirred) {
    float fresnel = water_fresnel(dot(n, v));
    vec3 reflection = water_reflection(n, v, sun, 0.08);
    float path;
    vec3 refraction = water_refraction(n, pos, path);
    vec3 c = mix(refraction, reflection, fresnel) + water_line_light(pos, n, fresnel);
    // Stirred water (a wake) is full of fine bubbles: it sends light back paler and
    // greener than the clear sea beside it, so the wake's wedge shows from any height.
    // Where a splash fell back the water is full of bubbles too, under and around its foam.
    float splash = splash_foam(pos.xz);
    c = mix(c, foam_radiance(n, sun) * kWaterScatterAlbedo * 1.6, 0.45 * max(stirred, min(1.0, 1.5 * splash)));
    // Foam on crests and in shallow water, broken up by noise that drifts slowly so it
    // reads as patches, not paint. Most of the sea has none: skip the noise there.
    // Splash foam is solid white where fresh and thick; as it thins it breaks into lace
    // (only the noise's peaks stay white).
    float shallow = u_shore_foam * (1.0 - smoothstep(0.05, 0.35, path));
    if (crest * u_foam + shallow + splash > 0.0) {
        float breakup = foam_noise(pos.xz * 2.3 + u_time_s * 0.15) * 0.6 + foam_noise(pos.xz * 7.1) * 0.4;
        float lace = foam_noise(pos.xz * 4.7) * 0.55 + foam_noise(pos.xz * 13.0) * 0.45;
        float foam = u_foam * crest * smoothstep(0.35, 0.8, breakup) + shallow * smoothstep(0.25, 0.6, breakup) +
                     smoothstep(1.05 - splash, 1.2 - splash, lace);
        c = mix(c, foam_radiance(n, sun), clamp(foam, 0.0, 1.0));
    }
    return c;
}

void main() {
    vec3 pos = world_from_depth(gl_FragCoord.xy * u_inv_viewport, texelFetch(u_depth, ivec2(gl_FragCoord.xy), 0).r);
    vec3 to_eye = u_eye - pos;
    float dist = length(to_eye);
    vec3 v = to_eye / dist;
    // The slopes' level for the pixel's footprint on the surface: a pixel spans dist *
    // pixel_m across the view, and that over the grazing angle's sine along it (what
    // the derivatives gave when the lattice was shaded; a full-screen pass's own
    // derivatives jump at every silhouette).
    float lod = log2(max(dist * u_pixel_m / (max(abs(v.y), 1e-3) * u_grid_spacing), 1e-6));
    float crest, stirred;
    vec2 slope = grid_slope(pos.xz, lod, crest, stirred) + ripple_slope(pos.xz, u_time_s, dist) * u_ripples;
    vec3 n = normalize(vec3(-slope.x, 1.0, -slope.y));
    vec3 c = shade_sea(pos, n, v, water_sun_visibility(pos), clamp(crest, 0.0, 1.0), stirred);
    o_colour = vec4(apply_fog(c, pos, u_eye), 1.0);
}
