#version 450 core
#include "common/sky.glsl"
#include "rain/drop_shape.glsl"
// Rain on the windshield seen from the driver's seat (seed 5.4, docs/effects/rain.md).
// A drop is a small lens: its lookup into the scene behind moves against its tilt by
// more than its own size, so it holds the scene flipped and shrunk (the road in its
// upper half, the sky and roof lining in its lower). It reflects the sky by Schlick's
// Fresnel term and glints where its surface sends the sun to the eye. Its outline is
// antialiased from the height field; the streak a runner leaves is a faint film that
// blurs and brightens the view and dries. Plain glass is left as it is. The wiper
// blades are drawn on top.
uniform sampler2D u_sums;      // the drops' splatted sums (DropHeightMap), bilinear
uniform vec2 u_map_texel;      // one texel of the sums' map, in texture coordinates
uniform vec2 u_texel_mm;       // and in glass millimetres
uniform sampler2D u_behind;    // the finished scene, with mips
uniform sampler2D u_film_map;  // per glass cell: 1 where a drop just ran, 0 dry
uniform vec2 u_glass_size_m;
uniform vec2 u_film_scale;     // glass metres to film map coordinates
uniform vec3 u_eye;
uniform vec2 u_inv_viewport;
uniform float u_aspect;
uniform float u_refraction;    // screen heights the lookup moves per unit of tilt...
uniform float u_reach;         // ...but at most this many of the drop's radii
uniform float u_blur_bias;     // mips: the eye is focused on the road, not the glass
uniform float u_scene_lod;     // log2 of the scene's pixels per output pixel: the blurs are sized in output pixels
uniform float u_glint;         // the sun's highlight, times its radiance
uniform float u_film;          // the wet streaks' strength
// Two blades, always: a missing one has an empty span. (A loop to a uniform count
// would read these arrays at a varying index, lane by lane on a software rasteriser.)
uniform vec2 u_blade_pivot[2];
uniform vec2 u_blade_dir[2];
uniform vec2 u_blade_span[2];  // inner, outer radius of the rubber
in vec3 v_world;
in vec2 v_uv_m;
in vec3 v_tangent_u, v_tangent_v;
flat in vec3 v_sky_overhead;  // sky_radiance straight up
layout(location = 0) out vec4 o_colour;

uniform float u_blade_half_width_m;  // RainPass's: the cells it shades reach this far
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
            cover = max(cover, 1.0 - smoothstep(u_blade_half_width_m - aa, u_blade_half_width_m + aa, across));
        if (along > 0.0 && along < u_blade_span[b].y * 0.97)
            arm = max(arm, 1.0 - smoothstep(kArmHalfWidth_m - aa, kArmHalfWidth_m + aa, across));
    }
    return max(cover, arm);
}

void main() {
    float arm;
    float blade = blades(v_uv_m, arm);
    // The drops' surface here (drop_shape.glsl): the height from the sums filtered at
    // the pixel, the normal from them one map texel further along u and v.
    vec2 uv = v_uv_m / u_glass_size_m;
    vec4 s = drop_surface(texture(u_sums, uv), texture(u_sums, uv + vec2(u_map_texel.x, 0.0)),
                          texture(u_sums, uv + vec2(0.0, u_map_texel.y)), u_texel_mm);
    // Coverage from the height field: the outline where the (bilinear) height leaves 0,
    // spread over one pixel's change of height, so edges are antialiased at any scale.
    float cover = clamp(s.b / max(fwidth(s.b), 1e-3), 0.0, 1.0);
    float film = texture(u_film_map, v_uv_m * u_film_scale).r * u_film;
    // Glass metres per pixel, x and y: its adjugate turns a tilt on the glass into a
    // direction on the screen (the sign of the determinant keeps it from flipping).
    vec2 gx = dFdx(v_uv_m), gy = dFdy(v_uv_m);
    float det = gx.x * gy.y - gy.x * gx.y;

    // The tilt (0 on dry glass), at most 1.
    vec2 tilt = s.rg;
    float t2 = min(dot(tilt, tilt), 1.0);
    tilt *= inversesqrt(max(dot(tilt, tilt), 1e-8)) * sqrt(t2);
    vec2 dir_px = sign(det) * vec2(gy.y * tilt.x - gy.x * tilt.y, -gx.y * tilt.x + gx.x * tilt.y);
    float dir_len2 = dot(dir_px, dir_px);
    // How far the lookup moves at full tilt: u_refraction of the screen's height, but
    // at most u_reach of the drop's radius on screen (h / nz for a spherical cap, over
    // the glass's millimetres per pixel): still past its edge, so the image flips, but
    // a drop a few pixels wide holds what is near it, not the bonnet far below.
    float radius_px = s.b / max(sqrt(1.0 - t2), 0.3) / (1000.0 * sqrt(abs(det)) + 1e-6);
    float reach = min(u_refraction, u_reach * radius_px * u_inv_viewport.y);
    vec2 shift = dir_len2 > 0.0 ? -dir_px * inversesqrt(dir_len2) * sqrt(t2) * reach * vec2(1.0 / u_aspect, 1.0) : vec2(0.0);
    vec2 look = gl_FragCoord.xy * u_inv_viewport + shift;
    // The mip for the image's own shrinking (the lookup's footprint, in the scene's
    // pixels), plus the focus blur; the film alone blurs by two mips. The blurs are the
    // eye's, a size on the screen: drawn smaller than the output (auto), they are as
    // many fewer of the scene's mips.
    vec2 lx = dFdx(look) / u_inv_viewport, ly = dFdy(look) / u_inv_viewport;
    float lod = 0.5 * log2(max(max(dot(lx, lx), dot(ly, ly)), 1.0)) + u_blur_bias + u_scene_lod;
    lod = max(lod, 2.0 * (1.0 - cover) + u_scene_lod);
    if (cover <= 0.0 && film <= 0.004 && blade <= 0.0) discard;

    vec3 behind = textureLod(u_behind, look, lod).rgb;
    vec3 glass_n = normalize(cross(v_tangent_u, v_tangent_v));
    vec3 view = normalize(v_world - u_eye);
    if (dot(glass_n, view) > 0.0) glass_n = -glass_n;  // towards the eye
    vec3 n = normalize(v_tangent_u * tilt.x + v_tangent_v * tilt.y + glass_n * sqrt(1.0 - t2));
    // What the drop's surface reflects, mirrored out through the glass: the drops sit
    // outside, under the sky, whatever side of them the eye is on. Never below the
    // horizon: a drop's rim reflecting the road would outline it in dark, like dirt.
    vec3 r = reflect(view, n);
    r -= 2.0 * dot(r, glass_n) * glass_n;
    r.y = max(r.y, 0.0);
    float cos_v = clamp(dot(-view, n), 0.0, 1.0);
    float fresnel = 0.02 + 0.98 * pow5(1.0 - cos_v);
    float mu = max(dot(r, u_sun_dir), 0.0);
    float mu2 = mu * mu, mu4 = mu2 * mu2, mu8 = mu4 * mu4, mu32 = mu8 * mu8 * mu8 * mu8;
    float up = max(r.y, 0.0), up2 = up * up, up8 = up2 * up2 * up2 * up2;
    // The sun's glint (a lobe wide enough to cover pixels of a small drop) and the
    // bright sky above on the drop's upper side.
    vec3 glint = u_sun_radiance * (u_glint * mu32) + v_sky_overhead * (0.5 * up8);
    vec3 sky = sky_radiance(r, false);
    vec3 drop = mix(behind, sky, fresnel) + glint;
    // The film: the same view, blurred, with a sheen of the sky.
    vec3 wet = mix(behind, sky, 0.2);

    float alpha = max(cover, film);
    vec3 colour = alpha > 0.0 ? mix(wet, drop, cover / alpha) : vec3(0.0);
    // Rubber nearly black; the arm a little lighter (painted metal catching the sky).
    vec3 blade_colour = mix(vec3(0.008), vec3(0.03), arm);
    colour = mix(colour, blade_colour, blade);
    o_colour = vec4(colour, max(alpha, blade));
}
