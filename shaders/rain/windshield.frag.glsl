#version 450 core
#include "common/sky.glsl"
// Rain on the windshield seen from the driver's seat (seed 5.4): where the height map
// has water, the scene behind is looked up shifted by the drop's normal (a drop is a
// small lens: its image is flipped) and out of focus, and mixed with the sky it
// reflects by Schlick's Fresnel term. Thin edges blend into plain glass, which is left
// as it is. The wiper blades are drawn on top.
uniform sampler2D u_surface;  // rg normal u, v; b height mm; a water
uniform sampler2D u_behind;   // the finished scene, with mips
uniform vec2 u_glass_size_m;
uniform vec3 u_eye;
uniform vec2 u_inv_viewport;
uniform float u_aspect;
uniform float u_refraction;
uniform float u_blur_lod;  // mip of the scene behind a drop one metre from the eye
uniform float u_rim;
// Two blades, always: a missing one has an empty span. (A loop to a uniform count
// would read these arrays at a varying index, lane by lane on a software rasteriser.)
uniform vec2 u_blade_pivot[2];
uniform vec2 u_blade_dir[2];
uniform vec2 u_blade_span[2];  // inner, outer radius of the rubber
in vec3 v_world;
in vec2 v_uv_m;
in vec3 v_tangent_u, v_tangent_v;
layout(location = 0) out vec4 o_colour;

const float kBladeHalfWidth_m = 0.008;
const float kArmHalfWidth_m = 0.005;

// Coverage of the blades and their arms at this point of the glass (0..1, antialiased).
float blades(vec2 p, out float arm) {
    float cover = 0.0;
    arm = 0.0;
    float aa = max(fwidth(p.x), fwidth(p.y));
    for (int b = 0; b < 2; ++b) {
        vec2 rel = p - u_blade_pivot[b];
        float along = dot(rel, u_blade_dir[b]);
        float across = abs(rel.x * u_blade_dir[b].y - rel.y * u_blade_dir[b].x);
        if (along > u_blade_span[b].x && along < u_blade_span[b].y)
            cover = max(cover, 1.0 - smoothstep(kBladeHalfWidth_m - aa, kBladeHalfWidth_m + aa, across));
        if (along > 0.0 && along < u_blade_span[b].y * 0.97)
            arm = max(arm, 1.0 - smoothstep(kArmHalfWidth_m - aa, kArmHalfWidth_m + aa, across));
    }
    return max(cover, arm);
}

void main() {
    float arm;
    float blade = blades(v_uv_m, arm);
    vec4 s = texture(u_surface, v_uv_m / u_glass_size_m);
    float water = smoothstep(0.0, 0.25, s.b) * s.a;
    if (water <= 0.0 && blade <= 0.0) discard;

    vec3 colour = vec3(0.0);
    if (water > 0.0) {
        vec2 tilt = s.rg;
        float nz = sqrt(max(1.0 - dot(tilt, tilt), 0.0));
        vec3 glass_n = normalize(cross(v_tangent_u, v_tangent_v));
        vec3 view = normalize(v_world - u_eye);
        if (dot(glass_n, view) > 0.0) glass_n = -glass_n;  // towards the eye
        vec3 n = normalize(v_tangent_u * tilt.x + v_tangent_v * tilt.y + glass_n * nz);

        vec2 screen = gl_FragCoord.xy * u_inv_viewport;
        vec2 shift = -tilt * u_refraction * vec2(1.0 / u_aspect, 1.0);
        // The eye is focused on the road: the glass, and the image a drop makes of what
        // lies behind it, is out of focus by a blur circle growing as 1 / distance.
        float lod = u_blur_lod + log2(1.0 / max(length(v_world - u_eye), 0.3));
        vec3 behind = textureLod(u_behind, screen + shift, max(lod, 0.0)).rgb;
        behind *= mix(1.0 - u_rim, 1.0, pow(nz, 3.0));  // light leaving a steep edge is bent away

        vec3 r = reflect(view, n);
        vec3 sky = sky_radiance(r, false) + u_sun_radiance * 4.0 * pow(max(dot(r, u_sun_dir), 0.0), 300.0);
        float cos_v = clamp(dot(-view, n), 0.0, 1.0);
        float fresnel = 0.02 + 0.98 * pow5(1.0 - cos_v);
        colour = mix(behind, sky, fresnel);
    }
    // Rubber nearly black; the arm a little lighter (painted metal catching the sky).
    vec3 blade_colour = mix(vec3(0.008), vec3(0.03), arm);
    colour = mix(colour, blade_colour, blade);
    o_colour = vec4(colour, max(water, blade));
}
