#version 450 core
// Dust shells and fins (seed §2-3): keep a texel where the fibre layer at this height
// has a fibre whose rank the local amount admits, and where the noise luminance says
// the dust reaches this high (the clipping that makes the dust surface bumpy).
// Lower layers are darker: the fibres above shade them.
in vec3 v_base_pos;
in vec3 v_normal;
in float v_amount;
in float v_height;
in vec2 v_fin_uv;
in float v_fin_fade;
in vec3 v_light;
in vec4 v_fog;

uniform sampler2DArray u_fibres;  // r: fibre coverage, g: fibre rank
uniform sampler2D u_luminance;
uniform int u_layers;
uniform float u_tile_m;
uniform float u_bumpiness;
uniform float u_threshold;
uniform vec3 u_colour;
uniform vec3 u_deep_colour;
uniform bool u_fin;

layout(location = 0) out vec4 o_colour;
layout(location = 1) out vec4 o_normal;

// Fibre texture coordinates on the plane the normal faces most (boxy props).
vec2 surface_uv(vec3 p, vec3 n) {
    vec3 a = abs(n);
    if (a.y >= a.x && a.y >= a.z) return p.xz / u_tile_m;
    return (a.x >= a.z ? p.zy : p.xy) / u_tile_m;
}

void main() {
    // Thin dust stays thin: little shows below a tenth of the full amount.
    float amount = smoothstep(0.08, 0.85, v_amount);
    if (amount <= 0.01) discard;
    vec3 n = normalize(v_normal);
    vec2 uv = u_fin ? v_fin_uv : surface_uv(v_base_pos, n);
    float lum = texture(u_luminance, surface_uv(v_base_pos, n) * 0.35).r;
    // How high the dust reaches here, as a fraction of the stack.
    float reach = clamp(amount * 1.3, 0.0, 1.0) * mix(1.0, 2.0 * lum, u_bumpiness);
    if (v_height > reach) discard;
    float coverage = clamp(amount * 1.6, 0.0, 1.0);
    float tone = v_height;
    if (v_height == 0.0 && !u_fin) {
        // The film: the dense bottom of the deposit, patchy where it is thin.
        if (coverage * (0.6 + 0.8 * lum) < 0.5) discard;
        tone = 0.45;
    } else {
        float layer = v_height * float(u_layers - 1);
        vec2 f0 = texture(u_fibres, vec3(uv, floor(layer))).rg;
        vec2 f1 = texture(u_fibres, vec3(uv, min(floor(layer) + 1.0, float(u_layers - 1)))).rg;
        vec2 f = mix(f0, f1, fract(layer));
        if (f.r * v_fin_fade < u_threshold || f.g > coverage) discard;
    }
    vec3 albedo = mix(u_deep_colour, u_colour, tone);
    vec3 c = albedo * v_light;
    o_colour = vec4(mix(c, v_fog.rgb, v_fog.a), 1.0);
    o_normal = vec4(n, 1.0);
}
