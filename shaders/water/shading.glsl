// The water look shared by the sea surface and the splash sheets: Fresnel mix of the
// sky's reflection with the sun's glint, and the refracted scene below, absorbed along
// its path through the water. Needs common/sky.glsl and common/lighting.glsl first.
uniform vec3 u_eye;
uniform float u_sea_level;
uniform float u_time_s;
uniform sampler2D u_scene_colour;  // copy of the opaque scene (no water in it)
uniform sampler2D u_scene_depth;
uniform vec2 u_inv_viewport;
uniform mat4 u_inv_view_proj;
uniform float u_absorption;  // scales the per-metre absorption below
uniform float u_refraction;  // screen-space offset per unit of normal tilt
uniform float u_foam;        // 0 = no foam

const vec3 kAbsorbPerMetre = vec3(0.45, 0.12, 0.09);  // red goes first: the sea turns blue-green

vec3 deep_water_colour() { return vec3(0.004, 0.03, 0.045) * u_sky_intensity; }

float water_fresnel(float cos_v) { return 0.02 + 0.98 * pow5(1.0 - clamp(cos_v, 0.0, 1.0)); }

vec3 world_from_depth(vec2 uv, float depth) {
    vec4 p = u_inv_view_proj * vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0);
    return p.xyz / p.w;
}

// The sun's visibility on the water: one bilinear comparison at the point lifted
// along the up normal (the opaque surfaces' 4-tap tent costs 16 comparisons a pixel,
// and on the sea it only shades the glint and the foam).
float water_sun_visibility(vec3 pos) {
    vec2 size = vec2(textureSize(u_shadow_map, 0));
    float texel_m = 1.0 / (size.x * length(vec3(u_shadow_matrix[0][0], u_shadow_matrix[1][0], u_shadow_matrix[2][0])));
    float nl = clamp(u_sun_dir.y, 0.0, 1.0);
    vec4 s = u_shadow_matrix * vec4(pos + vec3(0.0, texel_m * (0.25 + sqrt(1.0 - nl * nl)), 0.0), 1.0);
    vec3 p = s.xyz / s.w;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return 1.0;
    return texture(u_shadow_map, vec3(p.xy, p.z - 0.0015));
}

// Sky in the mirror direction (bent upwards: the sea does not reflect itself) plus the
// sun's highlight; `sun` is the sun's visibility (shadow) there.
vec3 water_reflection(vec3 n, vec3 v, float sun, float roughness) {
    vec3 r = reflect(-v, n);
    r.y = abs(r.y);
    vec3 c = textureLod(u_env, r, 0.0).rgb;
    return c + u_sun_radiance * ggx_specular(n, v, u_sun_dir, roughness) * sun;
}

// White water lit like a rough diffuse surface.
vec3 foam_radiance(vec3 n, float sun) {
    float nl = max(dot(n, u_sun_dir), 0.0);
    vec3 direct = u_sun_radiance * (0.35 + 0.65 * nl) * sun / 3.14159265;
    vec3 ambient = textureLod(u_env, vec3(0, 1, 0), u_env_max_lod).rgb;
    return 0.85 * (direct + ambient);
}

// The energy beams' line lights (common/lighting.glsl) as the sea returns them: the
// part the surface lets in, scattered back out by the water just under it, so the sea
// glows under a passing shot.
const vec3 kWaterScatterAlbedo = vec3(0.12, 0.3, 0.35);
vec3 water_line_light(vec3 pos, vec3 n, float fresnel) {
    return (1.0 - fresnel) * kWaterScatterAlbedo / 3.14159265 * line_light_irradiance(pos, n);
}

// What lies behind the surface at this pixel, seen through it: the scene copy sampled
// a little off by the normal's tilt, its light absorbed over `path` metres of water.
// An offset sample that lies in front of the surface is not refracted.
vec3 water_refraction(vec3 n, vec3 pos, out float path) {
    vec2 uv = gl_FragCoord.xy * u_inv_viewport;
    vec2 refr_uv = clamp(uv + n.xz * u_refraction, vec2(0.001), vec2(0.999));
    float surface_dist = length(pos - u_eye);
    vec3 behind = world_from_depth(refr_uv, texture(u_scene_depth, refr_uv).r);
    if (length(behind - u_eye) < surface_dist) {
        refr_uv = uv;
        behind = world_from_depth(uv, texelFetch(u_scene_depth, ivec2(gl_FragCoord.xy), 0).r);
    }
    path = max(length(behind - u_eye) - surface_dist, 0.0);
    vec3 absorb = exp(-path * kAbsorbPerMetre * u_absorption);
    return mix(deep_water_colour(), texture(u_scene_colour, refr_uv).rgb, absorb);
}
