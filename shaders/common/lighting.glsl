// Sun with a shadow map, sky ambient and environment reflection: the base lighting
// every opaque surface gets.
uniform sampler2DShadow u_shadow_map;
uniform mat4 u_shadow_matrix;  // world -> shadow texture coordinates and depth
uniform samplerCube u_env;
uniform float u_env_max_lod;
uniform sampler2DShadow u_sky_map;  // the props' top-down depth (SkyOcclusionPass)
uniform mat4 u_sky_matrix;          // world -> its texture coordinates and depth

// Line lights (SceneLighting::set_line_lights): the energy weapon's beams light the
// surfaces near them. Ends, reach, radiant intensity per metre and colour.
const int kMaxLineLights = 16;
layout(std140, binding = 3) uniform LineLights {
    ivec4 u_line_light_count;                   // x
    vec4 u_line_light_start[kMaxLineLights];    // xyz, reach_m
    vec4 u_line_light_end[kMaxLineLights];      // xyz, intensity per metre
    vec4 u_line_light_colour[kMaxLineLights];   // rgb
};

// Irradiance at p (normal n) from the line lights: a few samples of each segment's
// Lambertian emission, fading to zero at its reach.
vec3 line_light_irradiance(vec3 p, vec3 n) {
    vec3 sum = vec3(0.0);
#if !defined(LINE_LIGHTS) || LINE_LIGHTS == 1  // 0: a frame without any (LitProgram)
    for (int i = 0; i < min(u_line_light_count.x, kMaxLineLights); ++i) {
        vec3 a = u_line_light_start[i].xyz, b = u_line_light_end[i].xyz;
        float reach = u_line_light_start[i].w;
        vec3 ab = b - a;
        float len2 = dot(ab, ab);
        float f = len2 > 1e-8 ? clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
        if (distance(p, a + f * ab) > reach) continue;
        const int kSamples = 6;
        float e = 0.0;
        for (int k = 0; k < kSamples; ++k) {
            vec3 l = a + ab * ((float(k) + 0.5) / float(kSamples)) - p;
            float r2 = dot(l, l);
            float fade = 1.0 - smoothstep(0.5 * reach, reach, sqrt(r2));
            e += max(dot(n, l), 0.0) * inversesqrt(r2) / (r2 + 0.25) * fade;
        }
        sum += u_line_light_colour[i].rgb * (u_line_light_end[i].w * sqrt(len2) / float(kSamples) * e);
    }
#endif
    return sum;
}

// The bias is all on the receiver (ShadowPass draws without a polygon offset): the
// point is looked up lifted along its normal by a quarter of a map texel plus one times
// the sine of the sun's angle to the normal (normal offset: a slope-scaled bias that
// cannot overshoot, so a lit slope under a low sun does not shadow itself), and its depth
// brought 0.6 m towards the sun, which the car's smooth-shaded hood needs in the
// driver's view (with less it streaks).
float sun_visibility(vec3 world_pos, vec3 n) {
    vec2 size = vec2(textureSize(u_shadow_map, 0));
    float texel_m = 1.0 / (size.x * length(vec3(u_shadow_matrix[0][0], u_shadow_matrix[1][0], u_shadow_matrix[2][0])));
    float nl = clamp(dot(n, u_sun_dir), 0.0, 1.0);
    vec4 s = u_shadow_matrix * vec4(world_pos + n * (texel_m * (0.25 + 1.0 * sqrt(1.0 - nl * nl))), 1.0);
    vec3 p = s.xyz / s.w;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return 1.0;
    float depth = p.z - 0.0015;
#if defined(SOFT_SHADOWS) && SOFT_SHADOWS == 0
    // A cheaper preset's: one bilinear comparison.
    return texture(u_shadow_map, vec3(p.xy, depth));
#else
    // A 3x3 box of bilinear comparisons, a tent over 4x4 texels, in four taps (Castano,
    // "Shadow Mapping Summary", 2013). Along x the box weighs the texels from floor(u)-1
    // to floor(u)+2 by (1-f, 1, 1, f) / 3 (f the fraction past a texel centre); tap a
    // takes the first two in the ratio 1-f : 1, tap b the last two as 1 : f, each tap
    // placed so that its own bilinear weights are that ratio.
    vec2 u = p.xy * size - 0.5;
    vec2 base = floor(u), f = u - base;
    vec2 wa = 2.0 - f, wb = 1.0 + f;                           // each tap's weight, of 3
    vec2 ua = (base - 0.5 + 1.0 / wa) / size, ub = (base + 1.5 + f / wb) / size;
    float sum = wa.x * wa.y * texture(u_shadow_map, vec3(ua.x, ua.y, depth)) +
                wb.x * wa.y * texture(u_shadow_map, vec3(ub.x, ua.y, depth)) +
                wa.x * wb.y * texture(u_shadow_map, vec3(ua.x, ub.y, depth)) +
                wb.x * wb.y * texture(u_shadow_map, vec3(ub.x, ub.y, depth));
    return sum / 9.0;
#endif
}

// How much of the sky p sees: 0 under a roof, 1 in the open, soft across a texel (the
// map filters its comparisons). Lifted off the surface so a roof sees past itself.
float sky_visibility(vec3 world_pos, vec3 n) {
    vec4 s = u_sky_matrix * vec4(world_pos + n * 0.1, 1.0);
    vec3 p = s.xyz / s.w;
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0)))) return 1.0;
    return texture(u_sky_map, vec3(p.xy, p.z - 0.002));
}

// Under a roof the ambient light is what the walls and floor pass on: a grey fraction of
// the sky's, not its blue.
const float kIndoorAmbient = 0.5;

vec3 fresnel_schlick(float cos_theta, vec3 f0) {
    return f0 + (1.0 - f0) * pow5(1.0 - clamp(cos_theta, 0.0, 1.0));
}

// GGX normal distribution with Smith-Schlick visibility, for the sun's highlight.
float ggx_specular(vec3 n, vec3 v, vec3 l, float roughness) {
    vec3 h = normalize(v + l);
    float a = max(roughness * roughness, 0.002);
    float a2 = a * a;
    float nh = max(dot(n, h), 0.0), nv = max(dot(n, v), 1e-3), nl = max(dot(n, l), 0.0);
    float d = nh * nh * (a2 - 1.0) + 1.0;
    float k = a * 0.5;
    float vis = 1.0 / ((nv * (1.0 - k) + k) * (nl * (1.0 - k) + k));
    return a2 / (3.14159265 * d * d) * vis * 0.25;
}

// Pre-integrated environment BRDF, analytic fit (Karis, "Physically Based Shading on
// Mobile", 2014): how much of the blurred environment a rough surface reflects.
vec3 env_brdf(vec3 f0, float roughness, float nv) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * nv)) * r.x + r.y;
    vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
    return f0 * ab.x + ab.y;
}

// Lit by the sun, the line lights and the sky as far as the surface sees it (sky: 0..1).
vec3 shade_surface_seeing_sky(vec3 base, float roughness, float metallic, vec3 world_pos, vec3 n, vec3 eye, float sky) {
    vec3 v = normalize(eye - world_pos);
    vec3 l = u_sun_dir;
    float nl = max(dot(n, l), 0.0);
    float shadow = nl > 0.0 ? sun_visibility(world_pos, n) : 0.0;
    vec3 f0 = mix(vec3(0.04), base, metallic);
    vec3 diffuse_colour = base * (1.0 - metallic);
    vec3 f = fresnel_schlick(max(dot(n, v), 0.0), f0);
    vec3 direct = (diffuse_colour / 3.14159265 * (1.0 - f) + f * ggx_specular(n, v, l, roughness)) * u_sun_radiance * nl * shadow;
    direct += diffuse_colour / 3.14159265 * line_light_irradiance(world_pos, n);
    vec3 sky_light = textureLod(u_env, n, u_env_max_lod).rgb;
    vec3 indoor = vec3(dot(sky_light, vec3(0.2126, 0.7152, 0.0722)) * kIndoorAmbient);
    vec3 ambient = mix(indoor, sky_light, sky) * diffuse_colour * (0.6 + 0.4 * n.y);
    // ENV_REFLECTION 0 (a cheaper preset's): the sky's ambient light stands in for the
    // reflected environment, one cube lookup a pixel instead of two (a trilinear one).
#if defined(ENV_REFLECTION) && ENV_REFLECTION == 0
    vec3 reflected = sky_light;
#else
    vec3 reflected = textureLod(u_env, reflect(-v, n), roughness * u_env_max_lod).rgb;
#endif
    vec3 spec_env = reflected * env_brdf(f0, roughness, max(dot(n, v), 1e-3)) * mix(kIndoorAmbient, 1.0, sky);
    return direct + ambient + spec_env;
}

vec3 shade_surface(vec3 base, float roughness, float metallic, vec3 world_pos, vec3 n, vec3 eye) {
#if defined(OPEN_SKY) && OPEN_SKY == 1
    // Ground the sky map has nothing above (GpuTerrain's open tiles): its lookup would
    // answer exactly 1, and it costs a tenth of the opaque pass on llvmpipe.
    return shade_surface_seeing_sky(base, roughness, metallic, world_pos, n, eye, 1.0);
#else
    return shade_surface_seeing_sky(base, roughness, metallic, world_pos, n, eye, sky_visibility(world_pos, n));
#endif
}

// Aerial perspective: distant things fade into the sky's horizon colour.
vec3 apply_fog(vec3 colour, vec3 world_pos, vec3 eye) {
    vec3 d = world_pos - eye;
    float dist = length(d);
    float fog = 1.0 - exp(-dist * 0.0012);
    return mix(colour, sky_radiance(d / max(dist, 1e-4), false), fog);
}
