#version 450 core
// The energy wave (specs/energy.md): for each pixel, the field's integral H between
// the eye and the first opaque surface (scene depth, water included), then a smooth
// saturation and a colour ramp, added to the HDR scene. The ray-marching baseline
// samples the same field; the raw mode writes H itself to a float target.
#include "energy/field.glsl"

layout(std430, binding = 2) readonly buffer EnergyTileSegments { uint u_tile_segments[]; };

flat in uvec2 v_list;

uniform sampler2D u_depth;
uniform mat4 u_inv_view_proj;
uniform vec3 u_eye;
uniform vec2 u_viewport;
uniform float u_max_distance_m;  // sky pixels: rays end here
uniform int u_march_samples;     // 0: closed form; N: ray marching with N samples
uniform bool u_raw;              // write H (red) instead of the glow
uniform float u_saturation;      // k of 1 - exp(-k H)
uniform float u_intensity;       // HDR radiance of a saturated pixel
uniform vec3 u_glow_colour;      // the ramp's falloff colour; the core goes white

out vec4 o_colour;

vec3 unproject(vec2 ndc, float z) {
    vec4 p = u_inv_view_proj * vec4(ndc, z, 1.0);
    return p.xyz / p.w;
}

float march(vec3 S, vec3 q, float s_end) {
    // Over the span of the tile's segments' bounding spheres on this ray.
    vec2 span = vec2(s_end, 0.0);
    for (uint i = 0u; i < v_list.y; ++i) {
        vec2 r = segment_reach(u_segments[u_tile_segments[v_list.x + i]], S, q);
        if (r.y > r.x) span = vec2(min(span.x, r.x), max(span.y, r.y));
    }
    span = vec2(max(span.x, 0.0), min(span.y, s_end));
    if (!(span.y > span.x)) return 0.0;
    float ds = (span.y - span.x) / float(u_march_samples);
    float sum = 0.0;
    for (int j = 0; j < u_march_samples; ++j) {
        vec3 P = S + q * (span.x + (float(j) + 0.5) * ds);
        for (uint i = 0u; i < v_list.y; ++i) sum += segment_density(u_segments[u_tile_segments[v_list.x + i]], P);
    }
    return sum * ds;
}

void main() {
    vec2 ndc = gl_FragCoord.xy / u_viewport * 2.0 - 1.0;
    // The depth at this pixel (the bloom draws at a lower resolution than the depth).
    float depth = texelFetch(u_depth, ivec2(gl_FragCoord.xy * vec2(textureSize(u_depth, 0)) / u_viewport), 0).r;
    vec3 S = u_eye;
    vec3 far_point = unproject(ndc, 1.0);
    vec3 q = normalize(far_point - S);
    float s_end = depth < 1.0 ? dot(unproject(ndc, depth * 2.0 - 1.0) - S, q) : u_max_distance_m;
    s_end = clamp(s_end, 0.0, u_max_distance_m);

    float H = 0.0;
    if (u_march_samples > 0) {
        H = march(S, q, s_end);
    } else {
        for (uint i = 0u; i < v_list.y; ++i) {
            EnergySegmentGpu seg = u_segments[u_tile_segments[v_list.x + i]];
            vec2 r = segment_reach(seg, S, q);
            if (r.y > 0.0 && r.x < s_end) H += segment_energy(seg, S, q, s_end);
        }
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
