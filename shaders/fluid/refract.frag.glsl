#version 450 core
#include "common/sky.glsl"
#include "fluid/common.glsl"
// Refraction through the liquid body's two surfaces (seed 4.4; the splash is a soft
// layer drawn over this, splash_layer.frag.glsl). At each surface a Schlick-Fresnel
// share is reflected (the background along the mirrored ray) and the rest refracted
// (Snell) and traced to the next surface with the secant method; the path inside the
// liquid is absorbed (Beer-Lambert). What leaves the back surface sees the scene behind
// (u_background: the frame's scene copy, its colour refreshed around the tank, water
// included), or the sky off screen. Then the tank's glass: a faint reflection and its
// steel edges.
uniform sampler2D u_body_front, u_body_back;
uniform sampler2D u_body_front_normal, u_body_back_normal;
uniform sampler2D u_background;   // the scene's colour before the fluid
uniform sampler2D u_scene_depth;  // window depth
uniform ivec4 u_background_rect;  // where u_background holds the scene
uniform mat3 u_view_to_world;
uniform mat4 u_view_to_tank;
uniform vec3 u_tank_size;
uniform vec3 u_absorption;        // a * C_a per view unit (metre)
uniform float u_ior;
uniform float u_epsilon;          // secant convergence, view units
uniform float u_frame_width;      // the glass tank's steel edges
uniform int u_probe;              // 1: write the exit ray of the body's two surfaces instead
layout(location = 0) out vec4 o_colour;

float scene_distance(vec2 px) {
    ivec2 p = clamp(ivec2(px), ivec2(0), ivec2(u_viewport) - 1);
    float ndc = texelFetch(u_scene_depth, p, 0).r * 2.0 - 1.0;
    return u_proj[3][2] / (ndc + u_proj[2][2]);
}

vec3 sky(vec3 view_dir) { return sky_radiance(u_view_to_world * view_dir, false); }

// What a ray from p along d sees behind the liquid: the scene where the ray reaches
// the scene's depth (one step estimate), or the sky. A ray turned back towards the eye
// would find what lies in front of the tank on screen (the car's hood), and one landing
// outside the copied rectangle would smear its edge: both see the sky instead.
vec3 background(vec3 p, vec3 d) {
    if (d.z >= 0.0) return sky(d);
    float ahead = max(scene_distance(project_to_pixel(p)) + p.z, 0.0);
    float s = min(ahead / -d.z, 40.0);
    vec3 q = p + d * s;
    if (q.z > -0.05) return sky(d);
    vec2 px = project_to_pixel(q);
    if (any(lessThan(px, vec2(u_background_rect.xy))) || any(greaterThanEqual(px, vec2(u_background_rect.zw))))
        return sky(d);
    // A steep ray can land on what stands in front of the liquid (the hood again): the
    // scene straight behind the point is the better guess then.
    if (scene_distance(px) < -p.z)
        px = clamp(project_to_pixel(p), vec2(u_background_rect.xy), vec2(u_background_rect.zw - 1));
    return texelFetch(u_background, ivec2(px), 0).rgb;
}

// Surfaces: 0 the body's front, 1 its back (samplers cannot be chosen with ?:, so a
// branch picks them).
const int kBodyFront = 0, kBodyBack = 1;

float depth_of(int surface, ivec2 p) {
    if (surface == kBodyFront) return texelFetch(u_body_front, p, 0).r;
    return texelFetch(u_body_back, p, 0).r;
}

vec3 normal_of(int surface, ivec2 p) {
    if (surface == kBodyFront) return texelFetch(u_body_front_normal, p, 0).xyz;
    return texelFetch(u_body_back_normal, p, 0).xyz;
}

float map_at(int surface, vec3 p, out bool valid) {
    vec2 px = project_to_pixel(p);
    valid = all(greaterThanEqual(px, vec2(u_rect.xy))) && all(lessThan(px, vec2(u_rect.zw)));
    float z = depth_of(surface, clamp_to_rect(ivec2(px)));
    valid = valid && has_depth(z);
    return z;
}

// Secant search for where p + t d meets the depth map (seed 3.3): f(t) = the point's
// view distance less the map's depth where it projects; where the map is empty, t is
// halved. Returns whether |f| fell below epsilon; t is the best estimate either way.
bool secant(int surface, vec3 p, vec3 d, float t_guess, out float t) {
    bool valid;
    float z0 = map_at(surface, p, valid);
    float ta = 0.0, fa = valid ? -p.z - z0 : -t_guess * max(-d.z, 0.25);
    float tb = max(t_guess, u_epsilon);
    t = tb;
    for (int k = 0; k < 10; ++k) {
        vec3 q = p + d * tb;
        float zb = map_at(surface, q, valid);
        if (!valid) {
            tb *= 0.5;
            continue;
        }
        float fb = -q.z - zb;
        t = tb;
        if (abs(fb) < u_epsilon) return true;
        if (fb == fa) break;
        float tn = tb - fb * (tb - ta) / (fb - fa);
        ta = tb;
        fa = fb;
        tb = clamp(tn, 0.0, 50.0);
    }
    return false;
}

float schlick(float cos_i) {
    float r0 = (u_ior - 1.0) / (u_ior + 1.0);
    r0 *= r0;
    float m = 1.0 - clamp(cos_i, 0.0, 1.0);
    return r0 + (1.0 - r0) * m * m * m * m * m;
}

vec3 normal_at(int surface, vec3 p, vec3 fallback) {
    vec3 n = normal_of(surface, clamp_to_rect(ivec2(project_to_pixel(p))));
    return dot(n, n) > 0.25 ? normalize(n) : fallback;
}

// The glass box in the tank's frame: entry/exit distances along the view ray.
bool tank_hit(vec3 ray, out float t_near, out float t_far) {
    vec3 o = (u_view_to_tank * vec4(0.0, 0.0, 0.0, 1.0)).xyz;
    vec3 d = mat3(u_view_to_tank) * ray;
    vec3 inv = 1.0 / d;
    vec3 a = (vec3(0.0) - o) * inv, b = (u_tank_size - o) * inv;
    vec3 lo = min(a, b), hi = max(a, b);
    t_near = max(max(lo.x, lo.y), lo.z);
    t_far = min(min(hi.x, hi.y), hi.z);
    return t_far > max(t_near, 0.0);
}

// 1 on the box's edges (two coordinates near a face), 0 elsewhere; at least 1.5 pixels
// wide at view distance `z`, so a far tank's frame does not break up.
float edge(vec3 p, float z) {
    float pixel_m = 2.0 * z / (u_proj[1][1] * u_viewport.y);
    vec3 near_face = step(min(p, u_tank_size - p), vec3(max(u_frame_width, 1.5 * pixel_m)));
    return step(1.5, near_face.x + near_face.y + near_face.z);
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec3 ray = view_ray(gl_FragCoord.xy);
    vec3 base = texelFetch(u_background, pix, 0).rgb;
    float scene_z = scene_distance(gl_FragCoord.xy);
    float zb = texelFetch(u_body_front, pix, 0).r;
    bool hb = has_depth(zb);
    vec3 colour = base;
    if (hb) {
        vec3 dir = normalize(ray);
        vec3 pos = ray * zb;
        vec3 acc = vec3(0.0), thr = vec3(1.0);
        // Into the liquid.
        vec3 n = normal_at(kBodyFront, pos, -dir);
        if (dot(n, dir) > 0.0) n = -n;
        float f = schlick(dot(-dir, n));
        acc += thr * f * background(pos, reflect(dir, n));
        thr *= 1.0 - f;
        dir = refract(dir, n, 1.0 / u_ior);
        // Through it to its back surface.
        bool valid;
        float back_z = map_at(kBodyBack, pos, valid);
        float t;
        float guess = valid ? max(back_z + pos.z, 0.0) / max(-dir.z, 0.25) : u_epsilon;
        bool found = secant(kBodyBack, pos, dir, guess, t);
        // Not converged (the ray left the map or the search oscillated): its last
        // estimate may be anywhere, so the ray leaves where the back surface lies
        // behind the entry point.
        if (!found) t = guess;
        pos += dir * t;
        thr *= exp(-u_absorption * t);
        // Out of it; total internal reflection sends the ray back in, which this
        // screen-space trace follows no further: it sees the mirrored background.
        vec3 nb = -normal_at(kBodyBack, pos, dir);
        if (dot(nb, dir) > 0.0) nb = -nb;
        vec3 out_dir = refract(dir, nb, u_ior);
        if (out_dir == vec3(0.0)) {
            colour = acc + thr * background(pos, reflect(dir, nb));
        } else {
            f = schlick(dot(out_dir, -nb));
            acc += thr * f * background(pos, reflect(dir, nb));
            thr *= 1.0 - f;
            if (u_probe == 1) {
                o_colour = vec4(out_dir, found ? 1.0 : 0.0);
                return;
            }
            colour = acc + thr * background(pos, out_dir);
        }
    } else if (u_probe == 1) {
        o_colour = vec4(0.0);
        return;
    }

    // The glass: a faint mirror and the steel frame, in front of the liquid; the back
    // edges show where no liquid is in front of them.
    float t_near, t_far;
    if (tank_hit(ray, t_near, t_far) && t_near > 0.0 && t_near < scene_z) {
        vec3 p_near = (u_view_to_tank * vec4(ray * t_near, 1.0)).xyz;
        vec3 d = normalize(ray);
        if (!hb && t_far < scene_z && edge((u_view_to_tank * vec4(ray * t_far, 1.0)).xyz, t_far) > 0.5)
            colour = mix(colour, vec3(0.05, 0.055, 0.06), 0.8);
        float cos_i = abs(d.z);  // about the view axis: the glass is thin and the mirror faint
        float f = 0.04 + 0.2 * pow(1.0 - cos_i, 5.0);
        colour = colour * vec3(0.93, 0.97, 0.96) + f * sky(reflect(d, vec3(0.0, 0.0, 1.0)));
        if (edge(p_near, t_near) > 0.5) colour = vec3(0.09, 0.1, 0.11) + 0.15 * sky(vec3(0.0, 1.0, 0.0));
    }
    o_colour = vec4(colour, 1.0);
}
