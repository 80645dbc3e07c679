#version 450 core
// The energy wave (docs/effects/energy.md): for each pixel, the field's integral H between
// the eye and the first opaque surface (scene depth, water included), then a smooth
// saturation and a colour ramp, added to the HDR scene. The ray-marching baseline
// samples the same field; the raw mode writes H itself to a float target.
#include "energy/field.glsl"

layout(std430, binding = 2) readonly buffer EnergyTileSegments { uint u_tile_segments[]; };

flat in uvec2 v_list;

uniform sampler2D u_depth;
uniform vec2 u_depth_scale;      // depth texels per pixel (the bloom draws at a lower resolution)
// The view ray through a pixel, unnormalised and affine in the pixel's position
// (EnergyPass works it out from the camera).
uniform vec3 u_ray_origin, u_ray_dx, u_ray_dy;
uniform vec3 u_forward;          // the camera's view direction
uniform vec2 u_depth_to_view;    // view depth = x / (ndc z + y)
uniform float u_max_distance_m;  // sky pixels: rays end here
uniform int u_march_samples;     // 0: closed form; N: ray marching with N samples
uniform bool u_raw;              // write H (red) instead of the glow
uniform float u_saturation;      // k of 1 - exp(-k H)
uniform float u_intensity;       // HDR radiance of a saturated pixel
uniform vec3 u_glow_colour;      // the ramp's falloff colour; the core goes white

out vec4 o_colour;

float march(vec3 q, float s_end) {
    // Over the span of the tile's segments' bounding spheres on this ray.
    vec2 span = vec2(s_end, 0.0);
    for (uint i = 0u; i < v_list.y; ++i) {
        vec2 r = segment_reach(u_segments[u_tile_segments[v_list.x + i]], q);
        if (r.y > r.x) span = vec2(min(span.x, r.x), max(span.y, r.y));
    }
    span = vec2(max(span.x, 0.0), min(span.y, s_end));
    if (!(span.y > span.x)) return 0.0;
    float ds = (span.y - span.x) / float(u_march_samples);
    float sum = 0.0;
    for (int j = 0; j < u_march_samples; ++j) {
        float s = span.x + (float(j) + 0.5) * ds;
        for (uint i = 0u; i < v_list.y; ++i) sum += segment_density(u_segments[u_tile_segments[v_list.x + i]], q, s);
    }
    return sum * ds;
}

void main() {
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy * u_depth_scale), 0).r;
    vec3 q = normalize(u_ray_origin + gl_FragCoord.x * u_ray_dx + gl_FragCoord.y * u_ray_dy);
    // The distance along the ray to the depth's point: its view depth over the ray's cosine.
    float s_end = depth < 1.0 ? u_depth_to_view.x / (depth * 2.0 - 1.0 + u_depth_to_view.y) / dot(q, u_forward)
                              : u_max_distance_m;
    s_end = clamp(s_end, 0.0, u_max_distance_m);

    float H = 0.0;
    if (u_march_samples > 0) {
        H = march(q, s_end);
    } else {
        for (uint i = 0u; i < v_list.y; ++i) H += segment_energy(u_segments[u_tile_segments[v_list.x + i]], q, s_end);
    }
    if (u_raw) {
        o_colour = vec4(H, s_end, 0.0, 1.0);
        return;
    }
    // Smooth saturation instead of the seed's clamp. The falloff stays the glow colour
    // and only the nearly saturated core goes white: a beam seen from the side is blue
    // around a thin white line, a ball or a beam seen end-on is white in the middle.
    float glow = 1.0 - exp(-u_saturation * H);
    vec3 colour = mix(u_glow_colour, vec3(1.0), smoothstep(0.7, 1.0, glow));
    o_colour = vec4(colour * u_intensity * glow, 0.0);
}
